// SPDX-License-Identifier: GPL-3.0-or-later
// Semantic mutation robustness of the whole solver (label verification): example decks
// that the deck library reads cleanly are damaged in their numbers (a field set to 0, -1,
// negated, scaled by 1e12 or 1e-3, an id pointed at 999999, two numbers swapped), keeping
// the fixed columns, so that the damage reaches the builders and the run itself rather
// than the reader (whose own mutation test, ctest/deck/test_mutations.cpp, garbles the
// text); one run in four damages the engine deck instead (time step, output and stop
// cards). Each mutated deck runs through hbm-solver, its end time cut to a tenth. Every run
// must end normally (0), stop with errors (1) or stop early on a criterion (3): never a
// crash, an abort, an exception, a sanitizer report or a hang (a run still going after 20 s,
// 60 s for the body model, must have got past 10,000 cycles: a deck can legitimately ask for
// a step 1000 times smaller). An error run must name the deck file and a line, and leave its output folder empty
// (outputs appear complete or not at all).
#include "example_deck_runner.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace hbm::solver::testing;

namespace {

struct Token {
  std::size_t line, begin, end;  // [begin, end) in the line
};

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// Numeric tokens of the data lines (not keywords, comments, /RUN lines or, in a starter
// deck, titles).
std::vector<Token> numeric_tokens(const std::vector<std::string>& lines, bool engine) {
  std::vector<Token> out;
  bool title_next = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l.empty() || l[0] == '#') continue;
    if (l[0] == '/') {
      // Keyword lines; the line after an object keyword with an id is its title.
      title_next = !engine && std::count(l.begin(), l.end(), '/') >= 2 && l != "/END";
      continue;
    }
    if (title_next) {
      title_next = false;
      continue;
    }
    if (i > 0 && lines[i - 1].rfind("/RUN/", 0) == 0) continue;  // the end time
    std::size_t p = 0;
    while (p < l.size()) {
      while (p < l.size() && l[p] == ' ') ++p;
      std::size_t q = p;
      while (q < l.size() && l[q] != ' ') ++q;
      if (q > p && is_number(l.substr(p, q - p))) out.push_back({i, p, q});
      p = q;
    }
  }
  return out;
}

// Writes `text` right-aligned to end where the token ends, taking spaces on its left.
bool put(std::string& line, const Token& t, const std::string& text) {
  std::size_t begin = t.begin;
  while (t.end - begin < text.size() && begin > 0 && line[begin - 1] == ' ') --begin;
  if (t.end - begin < text.size()) return false;
  line.replace(begin, t.end - begin, std::string(t.end - begin - text.size(), ' ') + text);
  return true;
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6E", v);
  return buf;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::string l;
  for (char c : text) {
    if (c == '\n') {
      lines.push_back(l);
      l.clear();
    } else {
      l += c;
    }
  }
  if (!l.empty()) lines.push_back(l);
  return lines;
}

// One mutation of a numeric token of a deck; its description. Starter decks keep their
// fixed columns; in the engine deck (free format) the token may grow. by_card: the card is
// drawn first, then a number in it (a large model's nodes and elements would otherwise take
// nearly every draw).
std::string mutate(std::vector<std::string>& lines, std::mt19937_64& rng, bool free_format = false,
                   bool by_card = false) {
  auto tokens = numeric_tokens(lines, free_format);
  if (tokens.empty()) return "none";
  if (by_card) {  // every card that holds a number is equally likely
    std::vector<std::size_t> card_of(lines.size(), 0);
    std::size_t card = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (!lines[i].empty() && lines[i][0] == '/') ++card;
      card_of[i] = card;
    }
    std::vector<std::size_t> cards;  // in line order, each once
    for (const Token& t : tokens)
      if (cards.empty() || cards.back() != card_of[t.line]) cards.push_back(card_of[t.line]);
    const std::size_t pick = cards[rng() % cards.size()];
    std::vector<Token> in_card;
    for (const Token& t : tokens)
      if (card_of[t.line] == pick) in_card.push_back(t);
    tokens = std::move(in_card);
  }
  const Token t = tokens[rng() % tokens.size()];
  std::string& line = lines[t.line];
  const std::string old = line.substr(t.begin, t.end - t.begin);
  const bool integer = old.find_first_of(".eE") == std::string::npos;
  const double v = std::strtod(old.c_str(), nullptr);
  std::string text;
  // Not scaled down in the engine deck: a fixed step 1000 times smaller is a legitimate run
  // 1000 times longer, not a robustness case.
  unsigned op = static_cast<unsigned>(rng() % 7);
  if (free_format && op == 4) op = 0;
  switch (op) {
    case 0: text = integer ? "0" : number_text(0.0); break;
    case 1: text = integer ? "-1" : number_text(-1.0); break;
    case 2: text = integer ? std::to_string(-static_cast<long long>(v)) : number_text(-v); break;
    case 3: text = integer ? "999999" : number_text(v * 1e12); break;
    case 4: text = integer ? "2" : number_text(v * 1e-3); break;  // 1e-12 on a density: 1e8 cycles
    case 5: text = integer ? "999999" : number_text(1e30); break;
    default: {  // swap with another number
      const Token u = tokens[rng() % tokens.size()];
      text = lines[u.line].substr(u.begin, u.end - u.begin);
      break;
    }
  }
  if (free_format) {
    line.replace(t.begin, t.end - t.begin, text);
  } else if (!put(line, t, text)) {
    return "none";
  }
  return "line " + std::to_string(t.line + 1) + ": '" + old + "' -> '" + text + "'";
}

