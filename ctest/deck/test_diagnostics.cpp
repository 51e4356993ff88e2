// SPDX-License-Identifier: GPL-3.0-or-later
// Diagnostics: each planted error is reported once, at its file:line:col, with the
// message format `file:line:col: error: /MAT/LAW1/17 field E = -1: must be > 0`; the
// --check command returns 1 for deck errors, 2 for bad command-line use, creates no file.
#include "deck_test_support.hpp"
#include "hbm/deck/check_command.hpp"
#include "hbm/deck/io.hpp"
#include "hbm/deck/summary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

using namespace hbm::deck;
using hbm::deck::testing::kDir;
using hbm::deck::testing::messages;

namespace {

const std::filesystem::path kPlanted = HBM_DECK_PLANTED;

struct Expect {
  std::uint32_t line;
  int col;
  std::string text;  // exact message
};

// A minimal valid starter deck around `body` (cards between /BEGIN and /END).
std::string starter(const std::string& body) {
  return "/BEGIN\nt\n      2024         0\n                  kg                  mm                  ms\n"
         "                  kg                  mm                  ms\n" +
         body + "/END\n";
}

std::string node(int id, double x, double y, double z) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%10d%20g%20g%20g\n", id, x, y, z);
  return buf;
}

std::string cube_nodes() {
  return "/NODE\n" + node(1, 0, 0, 0) + node(2, 1, 0, 0) + node(3, 1, 1, 0) + node(4, 0, 1, 0) + node(5, 0, 0, 1) +
         node(6, 1, 0, 1) + node(7, 1, 1, 1) + node(8, 0, 1, 1);
}

const std::string kSolidPart =
    "/PART/1\np\n         1         1\n/PROP/TYPE14/1\ns\n\n/MAT/LAW1/1\nm\n                  1.\n"
    "                  1.                 0.3\n";

std::vector<std::string> errors_of(const ReadResult& r) {
  std::vector<std::string> out;
  for (const Diagnostic& d : r.diagnostics)
    if (d.severity == Severity::Error) out.push_back(format(d, r.deck));
  return out;
}

}  // namespace

TEST(DeckDiagnostics, PlantedErrorsEachReportedAtTheirLine) {
  const ReadResult r = read_deck(kPlanted, Section::Starter);
  const std::vector<Expect> expected = {
      {19, 1, "/NODE field id = 8: duplicate node id (first defined at " + kPlanted.string() + ":18)"},
      {20, 28, "/NODE field X = '1O.': number expected, found text"},
      {23, 1,
       "/BRICK/1 element 102: inverted or degenerate brick: Jacobian at the centre = -125 (needs "
       "(n2-n1)x(n4-n1).(n5-n1) > 0: n1-n4 counter-clockwise seen from the n5-n8 side)"},
      {24, 81, "/BRICK/1 field n8 = 99: node 99 is not defined"},
      {34, 16, "/MAT/LAW1/1 field E = -210: must be > 0"},
      {34, 38, "/MAT/LAW1/1 field nu = 0.6: must be in (-1, 0.5)"},
      {35, 1, "keyword /MAT/LAW3 is not supported; nearest supported keyword: /MAT/LAW1"},
      {42, 1, "/FUNCT/5 field X = 1: abscissa must increase (previous point X = 2)"},
      {45, 104, "content past column 100 (the starter reads 100 columns)"},
      {48, 1, "missing /END: the starter deck must end with /END"},
      {48, 21, "/BCS/1 field grnod_id = 7: node group 7 is not defined"},
  };
  ASSERT_EQ(r.diagnostics.size(), expected.size()) << messages(r);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const Diagnostic& d = r.diagnostics[i];
    EXPECT_EQ(d.severity, Severity::Error);
    EXPECT_EQ(d.loc.line, expected[i].line) << d.message;
    EXPECT_EQ(d.column, expected[i].col) << d.message;
    EXPECT_EQ(d.message, expected[i].text);
  }
  EXPECT_EQ(format(r.diagnostics[4], r.deck),
            kPlanted.string() + ":34:16: error: /MAT/LAW1/1 field E = -210: must be > 0");
}

