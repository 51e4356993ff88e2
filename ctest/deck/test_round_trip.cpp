// SPDX-License-Identifier: GPL-3.0-or-later
// Round trip: read -> write -> read gives the same cards (ids, titles, every value and
// its blank flag, texts), for the small decks and for one card of every keyword of the
// table built with every field set (CardBuilder).
#include "deck_test_support.hpp"
#include "hbm/deck/io.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <sstream>

using namespace hbm::deck;
using hbm::deck::testing::kDir;
using hbm::deck::testing::messages;

namespace {

bool text_fits(double x, int width) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return r.ptr - buf <= width;
}

void expect_same_cards(const Deck& a, const Deck& b, bool compare_blank) {
  ASSERT_EQ(a.cards.size(), b.cards.size());
  for (std::size_t i = 0; i < a.cards.size(); ++i) {
    const Card& x = a.cards[i];
    const Card& y = b.cards[i];
    SCOPED_TRACE(std::string(x.keyword()) + "/" + std::to_string(x.id));
    ASSERT_EQ(x.spec, y.spec);
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.title, y.title);
    ASSERT_EQ(x.n_rows(), y.n_rows());
    ASSERT_EQ(x.n_name_rows(), y.n_name_rows());
    ASSERT_EQ(x.lines.size(), y.lines.size());
    for (std::size_t l = 0; l < x.lines.size(); ++l) {
      ASSERT_EQ(x.lines[l].layout, y.lines[l].layout);
      for (std::size_t f = 0; f < x.lines[l].layout->fields.size(); ++f) {
        const FieldSpec& fs = x.lines[l].layout->fields[f];
        const Value& u = x.values[x.lines[l].first + f];
        const Value& v = y.values[y.lines[l].first + f];
        SCOPED_TRACE(std::string(fs.name));
        if (compare_blank) {
          EXPECT_EQ(u.blank, v.blank);
        }
        if (fs.type == FieldType::Real) {
          // Exact when the shortest round-trip text fits the field (20 columns hold up to
          // 17 significant digits for exponents of 2 digits); otherwise the field keeps
          // at least 13 significant digits: relative difference <= 1e-13.
          if (text_fits(u.real, fs.width)) {
            EXPECT_EQ(u.real, v.real);
          } else {
            EXPECT_NEAR(u.real, v.real, 1e-13 * std::fabs(u.real));
          }
        } else if (fs.type == FieldType::Int) {
          EXPECT_EQ(u.integer, v.integer);
        } else {
          EXPECT_EQ(u.blank ? std::string_view{} : a.text(u), v.blank ? std::string_view{} : b.text(v));
        }
      }
    }
  }
}

// A value inside the field's valid range, different per field index.
double sample(const FieldSpec& f, int k) {
  const bool lo = std::isfinite(f.min), hi = std::isfinite(f.max);
  if (f.type == FieldType::Int) {
    if (lo && hi) return std::floor((f.min + f.max) / 2);
    if (lo) return f.min + 1 + k;
    return 3 + k;
  }
  if (lo && hi) return f.min + (f.max - f.min) * 0.3183098861837907;
  if (lo) return f.min + 1.2345678901234567 * (k + 1);
  return -3.1415926535897931e-5 * (k + 1);
}

std::string sample_text(const FieldSpec& f, int k) {
  if (f.name == "Tra") return "101";
  if (f.name == "rot") return "010";
  if (f.name == "Dir") return "Y";
  if (f.name == "mass") return "g";
  if (f.name == "length") return "m";
  if (f.name == "time") return "s";
  std::string s = "T" + std::to_string(k) + "x";
  return s.substr(0, static_cast<std::size_t>(f.width));
}

void fill(CardBuilder& b, const LineSpec& ls, std::size_t line, bool row, bool name_row) {
  int k = 0;
  for (const FieldSpec& f : ls.fields) {
    ++k;
    if (f.type == FieldType::Text) {
      if (name_row) b.name_row_set_text(line, f.name, sample_text(f, k));
      else if (row) b.row_set_text(line, f.name, sample_text(f, k));
      else b.set_text(line, f.name, sample_text(f, k));
    } else if (f.type == FieldType::Int) {
      const auto v = static_cast<std::int64_t>(sample(f, k));
      if (row) b.row_set_int(line, f.name, v);
      else b.set_int(line, f.name, v);
    } else {
      if (row) b.row_set(line, f.name, sample(f, k));
      else b.set(line, f.name, sample(f, k));
    }
  }
}

}  // namespace