// The cycle number of the listing's last progress line ("  CYCLE  TIME  TIME-STEP ..."), or -1.
long long last_listed_cycle(const std::string& text) {
  long long last = -1;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    const std::string line = text.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos);
    pos = nl == std::string::npos ? text.size() : nl + 1;
    char* end = nullptr;
    const long long cycle = std::strtoll(line.c_str(), &end, 10);
    if (end == line.c_str() || *end != ' ') continue;
    char* end2 = nullptr;
    std::strtod(end, &end2);
    if (end2 != end && line.find("e+") != std::string::npos) last = cycle;  // "cycle time ..." rows
  }
  return last;
}

struct Outcome {
  int normal = 0, errors = 0, stopped = 0, slow = 0, unchanged = 0;
};

// Runs hbm-solver on `starter` (outputs in <dir>/out, console in <dir>/log.txt, stopped after
// `timeout_s`) and checks the outcome: exit 0, 1 or 3, no crash or sanitizer report; an error
// run names one of `deck_files` with a line ("name:") and leaves no output. The folder is
// removed unless the run failed a check or was stopped. Returns the exit code.
int run_and_check(const fs::path& dir, const fs::path& starter, const std::vector<std::string>& deck_files,
                  int timeout_s, const std::string& what, Outcome& o) {
#ifndef HBM_SOLVER_EXE
  ADD_FAILURE() << "hbm-solver was not built";
  return -1;
#else
  const fs::path log = dir / "log.txt", out = dir / "out";
  const std::string cmd = "timeout " + std::to_string(timeout_s) + " '" + std::string(HBM_SOLVER_EXE) + "' '" +
                          starter.string() + "' --out '" + out.string() + "' > '" + log.string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  const std::string text = read_text(log);
  const std::string where = what + ", " + log.string();
  const bool had_failure = ::testing::Test::HasFailure();
  for (const char* bad : {"runtime error", "AddressSanitizer", "terminate called", "Assertion", "Segmentation"})
    EXPECT_EQ(text.find(bad), std::string::npos) << where << ":\n" << text;
  if (rc == 124) {
    // Still running at the limit (the example decks run in well under a second, the hub deck
    // in about one): a run that got past 10,000 cycles is a legitimately long one (a damaged
    // deck can ask for a fixed step 1000 times smaller); one stuck below is a hang.
    ++o.slow;
    EXPECT_GT(last_listed_cycle(text), 10000) << where << ": still running after " << timeout_s
                                              << " s without progress (a hang)\n"
                                              << text.substr(text.size() > 2000 ? text.size() - 2000 : 0);
    return rc;
  }
  EXPECT_TRUE(rc == 0 || rc == 1 || rc == 3) << where << ": exit " << rc << "\n" << text;
  if (rc == 0) ++o.normal;
  if (rc == 3) ++o.stopped;
  if (rc == 1) {
    ++o.errors;
    bool named = false;
    for (const auto& f : deck_files) named = named || text.find(f + ":") != std::string::npos;
    EXPECT_TRUE(named) << where << ": the error names no deck file and line\n" << text;
    EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out)) << where << ": an error run left files in " << out;
  }
  // Keep the folder of a run that failed a check (or of every run after a first failure).
  if (!had_failure && !::testing::Test::HasFailure()) fs::remove_all(dir);
  return rc;
#endif
}

void mutate_and_run(const std::string& name, int runs, std::uint64_t seed, Outcome& o) {
#ifndef HBM_SOLVER_EXE
  ADD_FAILURE() << "hbm-solver was not built";
#else
  const fs::path src = example_deck(name).parent_path();
  const std::vector<std::string> starter = lines_of(read_text(src / (name + "_0000.rad")));
  std::vector<std::string> engine = lines_of(read_text(src / (name + "_0001.rad")));
  for (std::size_t i = 1; i < engine.size(); ++i)
    if (engine[i - 1].rfind("/RUN/", 0) == 0) engine[i] = number_text(0.1 * std::strtod(engine[i].c_str(), nullptr));
  std::mt19937_64 rng(seed);
  for (int k = 0; k < runs; ++k) {
    std::vector<std::string> lines = starter, engine_lines = engine;
    // One run in four damages the engine deck (time step, output and stop cards).
    const bool in_engine = rng() % 4 == 0;
    const std::string what = (in_engine ? "engine deck " : "") +
                             (in_engine ? mutate(engine_lines, rng, true) : mutate(lines, rng));
    if (what.size() >= 4 && what.compare(what.size() - 4, 4, "none") == 0) {
      ++o.unchanged;
      continue;
    }
    const fs::path dir = fs::current_path() / ("mut_" + name + "_" + std::to_string(k) + per_process_suffix());
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
      std::ofstream s(dir / (name + "_0000.rad")), e(dir / (name + "_0001.rad"));
      for (const auto& l : lines) s << l << "\n";
      for (const auto& l : engine_lines) e << l << "\n";
    }
    run_and_check(dir, dir / (name + "_0000.rad"), {name + "_0000.rad", name + "_0001.rad"}, 20,
                  name + " run " + std::to_string(k) + " (" + what + ")", o);
  }
