// SPDX-License-Identifier: GPL-3.0-or-later
// Mutation robustness: valid decks are damaged by thousands of seeded random mutations
// (deleted, duplicated, truncated and swapped lines; garbled numbers; random bytes; huge
// values; NaN/Inf text; missing /END; shifted columns; stray keywords). Every run must
// end either with at least one error pointing at a real line of the deck, or, when the
// mutation happened to leave a valid deck, with a clean read that also round-trips
// through the writer. No exception, no crash, no hang (each run is timed), and, in the
// sanitizer build, no ASan/UBSan report (the test runs under -fno-sanitize-recover).
#include "deck_test_support.hpp"
#include "hbm/deck/check_command.hpp"
#include "hbm/deck/io.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

using namespace hbm::deck;
using hbm::deck::testing::kDir;
using hbm::deck::testing::slurp;

namespace {

std::vector<std::string> split_lines(const std::string& t) {
  std::vector<std::string> out;
  std::size_t pos = 0;
  while (pos <= t.size()) {
    const std::size_t nl = t.find('\n', pos);
    if (nl == std::string::npos) {
      if (pos < t.size()) out.push_back(t.substr(pos));
      break;
    }
    out.push_back(t.substr(pos, nl - pos));
    pos = nl + 1;
  }
  return out;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string t;
  for (const auto& l : lines) {
    t += l;
    t += '\n';
  }
  return t;
}

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : rng_(seed) {}

  std::size_t pick(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng_() % n); }

  // One mutation; returns its name (for failure messages).
  std::string mutate(std::vector<std::string>& lines) {
    if (lines.empty()) {
      lines.push_back("/END");
      return "insert /END";
    }
    const std::size_t i = pick(lines.size());
    std::string& l = lines[i];
    switch (pick(14)) {
      case 0:
        lines.erase(lines.begin() + static_cast<long>(i));
        return "delete line " + std::to_string(i + 1);
      case 1:
        lines.insert(lines.begin() + static_cast<long>(i), l);
        return "duplicate line " + std::to_string(i + 1);
      case 2:
        l.resize(pick(l.size() + 1));
        return "truncate line " + std::to_string(i + 1);
      case 3: {
        const std::size_t j = pick(lines.size());
        std::swap(lines[i], lines[j]);
        return "swap lines " + std::to_string(i + 1) + " " + std::to_string(j + 1);
      }
      case 4: {  // garble a digit
        for (int tries = 0; tries < 20; ++tries) {
          const std::size_t k = pick(l.size());
          if (k < l.size() && l[k] >= '0' && l[k] <= '9') {
            static constexpr char repl[] = "xO.-+eEdD ,/#9";
            l[k] = repl[pick(sizeof repl - 1)];
            return "garble digit on line " + std::to_string(i + 1);
          }
        }
        return "garble (no digit)";
      }
      case 5: {  // random bytes
        const std::size_t n = 1 + pick(4);
        for (std::size_t k = 0; k < n; ++k) {
          const char b = static_cast<char>(rng_() & 0xff);
          l.insert(l.begin() + static_cast<long>(pick(l.size() + 1)), b);
        }
        return "random bytes on line " + std::to_string(i + 1);
      }
      case 6:
      case 7: {  // replace a numeric token with a huge / special value
        static constexpr const char* vals[] = {"1e308",  "-1E+999", "9999999999", "99999999999999999999",
                                               "NaN",    "Inf",     "-inf",       "nan(0x1)",
                                               "1.0e-400", "0x1p3", "1e",         "-0"};
        const std::string v = vals[pick(sizeof vals / sizeof vals[0])];
        const std::size_t k = l.find_first_of("0123456789");
        if (k == std::string::npos) return "no number on line";
        std::size_t e = k;
        while (e < l.size() && l[e] != ' ') ++e;
        std::size_t b = k;
        while (b > 0 && l[b - 1] != ' ') --b;
        l.replace(b, e - b, v);
        return "special value " + v + " on line " + std::to_string(i + 1);
      }
      case 8: {  // remove /END
        for (std::size_t k = 0; k < lines.size(); ++k)
          if (lines[k].rfind("/END", 0) == 0) {
            lines.erase(lines.begin() + static_cast<long>(k));
            return "remove /END";
          }
        return "no /END";
      }
      case 9:
        l.insert(0, " ");
        return "shift line " + std::to_string(i + 1);
      case 10: {
        static constexpr const char* kws[] = {"/MAT/LAW42/3", "/NODE", "/BRICK/999", "/PART", "/BEGIN",
                                              "/END",         "/",     "//",         "/RUN/x/1", "/FUNCT/7"};
        lines.insert(lines.begin() + static_cast<long>(i), kws[pick(sizeof kws / sizeof kws[0])]);
        return "insert keyword at line " + std::to_string(i + 1);
      }
      case 11:
        l.append(std::string(pick(120), ' ') + "7");
        return "extend line " + std::to_string(i + 1);
      case 12:
        lines.resize(pick(lines.size() + 1));
        return "truncate file";
      default: {
        // Flip a sign of a number.
        const std::size_t k = l.find_first_of("0123456789");
        if (k != std::string::npos && k > 0 && l[k - 1] == ' ') l[k - 1] = '-';
        return "negate on line " + std::to_string(i + 1);
      }
    }
  }

 private:
  std::mt19937_64 rng_;
};

