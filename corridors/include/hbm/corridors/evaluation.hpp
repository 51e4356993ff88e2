// SPDX-License-Identifier: GPL-3.0-or-later
// Evaluation of a case against a run: reads the run's time-history CSVs, builds every
// signal (column lookup, unit conversion, scale, CFC filter, resampling to the common
// rate, combinations), sets time zero, rates each corridor (ISO/TS 18571, CORA, inside
// fraction) and computes the injury criteria. Pure computation: nothing is written here.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "hbm/corridors/case_definition.hpp"
#include "hbm/corridors/cora.hpp"
#include "hbm/corridors/corridor.hpp"
#include "hbm/corridors/iso18571.hpp"

namespace hbm::corridors {

struct ProcessedSignal {
  std::string name, unit;
  std::vector<double> y;  ///< on EvaluationResult::time_ms
  std::string source;     ///< "FILE: column" or "difference of a, b"
  double cfc = 0.0;
};

struct RatingResult {
  RatingDef def;
  Corridor corridor;              ///< converted to the display units below
  std::string x_unit, y_unit;     ///< display units (the corridor's, time in ms)
  bool reference_is_mean = true;  ///< false: the corridor mid-line stands in for the mean
  Polyline reference;             ///< reference curve shown in the plot (mean or mid-line)
  Polyline model;                 ///< model curve shown in the plot (x: time after t0 or deflection)
  std::vector<double> rated_abscissa, rated_reference, rated_model;  ///< what the ratings saw
  Iso18571Result iso;
  CoraResult cora;
  double inside_fraction = 0.0;
  double model_peak = 0.0, model_peak_x = 0.0;          ///< peak |y| of the model (signed), at x
  double reference_peak = 0.0, reference_peak_x = 0.0;  ///< peak |y| of the reference
  double model_peak_deflection = 0.0, reference_peak_deflection = 0.0;  ///< cross only
  std::string parameterisation;  ///< how the ratings' common abscissa was made
  std::vector<std::string> notes;
};

struct CriterionResult {
  CriterionDef def;
  std::string quantity;  ///< e.g. "HIC15", "VC max"
  double value = 0.0;
  std::string unit;
  double t1_ms = 0.0, t2_ms = 0.0;  ///< relative to time zero
  double limit = -1.0;              ///< < 0: none
  std::string limit_source;
  double risk = -1.0;               ///< < 0: no risk function
  std::string risk_source;
  std::string detail;
};

struct EvaluationResult {
  CaseDefinition definition;
  std::string run_dir;
  double t0_ms = 0.0;                ///< time zero on the solver's clock
  std::vector<double> time_ms;       ///< common grid, solver clock
  std::vector<ProcessedSignal> signals;
  std::vector<RatingResult> ratings;
  std::vector<CriterionResult> criteria;
  std::vector<std::string> input_files;

  const ProcessedSignal& signal(const std::string& name) const;
};

/// Throws InputError on bad input (missing file or column: the message lists the available
/// columns; unit mismatch; run too short for the rate).
EvaluationResult evaluate_case(const CaseDefinition& definition, const std::filesystem::path& run_dir);

}  // namespace hbm::corridors