#endif
}

}  // namespace

// The body model: decks/hub_frontal_6p7 with its include decks/hbm50/hbm50.inc damaged (a
// card drawn among the model's 1,000-odd cards, then a number in it), run to 0.6 ms.
TEST(DeckMutationRuns, DamagedBodyModelNeverCrashesTheSolver) {
#ifndef HBM_SOLVER_EXE
  ADD_FAILURE() << "hbm-solver was not built";
#else
  const fs::path decks = fs::path(HBM_SOURCE_DIR) / "decks";
  const std::vector<std::string> model = lines_of(read_text(decks / "hbm50" / "hbm50.inc"));
  std::vector<std::string> engine = lines_of(read_text(decks / "hub_frontal_6p7" / "hub_frontal_6p7_0001.rad"));
  for (std::size_t i = 1; i < engine.size(); ++i)
    if (engine[i - 1].rfind("/RUN/", 0) == 0) engine[i] = "0.6";
  std::mt19937_64 rng(20261124);
  Outcome o;
  for (int k = 0; k < 60; ++k) {
    std::vector<std::string> lines = model;
    const std::string what = mutate(lines, rng, false, true);
    if (what == "none") {
      ++o.unchanged;
      continue;
    }
    const fs::path dir = fs::current_path() / ("mut_hbm50_" + std::to_string(k) + per_process_suffix());
    fs::remove_all(dir);
    fs::create_directories(dir / "hbm50");
    fs::create_directories(dir / "hub");
    {
      std::ofstream m(dir / "hbm50" / "hbm50.inc"), e(dir / "hub" / "hub_frontal_6p7_0001.rad");
      for (const auto& l : lines) m << l << "\n";
      for (const auto& l : engine) e << l << "\n";
    }
    fs::copy_file(decks / "hub_frontal_6p7" / "hub_frontal_6p7_0000.rad", dir / "hub" / "hub_frontal_6p7_0000.rad");
    const int rc = run_and_check(dir, dir / "hub" / "hub_frontal_6p7_0000.rad",
                                 {"hbm50.inc", "hub_frontal_6p7_0000.rad"}, 60,
                                 "hbm50 run " + std::to_string(k) + " (" + what + ")", o);
    // The card hit and the outcome, one line per run.
    std::size_t kw = std::stoul(what.substr(5, what.find(':') - 5)) - 1;
    while (kw > 0 && (lines[kw].empty() || lines[kw][0] != '/')) --kw;
    std::printf("  %-28s %-52s exit %d\n", lines[kw].substr(0, 28).c_str(), what.c_str(), rc);
  }
  std::printf("mutated body model runs: %d normal, %d stopped early, %d deck errors, %d stopped at 60 s, %d not mutated\n",
              o.normal, o.stopped, o.errors, o.slow, o.unchanged);
  EXPECT_GT(o.errors, 3);
  EXPECT_GT(o.normal + o.stopped, 3);
#endif
}

TEST(DeckMutationRuns, DamagedNumbersNeverCrashTheSolver) {
  Outcome o;
  const char* decks[] = {"uniaxial_law2",           "law36_erosion",          "law36_rate_filter",
                         "law34_impact",
                         "relax_law34",             "solid_ha8_law34_impact", "tetra_prism_uniaxial",
                         "shell_pull_failure_tria", "shell_fold_small_strain", "shell_cantilever_grav_quad",
                         "springs_nonlinear",       "springs_torsion",        "springs_damping",
                         "rigid_spring_impact",     "rigid_rwall_impact",     "rigid_tumbling",
                         "contact_block_slide",     "contact_sphere_rwall",   "shell_pull_ogden_quad"};
  std::uint64_t seed = 20261124;
  for (const char* d : decks) mutate_and_run(d, 40, seed++, o);
  std::printf("mutated runs: %d normal, %d stopped early, %d deck errors, %d stopped at 20 s, %d not mutated\n",
              o.normal, o.stopped, o.errors, o.slow, o.unchanged);
  EXPECT_GT(o.errors, 100);  // the damage reaches the checks
  EXPECT_GT(o.normal + o.stopped, 100);
}