TEST(DeckDiagnostics, CheckCommandExitCodesAndNoFileWritten) {
  const auto dir = kPlanted.parent_path();
  std::set<std::string> before;
  for (const auto& e : std::filesystem::directory_iterator(dir)) before.insert(e.path().string());
  std::ostringstream out, err;
  EXPECT_EQ(run_check(kPlanted, out, err), 1);
  EXPECT_NE(err.str().find(kPlanted.string() + ":34:16: error: /MAT/LAW1/1 field E = -210: must be > 0"),
            std::string::npos)
      << err.str();
  EXPECT_NE(err.str().find("11 errors; deck rejected"), std::string::npos) << err.str();
  EXPECT_EQ(out.str(), "");
  std::set<std::string> after;
  for (const auto& e : std::filesystem::directory_iterator(dir)) after.insert(e.path().string());
  EXPECT_EQ(before, after);

  std::ostringstream o2, e2;
  EXPECT_EQ(run_check(kDir / "no_such_0000.rad", o2, e2), 2);
  EXPECT_EQ(run_check(kDir / "small_nodes.inc", o2, e2), 2);
  EXPECT_EQ(run_check(kDir / "small_0000.rad", o2, e2), 0) << e2.str();
  EXPECT_NE(o2.str().find("Engine deck"), std::string::npos);
}

TEST(DeckDiagnostics, ModelSummaryOfTheSmallDeck) {
  // Analytic values: 10 mm steel cube rho 7.8e-6 kg/mm^3 -> 7.8e-3 kg; dt = L/c with
  // L = V/Amax = 10 mm, c = sqrt(E(1-nu)/((1+nu)(1-2nu)rho)) = 6020.18 mm/ms.
  const ReadResult r = read_deck(kDir / "small_0000.rad", Section::Starter);
  ASSERT_TRUE(r.ok()) << messages(r);
  const ModelSummary s = summarize(r.deck);
  EXPECT_EQ(s.nodes, 11u);
  EXPECT_EQ(s.elements.at("/BRICK"), 1u);
  EXPECT_EQ(s.elements.at("/SH3N"), 1u);
  ASSERT_EQ(s.parts.size(), 4u);
  const double c_steel = std::sqrt(210.0 * 0.7 / (1.3 * 0.4 * 7.8e-6));
  EXPECT_NEAR(s.parts[0].mass, 7.8e-3, 1e-15);
  EXPECT_NEAR(s.parts[0].dt_min, 10.0 / c_steel, 1e-12);
  EXPECT_EQ(s.parts[0].dt_element, 101);
  // Tetra (0,0,10) (10,0,10) (0,10,10) (0,0,15): V = 250/3 mm^3, rho 1.04e-6;
  // L = 3V / largest face (50 mm^2, the 10x10 right triangle), c = sqrt((K + 4G0/3)/rho).
  EXPECT_NEAR(s.parts[1].mass, 1.04e-6 * 250.0 / 3.0, 1e-15);
  const double c_brain = std::sqrt((2.19 + 4.0 / 3.0 * 5.28e-4) / 1.04e-6);
  // Largest face: (10,0,10) (0,10,10) (0,0,15): area 0.5 |(-10,10,0) x (-10,0,5)| = 0.5 sqrt(15000).
  EXPECT_NEAR(s.parts[1].dt_min, 3 * (250.0 / 3.0) / (0.5 * std::sqrt(15000.0)) / c_brain, 1e-12);
  // Shells: quad 10x10 thick 0.5 + triangle area 50 with property thickness 1.2.
  EXPECT_NEAR(s.parts[2].mass, 7.8e-6 * (100 * 0.5 + 50 * 1.2), 1e-15);
  const double c_plate = std::sqrt(210.0 / ((1 - 0.09) * 7.8e-6));
  EXPECT_NEAR(s.parts[2].dt_min, (100.0 / std::sqrt(200.0)) / c_plate, 1e-12);
  // Spring: m = 1e-3 kg, k = 10 kN/mm -> sqrt(2m/k).
  EXPECT_NEAR(s.parts[3].dt_min, std::sqrt(2e-3 / 10.0), 1e-15);
  EXPECT_NEAR(s.rbody_mass, 0.5, 0);
  EXPECT_NEAR(s.total_mass(), 7.8e-3 + 1.04e-6 * 250.0 / 3.0 + 7.8e-6 * 110 + 1e-3 + 0.5, 1e-12);
  EXPECT_EQ(s.dt_part, 3);
}