struct Seed {
  std::string text;
  std::filesystem::path name;
  Section section;
};

std::vector<Seed> seeds() {
  return {{slurp(kDir / "small_0000.rad"), kDir / "small_0000.rad", Section::Starter},
          {slurp(kDir / "small_0001.rad"), kDir / "small_0001.rad", Section::Engine},
          {slurp(HBM_DECK_PLANTED), std::filesystem::path(HBM_DECK_PLANTED), Section::Starter}};
}

// Runs one mutated deck through the reader and checks the contract.
void check_one(const std::string& text, const Seed& seed, const std::string& what) {
  const auto t0 = std::chrono::steady_clock::now();
  ReadResult r;
  ASSERT_NO_THROW(r = read_deck_text(text, seed.name.string(), seed.section)) << what;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(seconds, 2.0) << what;  // a hang shows up here (and in the CTest timeout)
  const std::size_t n_lines = split_lines(text).size();
  if (!r.ok()) {
    bool located = false;
    for (const Diagnostic& d : r.diagnostics) {
      EXPECT_FALSE(d.message.empty()) << what;
      if (d.severity != Severity::Error) continue;
      if (d.loc.file == 0) {
        EXPECT_GE(d.loc.line, 1u) << what << ": " << d.message;
        EXPECT_LE(d.loc.line, std::max<std::size_t>(n_lines, 1)) << what << ": " << d.message;
      }
      located = located || d.loc.line >= 1;
      EXPECT_FALSE(format(d, r.deck).empty());
    }
    EXPECT_TRUE(located) << what;
    return;
  }
  // Still a valid deck: it must also survive the writer unchanged.
  std::ostringstream os;
  ASSERT_NO_THROW(write_deck(os, r.deck)) << what;
  const ReadResult again = read_deck_text(os.str(), seed.name.string(), seed.section);
  EXPECT_TRUE(again.ok()) << what << "\n" << os.str();
  EXPECT_EQ(again.deck.cards.size(), r.deck.cards.size()) << what;
}

}  // namespace

TEST(DeckMutations, SeedDecksAreValid) {
  const auto s = seeds();
  EXPECT_TRUE(read_deck_text(s[0].text, s[0].name.string(), s[0].section).ok());
  EXPECT_TRUE(read_deck_text(s[1].text, s[1].name.string(), s[1].section).ok());
  EXPECT_FALSE(read_deck_text(s[2].text, s[2].name.string(), s[2].section).ok());  // planted errors stay errors
}

TEST(DeckMutations, ThousandsOfRandomMutationsNeverCrashOrPassSilently) {
  const auto all = seeds();
  std::size_t invalid = 0, still_valid = 0;
  constexpr int kRunsPerSeed = 2000;
  for (std::size_t s = 0; s < all.size(); ++s) {
    const std::vector<std::string> base = split_lines(all[s].text);
    Mutator m(0x5eed0000 + s);
    for (int run = 0; run < kRunsPerSeed; ++run) {
      std::vector<std::string> lines = base;
      std::string what = "seed ";
      what.append(std::to_string(s)).append(" run ").append(std::to_string(run)).append(":");
      const std::size_t n = 1 + m.pick(3);
      for (std::size_t k = 0; k < n; ++k) what.append(" ").append(m.mutate(lines));
      const std::string text = join_lines(lines);
      check_one(text, all[s], what);
      if (::testing::Test::HasFailure()) return;  // one clear report is enough
      const bool valid = read_deck_text(text, all[s].name.string(), all[s].section).ok();
      (valid ? still_valid : invalid)++;
      if (valid && std::getenv("HBM_MUTATION_LOG")) std::cout << "valid after: " << what << "\n";
    }
  }
  // Most mutations break the deck; some leave it valid (e.g. a shifted blank line).
  std::cout << "mutated decks: " << invalid << " rejected with errors, " << still_valid << " still valid\n";
  EXPECT_GT(invalid, 4000u);
  EXPECT_EQ(invalid + still_valid, 3u * kRunsPerSeed);
}

TEST(DeckMutations, CheckCommandExitCodes) {
  // A few dozen mutated starter decks written to files and run through the --check
  // command: exit 1 exactly when the reader reports an error, never another file.
  const Seed seed = seeds()[0];
  const auto dir = std::filesystem::temp_directory_path() / "hbm_deck_mutation_check";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(kDir / "small_nodes.inc", dir / "small_nodes.inc");
  const std::vector<std::string> base = split_lines(seed.text);
  Mutator m(42);
  int rejected = 0;
  for (int run = 0; run < 40; ++run) {
    std::vector<std::string> lines = base;
    const std::string what = m.mutate(lines);
    const auto path = dir / "mut_0000.rad";
    std::ofstream(path, std::ios::binary) << join_lines(lines);
    std::ostringstream out, err;
    const int rc = run_check(path, out, err);
    const bool ok = read_deck(path, Section::Starter).ok();
    EXPECT_EQ(rc, ok ? 0 : 1) << what << "\n" << err.str();
    rejected += rc == 1;
    std::size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 2u) << what;  // the deck and its include: nothing written
  }
  EXPECT_GT(rejected, 20);
  std::filesystem::remove_all(dir);
}
