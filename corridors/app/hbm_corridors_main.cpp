// SPDX-License-Identifier: GPL-3.0-or-later
// hbm-corridors: rates a run's time histories against PMHS corridors and writes plots and a
// report.  hbm-corridors --case FILE --th RUN_DIR --out REPORT_DIR
// Exit status: 0 success, 1 bad input (message FILE:LINE: error: ...), 2 other failure
// (e.g. gnuplot missing). The report is written into a temporary sibling folder that is
// renamed to REPORT_DIR only when complete, so a failed run leaves no partial report. An
// existing REPORT_DIR is replaced only when it is empty or holds an earlier report.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <random>
#include <unistd.h>

#include "hbm/corridors/case_definition.hpp"
#include "hbm/corridors/evaluation.hpp"
#include "hbm/corridors/input_error.hpp"
#include "hbm/corridors/report.hpp"

namespace fs = std::filesystem;
using namespace hbm::corridors;

int main(int argc, char** argv) {
  CLI::App app{"hbm-corridors: filter time histories (SAE J211), rate them against PMHS corridors "
               "(ISO/TS 18571, CORA, inside fraction), compute injury criteria, draw plots and a report"};
  std::string case_file, run_dir, out_dir, gnuplot = "gnuplot";
  bool quiet = false;
  app.add_option("--case", case_file, "case definition (TOML, see docs/corridors.md)")->required();
  app.add_option("--th", run_dir, "run folder holding the time-history CSV files")->required();
  app.add_option("--out", out_dir, "report folder to write (an earlier report there is replaced)")->required();
  app.add_option("--gnuplot", gnuplot, "gnuplot executable");
  app.add_flag("--quiet", quiet, "print nothing on success");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help exits 0; a bad command line is bad input: exit 1 (docs/corridors.md)
    return app.exit(e) == 0 ? 0 : 1;
  }

  fs::path tmp;
  try {
    fs::path out = fs::absolute(out_dir).lexically_normal();
    if (out.has_parent_path() && out.filename().empty()) out = out.parent_path();  // trailing '/'
    // an existing REPORT_DIR is replaced only when it is empty or an earlier report
    if (fs::exists(out)) {
      const bool is_report = fs::is_directory(out) &&
                             (fs::is_empty(out) || (fs::exists(out / "summary.json") && fs::exists(out / "report.html")));
      if (!is_report)
        throw InputError(out.string(), 0,
                         "--out exists and is not an hbm-corridors report folder (no summary.json and report.html); "
                         "refusing to replace it");
    }
    const CaseDefinition cd = load_case(case_file);
    const EvaluationResult result = evaluate_case(cd, run_dir);
    const fs::path parent = out.parent_path();
    fs::create_directories(parent);
    tmp = parent / ("." + out.filename().string() + ".tmp-" + std::to_string(::getpid()));
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    write_plots(result, tmp, gnuplot);
    write_report(result, tmp);
    if (fs::exists(out)) fs::remove_all(out);
    fs::rename(tmp, out);
    tmp.clear();
    if (!quiet) {
      std::cout << "hbm-corridors: " << cd.title << "\n";
      for (const auto& r : result.ratings)
        std::cout << "  " << r.def.name << ": ISO/TS 18571 R = " << r.iso.overall << " (" << r.iso.grade
                  << "), CORA = " << r.cora.overall << ", inside corridor " << 100.0 * r.inside_fraction << " %\n";
      for (const auto& c : result.criteria)
        std::cout << "  " << c.quantity << " = " << c.value << (c.unit == "-" ? "" : " " + c.unit) << "\n";
      std::cout << "report: " << (out / "report.html").string() << "\n";
    }
    return 0;
  } catch (const InputError& e) {
    std::cerr << e.what() << "\n";
    if (!tmp.empty()) fs::remove_all(tmp);
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "hbm-corridors: error: " << e.what() << "\n";
    std::error_code ec;
    if (!tmp.empty()) fs::remove_all(tmp, ec);
    return 2;
  }
}