namespace {

// Reads ctest/deck/decks/<file>, writes it, reads the text back: the same cards.
void expect_file_round_trip(const std::string& file, Section section) {
  const ReadResult a = read_deck(kDir / file, section);
  ASSERT_TRUE(a.ok()) << messages(a);
  std::ostringstream os;
  write_deck(os, a.deck);
  const ReadResult b = read_deck_text(os.str(), "written_" + file, section);
  ASSERT_TRUE(b.ok()) << messages(b) << os.str();
  expect_same_cards(a.deck, b.deck, true);
}

}  // namespace

TEST(DeckRoundTrip, SmallStarterDeck) { expect_file_round_trip("small_0000.rad", Section::Starter); }

TEST(DeckRoundTrip, SmallEngineDeck) { expect_file_round_trip("small_0001.rad", Section::Engine); }

// Every keyword of the table: a card with every field set, written and read back.
TEST(DeckRoundTrip, EveryKeywordEveryField) {
  for (Section sec : {Section::Starter, Section::Engine}) {
    Deck d;
    d.section = sec;
    for (const KeywordSpec& k : keyword_table()) {
      if (k.section != sec || k.keyword == "/END") continue;  // /END goes last
      std::int64_t id = 0;
      if (k.id == IdKind::Object || k.id == IdKind::Part) id = 17;
      if (k.id == IdKind::Optional) id = 3;
      std::string title = k.has_title ? "title of " + std::string(k.keyword) : std::string();
      if (k.keyword == "/RUN") title = "roundtrip";
      CardBuilder b(d, k.keyword, id, title);
      for (std::size_t l = 0; l < k.lines.size(); ++l) fill(b, k.lines[l], l, false, false);
      if (k.name_rows) {
        b.add_name_row();
        fill(b, *k.name_rows, 0, false, true);
      }
      if (k.rows) {
        for (int r = 0; r < 3; ++r) {
          const std::size_t row = b.add_row();
          fill(b, *k.rows, row, true, false);
          b.row_set_int(row, k.rows->fields[0].name, 1000 + r);  // distinct first field
        }
      }
      b.commit();
    }
    if (sec == Section::Starter) CardBuilder(d, "/END").commit();
    std::ostringstream os;
    write_deck(os, d);
    const ReadResult back = read_deck_text(os.str(), "every_keyword.rad", sec);
    // The deck is not a consistent model (references are undefined), but nothing may be
    // lost: every card reads back with the same values.
    for (const Diagnostic& diag : back.diagnostics) {
      const std::string& m = diag.message;
      EXPECT_EQ(m.find("expected"), std::string::npos) << format(diag, back.deck);
      EXPECT_EQ(m.find("column"), std::string::npos) << format(diag, back.deck);
      EXPECT_EQ(m.find("nearest supported keyword"), std::string::npos) << format(diag, back.deck);
      EXPECT_EQ(m.find("missing data line"), std::string::npos) << format(diag, back.deck);
    }
    expect_same_cards(d, back.deck, true);
    // Writing what was read gives the same text again (the canonical form is a fixed point).
    std::ostringstream again;
    write_deck(again, back.deck);
    EXPECT_EQ(os.str(), again.str());
  }
}

TEST(DeckRoundTrip, WriteDeckFileIsAtomic) {
  const ReadResult a = read_deck(kDir / "small_0000.rad", Section::Starter);
  ASSERT_TRUE(a.ok());
  const auto dir = std::filesystem::temp_directory_path() / "hbm_deck_write_test";
  std::filesystem::create_directories(dir);
  const auto out = dir / "copy_0000.rad";
  std::filesystem::remove(out);
  write_deck_file(out, a.deck);
  ASSERT_TRUE(std::filesystem::exists(out));
  const ReadResult b = read_deck(out, Section::Starter);
  ASSERT_TRUE(b.ok()) << messages(b);
  expect_same_cards(a.deck, b.deck, true);
  // A card that cannot be written (non-finite value) leaves no file behind.
  Deck bad = a.deck;
  bad.cards[0].values.back().real = 1.0;
  for (Card& c : bad.cards)
    if (c.keyword() == "/MAT/LAW1") c.values[0].real = std::nan("");
  const auto out2 = dir / "bad_0000.rad";
  std::filesystem::remove(out2);
  EXPECT_THROW(write_deck_file(out2, bad), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(out2));
  std::size_t leftovers = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().find("bad_0000.rad") != std::string::npos) ++leftovers;
  EXPECT_EQ(leftovers, 0u);
}