// OpenRadioss reads a typed 0 in fields such as /PROP/TYPE14 qa, qb, h or /INTER/TYPE7
// Stfac, VISs as the field's default (starter: IF(QA==ZERO) QA=ONEP1, ...), as it reads a
// blank; a field without that rule (/MAT/LAW1 rho here: 0 is an error) keeps its 0.
TEST(DeckDiagnostics, TypedZeroReadsAsTheDefaultWhereOpenRadiossSaysSo) {
  const auto dir = std::filesystem::temp_directory_path() / "hbm_deck_zero_default_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "z_0000.rad") << starter(
      "/PROP/TYPE14/1\nzeros\n         0\n  0.000000000000E+00                  0.                   0\n"
      "/PROP/TYPE14/2\nvalues\n         0\n                 1.5                0.07                0.12\n"
      "/MAT/LAW2/1\nm\n              7.8E-6\n                210.                 0.3\n"
      "                 0.3                 0.5                   0\n"
      "/PROP/TYPE4/3\nspring\n               0.001\n                 10.                  0.                  0.\n");
  const ReadResult r = read_deck(dir / "z_0000.rad", Section::Starter);
  ASSERT_TRUE(errors_of(r).empty()) << messages(r);
  const Card& zeros = *r.deck.cards_of("/PROP/TYPE14")[0];
  EXPECT_DOUBLE_EQ(zeros.real(1, "qa"), 1.1);
  EXPECT_DOUBLE_EQ(zeros.real(1, "qb"), 0.05);
  EXPECT_DOUBLE_EQ(zeros.real(1, "h"), 0.1);
  const Card& values = *r.deck.cards_of("/PROP/TYPE14")[1];
  EXPECT_DOUBLE_EQ(values.real(1, "qa"), 1.5);
  EXPECT_DOUBLE_EQ(values.real(1, "qb"), 0.07);
  EXPECT_DOUBLE_EQ(values.real(1, "h"), 0.12);
  const Card& law2 = *r.deck.cards_of("/MAT/LAW2")[0];
  EXPECT_DOUBLE_EQ(law2.real(2, "n"), 1.0);  // hm_read_mat02.F: IF (CN == ZERO) CN = ONE
  const Card& spring = *r.deck.cards_of("/PROP/TYPE4")[0];
  EXPECT_DOUBLE_EQ(spring.real(1, "C"), 0.0);  // no rule: 0 stays 0
  EXPECT_DOUBLE_EQ(spring.real(1, "A"), 1.0);  // hm_read_prop04.F: A 0 -> 1
  // Poisson's ratio 0.5 reads as 0.499 with a warning (hm_read_mat01.F: IF(ANU==HALF)ANU=ZEP499).
  std::ofstream(dir / "z_0000.rad") << starter("/MAT/LAW1/1\nm\n                  1.\n                  1.                 0.5\n");
  const ReadResult half = read_deck(dir / "z_0000.rad", Section::Starter);
  ASSERT_TRUE(errors_of(half).empty()) << messages(half);
  EXPECT_DOUBLE_EQ(half.deck.cards_of("/MAT/LAW1")[0]->real(1, "nu"), 0.499);
  EXPECT_NE(messages(half).find("/MAT/LAW1/1 field nu = 0.5: read as 0.499 (as OpenRadioss reads it)"),
            std::string::npos) << messages(half);
  // Our own writers may not put a 0 there: it would read as the default.
  Deck built;
  EXPECT_THROW(CardBuilder(built, "/PROP/TYPE14", 1, "p").set(1, "qa", 0.0), std::invalid_argument);
  // A field without the rule: rho typed 0 stays 0 and is an error.
  std::ofstream(dir / "z_0000.rad") << starter("/MAT/LAW1/1\nm\n                  0.\n                  1.                 0.3\n");
  const auto errs = errors_of(read_deck(dir / "z_0000.rad", Section::Starter));
  ASSERT_EQ(errs.size(), 1u);
  EXPECT_NE(errs[0].find("field rho = 0: must be > 0"), std::string::npos) << errs[0];
}

