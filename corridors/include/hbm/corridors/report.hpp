// SPDX-License-Identifier: GPL-3.0-or-later
// Report writers: plots through gnuplot (PNG via the pngcairo terminal and SVG), a Markdown
// and an HTML report with a table of all channels (peaks, scores, grades) and the plots,
// and a machine-readable summary (summary.json and summary.csv).
#pragma once

#include <filesystem>
#include <string>

#include "hbm/corridors/evaluation.hpp"

namespace hbm::corridors {

/// Writes plots/<rating>.{png,svg} (plus the .dat and .gp files they came from) under dir.
/// gnuplot is run as an external process; throws std::runtime_error when it fails.
void write_plots(const EvaluationResult& result, const std::filesystem::path& dir,
                 const std::string& gnuplot = "gnuplot");

/// Writes report.md, report.html, summary.json, summary.csv and processed_signals.csv.
void write_report(const EvaluationResult& result, const std::filesystem::path& dir);

}  // namespace hbm::corridors
