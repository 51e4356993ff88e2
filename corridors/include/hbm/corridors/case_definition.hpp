// SPDX-License-Identifier: GPL-3.0-or-later
// Case definition: a TOML file (format in docs/corridors.md) saying which time-history
// columns feed which corridor, with sign and unit conversions, CFC filter classes, time
// zero, cross-plots (force against deflection = impactor minus spine displacement) and the
// injury criteria to compute. Every entry keeps its line so errors point into the file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "hbm/corridors/corridor.hpp"

namespace hbm::corridors {

/// One processed channel: a CSV column (converted, scaled, filtered) or a combination of
/// other signals (difference a - b, sum, resultant).
struct SignalDef {
  std::string name;
  long line = 0;
  std::string file;         ///< CSV file in the run folder ('*' wildcards); "" = search all
  std::string column;       ///< exact header, name, or unique substring (sum_columns: a '*'/'?' pattern)
  bool sum_columns = false; ///< sum every column whose name matches the pattern `column`
  std::string unit;         ///< unit of the column when its header has none
  double scale = 1.0;       ///< multiplier (sign flip, mass for force = m a, ...)
  std::string scaled_unit;  ///< unit after scaling, when the scale changes the dimension
  std::string to_unit;      ///< unit of the processed signal ("" = keep)
  double cfc = 0.0;         ///< SAE J211 channel class; 0 = no filter
  std::string combine;      ///< "", "difference", "sum", "resultant"
  std::vector<std::string> of;  ///< signals combined
  bool zero_at_time_zero = false;  ///< subtract the value at time zero (displacements)
};

struct TimeZeroDef {
  std::string method = "given";  ///< "given" or "first_exceed"
  double time_ms = 0.0;          ///< for "given"
  std::string signal;            ///< for "first_exceed"
  double threshold = 0.0;        ///< in the signal's processed unit
  bool use_filtered = false;     ///< detect on the CFC-filtered signal (default: unfiltered,
                                 ///< as a zero-phase filter spreads a contact onset backwards)
  long line = 0;
};

struct RatingDef {
  std::string name, title;
  long line = 0;
  std::string kind;       ///< "time" (signal against time) or "cross" (y against x)
  std::string y_signal;   ///< rated signal (ordinate)
  std::string x_signal;   ///< abscissa signal for "cross"
  std::string method = "loading";  ///< cross: "loading" or "arc_length"
  std::size_t points = 500;        ///< cross: grid points of the parameterisation
  std::string x_label, y_label;    ///< axis quantity names (units are added)
  CorridorSpec corridor;
};

struct CriterionDef {
  std::string kind;  ///< peak, hic, a3ms, chest_deflection, vc, nij, belt_force, failed_elements
  std::string name;
  long line = 0;
  std::string signal;
  std::vector<std::string> signals;  ///< failed_elements
  std::string fz, my, fx;            ///< nij
  double window_ms = 15.0;           ///< hic
  double age_years = 45.0;           ///< chest_deflection (Laituri 2005 risk)
  double scale_factor = 1.3;         ///< vc
  double d0_mm = 229.0;              ///< vc
  double e_m = 0.01778;              ///< nij moment arm
  double limit = -1.0;               ///< < 0: none given
  std::string unit;                  ///< peak: report unit ("" = signal unit)
};

struct CaseDefinition {
  std::string path;
  std::string name, title, description;
  double rate_hz = 10000.0;
  std::string time_unit = "ms";  ///< unit of time columns whose header has none
  TimeZeroDef time_zero;
  std::vector<SignalDef> signals;
  std::vector<RatingDef> ratings;
  std::vector<CriterionDef> criteria;

  const SignalDef* find_signal(const std::string& name) const;
};

/// Parses and checks a case file. Throws InputError "FILE:LINE: error: ..." on any problem
/// (syntax, unknown key, wrong type, unknown unit, missing corridor file, undefined signal).
CaseDefinition load_case(const std::filesystem::path& path);

}  // namespace hbm::corridors