// /MAT/LAW42 (Ogden) as the Radioss reference guide lays it out: nu and sigma_cut read 0 as
// their defaults (0.495, 1e30: hm_read_mat42.F), the pairs are read by name; Prony terms
// (M > 0) are refused by the field's range, and a solid part may not use the law here.
TEST(DeckDiagnostics, OgdenLaw42CardDefaultsAndLimits) {
  const auto dir = std::filesystem::temp_directory_path() / "hbm_deck_law42_test";
  std::filesystem::create_directories(dir);
  auto law42 = [](const std::string& m_field) {
    return "/MAT/LAW42/1\nskin\n                1e-6\n"
           "                   0                   0                   0                   0" + m_field + "\n"
           "                3e-4                1e-6\n"
           "                  2.                 24.\n";
  };
  std::ofstream(dir / "o_0000.rad") << starter(law42(""));
  const ReadResult r = read_deck(dir / "o_0000.rad", Section::Starter);
  ASSERT_TRUE(errors_of(r).empty()) << messages(r);
  const Card& m = *r.deck.cards_of("/MAT/LAW42")[0];
  EXPECT_DOUBLE_EQ(m.real(1, "nu"), 0.495);
  EXPECT_DOUBLE_EQ(m.real(1, "sigma_cut"), 1e30);
  EXPECT_DOUBLE_EQ(m.real(2, "mu1"), 3e-4);
  EXPECT_DOUBLE_EQ(m.real(2, "mu2"), 1e-6);
  EXPECT_DOUBLE_EQ(m.real(2, "mu3"), 0.0);
  EXPECT_DOUBLE_EQ(m.real(3, "alpha2"), 24.0);
  // M = 2 Prony terms: refused, the field named.
  std::ofstream(dir / "o_0000.rad") << starter(law42("         2"));
  const auto prony = errors_of(read_deck(dir / "o_0000.rad", Section::Starter));
  ASSERT_EQ(prony.size(), 1u);
  EXPECT_NE(prony[0].find("/MAT/LAW42/1"), std::string::npos) << prony[0];
  EXPECT_NE(prony[0].find("field M = 2"), std::string::npos) << prony[0];
  // A brick part on it.
  std::string solid = kSolidPart;
  solid.replace(solid.find("/MAT/LAW1/1"), std::string::npos, law42(""));
  std::ofstream(dir / "o_0000.rad") << starter(cube_nodes() + "/BRICK/1\n         1         1         2         3         4"
                                               "         5         6         7         8\n" + solid);
  const auto on_solid = errors_of(read_deck(dir / "o_0000.rad", Section::Starter));
  ASSERT_EQ(on_solid.size(), 1u) << messages(read_deck(dir / "o_0000.rad", Section::Starter));
  EXPECT_NE(on_solid[0].find("applies to shell elements only"), std::string::npos) << on_solid[0];
}

// OpenRadioss accepts a /PROP/TYPE1 Thick of 0 when the part (or the element) gives the
// thickness; the deck is in error only for a shell whose element, part and property
// thicknesses are all 0, and the message names that element.
TEST(DeckDiagnostics, ShellThicknessFromPartOrElementWhenThePropertyHasNone) {
  const auto dir = std::filesystem::temp_directory_path() / "hbm_deck_shell_thickness_test";
  std::filesystem::create_directories(dir);
  auto deck = [](const std::string& part_thick, const std::string& element_thick) {
    return starter(
        "/NODE\n         1                  0.                  0.                  0.\n"
        "         2                  1.                  0.                  0.\n"
        "         3                  1.                  1.                  0.\n"
        "         4                  0.                  1.                  0.\n"
        "/PROP/TYPE1/1\nplate\n         0\n\n         3          " "                  0.\n"
        "/MAT/LAW1/1\nm\n              7.8E-6\n                210.                 0.3\n"
        "/PART/1\nplate\n         1         1         0" + part_thick + "\n"
        "/SHELL/1\n         7         1         2         3         4" + std::string(30, ' ') + element_thick + "\n");
  };
  std::ofstream(dir / "t_0000.rad") << deck("                 1.5", "");
  const ReadResult by_part = read_deck(dir / "t_0000.rad", Section::Starter);
  EXPECT_TRUE(errors_of(by_part).empty()) << messages(by_part);
  std::ofstream(dir / "t_0000.rad") << deck("", "                 1.5");
  const ReadResult by_element = read_deck(dir / "t_0000.rad", Section::Starter);
  EXPECT_TRUE(errors_of(by_element).empty()) << messages(by_element);
  std::ofstream(dir / "t_0000.rad") << deck("", "");
  const auto errs = errors_of(read_deck(dir / "t_0000.rad", Section::Starter));
  ASSERT_EQ(errs.size(), 1u);
  EXPECT_NE(errs[0].find("/SHELL/1 element 7: shell thickness 0"), std::string::npos) << errs[0];
  EXPECT_NE(errs[0].find("t_0000.rad:"), std::string::npos) << errs[0];
}

