// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-solver: explicit engine for Radioss-style decks.
//   hbm-solver NAME_0000.rad [--out DIR] [--threads N]   run (NAME_0001.rad beside it;
//                                    without --threads N > 0 the count is chosen by timing)
//   hbm-solver --check NAME_0000.rad                      check the deck only
//   hbm-solver --bench [--elements N] [--threads N]       phase timings on a brick block
// Exit codes: 0 normal termination, 1 deck or model errors, 2 command-line misuse,
// 3 run stopped early (inverted element, DMmax, Emax).
#include "hbm/deck/check_command.hpp"
#include "hbm/solver/run.hpp"

#include <CLI/CLI.hpp>

#include <iostream>

namespace hbm::solver {
int run_bench(std::size_t n_elements, int threads, std::ostream& out);
}

int main(int argc, char** argv) {
  CLI::App app{"hbm-solver: explicit engine for Radioss-style decks (NAME_0000.rad + NAME_0001.rad)"};
  std::string deck, out_dir = ".";
  int threads = 0;
  bool check = false, bench = false;
  std::size_t bench_elements = 100000;
  app.add_option("deck", deck, "starter deck NAME_0000.rad (engine deck NAME_0001.rad beside it)");
  app.add_option("--out", out_dir, "output folder (listing, CSV time histories, VTK animation)");
  app.add_option("--threads", threads,
                 "OpenMP threads for the whole run (results are bitwise the same for any count); 0 or absent: "
                 "chosen during the run by timing, 20 cycles on the OpenMP maximum against 20 on 1 thread, "
                 "the faster kept for 2000 cycles, then timed again (--bench: 1, then 2 threads)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--check", check, "check the deck and print a model summary; no run");
  app.add_flag("--bench", bench, "print ns per element-cycle / node-cycle per phase on a brick block");
  app.add_option("--elements", bench_elements, "bench block size (elements)")->check(CLI::PositiveNumber);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  if (bench) return hbm::solver::run_bench(bench_elements, threads, std::cout);
  if (deck.empty()) {
    std::cerr << "error: give a starter deck NAME_0000.rad (or --bench)\n" << app.help();
    return 2;
  }
  if (check) return hbm::deck::run_check(deck, std::cout, std::cerr);  // 0, 1 deck errors, 2 usage
  hbm::solver::RunOptions opt;
  opt.out_dir = out_dir;
  opt.threads = threads;
  opt.console = &std::cout;
  const hbm::solver::RunResult r = hbm::solver::run_deck(deck, opt, std::cerr);
  if (r.exit_code == 3) std::cerr << "hbm-solver: run stopped: " << r.message << "\n";
  return r.exit_code;
}