TEST(DeckDiagnostics, IncludeChainAndCycle) {
  const auto dir = std::filesystem::temp_directory_path() / "hbm_deck_include_test";
  std::filesystem::create_directories(dir / "sub");
  {
    std::ofstream(dir / "main_0000.rad") << starter("#include sub/a.inc\n");
    std::ofstream(dir / "sub" / "a.inc") << "# a\n#include b.inc\n";
    std::ofstream(dir / "sub" / "b.inc") << "/MAT/LAW1/3\nm\n                  1.\n                 -5.                 0.3\n";
  }
  const ReadResult r = read_deck(dir / "main_0000.rad", Section::Starter);
  const auto errs = errors_of(r);
  ASSERT_EQ(errs.size(), 1u) << messages(r);
  EXPECT_EQ(errs[0], (dir / "sub" / "b.inc").string() + ":4:18: error: /MAT/LAW1/3 field E = -5: must be > 0\n" +
                         "  included from " + (dir / "sub" / "a.inc").string() + ":2\n" + "  included from " +
                         (dir / "main_0000.rad").string() + ":6");
  {
    std::ofstream(dir / "sub" / "b.inc") << "#include a.inc\n";
  }
  const ReadResult c = read_deck(dir / "main_0000.rad", Section::Starter);
  const auto cerrs = errors_of(c);
  ASSERT_EQ(cerrs.size(), 1u) << messages(c);
  EXPECT_NE(cerrs[0].find("b.inc:1:10: error: #include cycle: "), std::string::npos) << cerrs[0];
  {
    std::ofstream(dir / "sub" / "a.inc") << "#include missing.inc\n";
  }
  const ReadResult m = read_deck(dir / "main_0000.rad", Section::Starter);
  ASSERT_EQ(errors_of(m).size(), 1u) << messages(m);
  EXPECT_NE(errors_of(m)[0].find("a.inc:1:10: error: cannot read included file"), std::string::npos);
}

TEST(DeckDiagnostics, NumberForms) {
  // Accepted forms and their values, then rejected ones with their messages.
  struct Ok { const char* text; double value; };
  for (const Ok& ok : {Ok{"1.5E-3", 1.5e-3}, Ok{"1.5D-3", 1.5e-3}, Ok{"1.5d+3", 1.5e3}, Ok{"1.5-3", 1.5e-3},
                       Ok{"-2.5+2", -250.0}, Ok{"+7", 7.0}, Ok{".5", 0.5}, Ok{"3.", 3.0}}) {
    char line[128];
    std::snprintf(line, sizeof line, "%10d%20s%20s%20s\n", 1, ok.text, "0", "0");
    const ReadResult r = read_deck_text(starter(std::string("/NODE\n") + line), "n.rad", Section::Starter);
    ASSERT_TRUE(r.ok()) << ok.text << "\n" << messages(r);
    EXPECT_EQ(r.deck.cards_of("/NODE")[0]->real(r.deck.cards_of("/NODE")[0]->row(0), "X"), ok.value) << ok.text;
  }
  struct Bad { const char* text; const char* message; };
  for (const Bad& bad : {Bad{"NaN", "/NODE field X = 'NaN': number expected, found text"},
                         Bad{"inf", "/NODE field X = 'inf': number expected, found text"},
                         Bad{"1e400", "/NODE field X = '1e400': number out of the representable range"},
                         Bad{"1.2.3", "/NODE field X = '1.2.3': number expected, found text"},
                         Bad{"1 2", "/NODE field X = '1 2': number expected, found text"},
                         Bad{"--1", "/NODE field X = '--1': number expected, found text"}}) {
    char line[128];
    std::snprintf(line, sizeof line, "%10d%20s%20s%20s\n", 1, bad.text, "0", "0");
    const ReadResult r = read_deck_text(starter(std::string("/NODE\n") + line), "n.rad", Section::Starter);
    ASSERT_EQ(r.diagnostics.size(), 1u) << bad.text << "\n" << messages(r);
    EXPECT_EQ(r.diagnostics[0].message, bad.message);
    EXPECT_EQ(r.diagnostics[0].loc.line, 7u);
    EXPECT_EQ(r.diagnostics[0].column, 31 - static_cast<int>(std::strlen(bad.text)));
  }
  // An integer field with a real in it.
  const ReadResult r = read_deck_text(starter("/NODE\n       1.5                  0.                  0.                  0.\n"),
                                      "n.rad", Section::Starter);
  ASSERT_EQ(r.diagnostics.size(), 1u) << messages(r);
  EXPECT_EQ(r.diagnostics[0].message, "/NODE field id = '1.5': integer expected");
  EXPECT_EQ(r.diagnostics[0].column, 8);
}

TEST(DeckDiagnostics, StructureErrors) {
  struct Case {
    std::string text;
    Section section;
    std::vector<std::string> messages;  // "line:col: message"
  };
  const std::vector<Case> cases = {
      {"/NODE\n" + node(1, 0, 0, 0) + "/END\n", Section::Starter,
       {"1:1: missing /BEGIN: the starter deck must start with /BEGIN"}},
      {starter("/MAT/LAW1\nm\n                  1.\n                  1.                 0.3\n"), Section::Starter,
       {"6:1: /MAT/LAW1 needs an id: /MAT/LAW1/id"}},
      {starter("/MAT/LAW1/4/2\nm\n"), Section::Starter,
       {"6:1: unit_ID in '/MAT/LAW1/4/2' is not supported: all values are in the units of /BEGIN"}},
      {starter("/MAT/LAW1/4\nm\n                  1.\n"), Section::Starter,
       {"6:1: /MAT/LAW1/4: missing data line 2 (elasticity)"}},
      {starter("/PART/4\n"), Section::Starter,
       {"6:1: /PART/4: missing title line (one line of text after the keyword)"}},
      {starter("/NODE\n\t1\n"), Section::Starter,
       {"7:1: tab character in a fixed-format line (fields are counted in columns; use spaces)"}},
      {starter("/NODE\n         1                  0.                  0.                  0.   7\n"),
       Section::Starter,
       {"7:74: /NODE: text in column 74, where this card has no field (columns 71-100 are unused)"}},
      {starter(cube_nodes() + "/BRICK/1\n         1         1         2         3         4         5         6         7\n" +
               kSolidPart),
       Section::Starter,
       {"16:81: /BRICK/1 field n8 = blank (default 0): required (must be >= 1)"}},
      {starter(cube_nodes() + "/BRICK/1\n         1         1         2         3         4         5         6         7         8\n" +
               "/PART/1\np\n         2         1\n/PROP/TYPE1/2\ns\n\n\n                                      1.\n"
               "/MAT/LAW1/1\nm\n                  1.\n                  1.                 0.3\n"),
       Section::Starter,
       {"15:1: /BRICK/1: part 1 has property /PROP/TYPE1/2; /BRICK elements need /PROP/TYPE14"}},
      {starter(cube_nodes() + "/SH3N/1\n         1         1         2         3\n         2         1         2         1\n" +
               "/PART/1\np\n         2         1\n/PROP/TYPE1/2\ns\n\n\n                                      1.\n"
               "/MAT/LAW1/1\nm\n                  1.\n                  1.                 0.3\n"),
       Section::Starter, {"17:1: /SH3N/1 element 2: degenerate shell (area 0)"}},
      {starter(cube_nodes() + "/TETRA4/1\n         1         1         3         2         5\n" + kSolidPart),
       Section::Starter,
       {"16:1: /TETRA4/1 element 1: inverted tetrahedron (6 x volume = -1; needs (n2-n1)x(n3-n1).(n4-n1) > 0)"}},
      {starter(kSolidPart + "/MAT/LAW34/1\nm2\n                  1.\n                  1.\n                  1.                  2.\n"),
       Section::Starter,
       {"16:1: /MAT/LAW34/1: duplicate material id 1 (first defined by /MAT/LAW1/1 at s.rad:12)",
        "20:21: /MAT/LAW34/1 field Ginf = 2: must be <= G0 = 1 (long-time shear modulus above the short-time one)"}},
      {starter("/GRNOD/NODE/1\ng\n" + std::string("         5\n") + "/BCS/1\nb\n  111  11         0         1\n"),
       Section::Starter,
       {"8:1: /GRNOD/NODE/1 field id1 = 5: node 5 is not defined",
        "11:3: /BCS/1: text in column 3, where this card has no field (columns 1-3 are unused)",
        "11:4: /BCS/1 field Tra = '11': must be three digits 0/1 for X Y Z (e.g. 111) in columns 4-6",
        "11:8: /BCS/1 field rot = '11': must be three digits 0/1 for X Y Z (e.g. 111) in columns 8-10"}},
      {"/RUN/r/1\n5\n/NODE\n/ANIM/VECT/VELO\n/PRINT/-10 3\n/STOP\n0 0.01 0 1 1 1\n", Section::Engine,
       {"3:1: keyword /NODE belongs to the starter deck (NAME_0000.rad), not this one",
        "4:1: keyword /ANIM/VECT/VELO is not supported; nearest supported keyword: /ANIM/VECT/VEL",
        "5:1: malformed keyword line '/PRINT/-10 3'", "7:14: /STOP: too many values on the line (expected 5)"}},
      {"/TFILE/4\n0.1\n/RUN/r/1\n-1\n", Section::Engine,
       {"1:1: missing /RUN: the engine deck must start with /RUN/name/1", "4:1: /RUN/r/1 field Tstop = -1: must be > 0"}},
  };
  for (const Case& c : cases) {
    const ReadResult r = read_deck_text(c.text, "s.rad", c.section);
    std::vector<std::string> got;
    for (const Diagnostic& d : r.diagnostics)
      got.push_back(std::to_string(d.loc.line) + ":" + std::to_string(d.column) + ": " + d.message);
    EXPECT_EQ(got, c.messages) << c.text;
    EXPECT_FALSE(r.ok());
  }
}

TEST(DeckDiagnostics, CheckDeckOnBuiltDecks) {
  Deck d;
  CardBuilder(d, "/BEGIN", 0, "b").set_int(0, "Invers", 2024).commit();
  CardBuilder(d, "/MAT/LAW1", 17, "m").set(0, "rho", 1e-6).set(1, "E", -1).set(1, "nu", 0.3).commit();
  CardBuilder(d, "/END").commit();
  const auto diags = check_deck(d);
  ASSERT_EQ(diags.size(), 1u);
  EXPECT_EQ(diags[0].message, "/MAT/LAW1/17 field E = -1: must be > 0");
  EXPECT_EQ(format(diags[0], d), "<generated>: error: /MAT/LAW1/17 field E = -1: must be > 0");
  EXPECT_THROW(CardBuilder(d, "/MAT/LAW99", 1), std::invalid_argument);
  EXPECT_THROW(CardBuilder(d, "/MAT/LAW1", 1).set(1, "Young", 1.0), std::out_of_range);
  EXPECT_THROW(CardBuilder(d, "/NODE").row_set(0, "X", 1.0), std::out_of_range);
}

TEST(DeckDiagnostics, BeginUnits) {
  const std::string ok = "/BEGIN\nu\n      2024\n                  Mg                  mm                 mus\n"
                         "                  kg                   m                   s\n/END\n";
  const ReadResult a = read_deck_text(ok, "u.rad", Section::Starter);
  ASSERT_TRUE(a.ok()) << messages(a);
  EXPECT_EQ(a.deck.input_units.mass, "Mg");
  EXPECT_EQ(a.deck.input_units.time, "mus");
  EXPECT_EQ(a.deck.work_units.length, "m");
  const std::string bad = "/BEGIN\nu\n      2024\n                  lb                  mm                  ms\n"
                          "                  kg                  mm                  ms\n/END\n";
  const ReadResult b = read_deck_text(bad, "u.rad", Section::Starter);
  ASSERT_EQ(b.diagnostics.size(), 1u) << messages(b);
  EXPECT_EQ(format(b.diagnostics[0], b.deck),
            "u.rad:4:1: error: /BEGIN field mass = 'lb': unknown unit (an SI prefix and g, e.g. kg, g, Mg)");
  // The factors to the base unit (the solver converts OpenRadioss's 10 kHz default of F_cut).
  EXPECT_EQ(hbm::deck::unit_factor("ms", 's'), 1e-3);
  EXPECT_EQ(hbm::deck::unit_factor("mus", 's'), 1e-6);
  EXPECT_EQ(hbm::deck::unit_factor("s", 's'), 1.0);
  EXPECT_EQ(hbm::deck::unit_factor("kg", 'g'), 1e3);
  EXPECT_EQ(hbm::deck::unit_factor("Mg", 'g'), 1e6);
  EXPECT_EQ(hbm::deck::unit_factor("dam", 'm'), 1e1);
  EXPECT_FALSE(hbm::deck::unit_factor("lb", 'g').has_value());
  EXPECT_FALSE(hbm::deck::unit_factor("ms", 'g').has_value());
  EXPECT_FALSE(hbm::deck::unit_factor("", 's').has_value());
}
