// SPDX-License-Identifier: GPL-3.0-or-later
// Case evaluation: signals, time zero, ratings, criteria (see evaluation.hpp).
#include "hbm/corridors/evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "hbm/corridors/cfc_filter.hpp"
#include "hbm/corridors/cross_plot.hpp"
#include "hbm/corridors/injury_criteria.hpp"
#include "hbm/corridors/input_error.hpp"
#include "hbm/corridors/risk_functions.hpp"
#include "hbm/corridors/time_history_csv.hpp"
#include "hbm/corridors/units.hpp"

namespace fs = std::filesystem;

namespace hbm::corridors {
namespace {

std::string fmt(double v, int digits = 4) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

bool wildcard_match(const std::string& pattern, const std::string& text) {
  // '*' matches any run of characters, '?' one character
  std::size_t p = 0, t = 0, star = std::string::npos, mark = 0;
  while (t < text.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t])) {
      ++p;
      ++t;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      mark = t;
    } else if (star != std::string::npos) {
      p = star + 1;
      t = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

double factor(const std::string& from, const std::string& to, const std::string& file, long line,
              const std::string& what) {
  if (to.empty() || from == to) return 1.0;
  try {
    return unit_conversion_factor(from, to);
  } catch (const std::exception& e) {
    throw InputError(file, line, what + ": " + e.what());
  }
}

struct RawSignal {
  std::vector<double> t_ms, y;
};

class SignalBuilder {
public:
  SignalBuilder(const CaseDefinition& cd, const fs::path& run_dir, EvaluationResult& out)
      : cd_(cd), run_dir_(run_dir), out_(out) {
    if (!fs::is_directory(run_dir)) throw InputError(run_dir.string(), 0, "run folder not found");
    for (const auto& e : fs::directory_iterator(run_dir))
      if (e.is_regular_file() && e.path().extension() == ".csv") csv_files_.push_back(e.path());
    std::sort(csv_files_.begin(), csv_files_.end());
    if (csv_files_.empty()) throw InputError(run_dir.string(), 0, "run folder holds no .csv time-history file");
  }

  void build() {
    std::map<std::string, RawSignal> raw;
    for (const auto& s : cd_.signals)
      if (s.combine.empty()) raw[s.name] = read_raw(s);
    // common grid: the time range every raw signal covers, at the case's rate
    double t_start = -std::numeric_limits<double>::infinity();
    double t_end = std::numeric_limits<double>::infinity();
    for (const auto& [n, r] : raw) {
      t_start = std::max(t_start, r.t_ms.front());
      t_end = std::min(t_end, r.t_ms.back());
    }
    const double dt_ms = 1000.0 / cd_.rate_hz;
    out_.time_ms = uniform_grid(t_start, t_end, dt_ms);
    if (out_.time_ms.size() < 10)
      throw InputError(cd_.path, 0, "the signals share less than 10 samples at " + fmt(cd_.rate_hz) +
                                        " Hz (common time range " + fmt(t_start) + " to " + fmt(t_end) + " ms)");
    for (const auto& [n, r] : unfiltered_)
      out_unfiltered_[n] = resample_linear(r.t_ms, r.y, out_.time_ms);
    for (const auto& s : cd_.signals) {
      ProcessedSignal p;
      p.name = s.name;
      p.cfc = s.cfc;
      if (s.combine.empty()) {
        const RawSignal& r = raw.at(s.name);
        p.y = resample_linear(r.t_ms, r.y, out_.time_ms);
        p.unit = units_.at(s.name);
        p.source = sources_.at(s.name);
      } else {
        combine(s, p);
      }
      out_.signals.push_back(std::move(p));
    }
  }

private:
  const TimeHistoryTable& table(const fs::path& p) {
    auto it = tables_.find(p.string());
    if (it == tables_.end()) {
      it = tables_.emplace(p.string(), read_time_history_csv(p)).first;
      out_.input_files.push_back(p.string());
    }
    return it->second;
  }

  RawSignal read_raw(const SignalDef& s) {
    std::vector<fs::path> candidates;
    if (s.file.empty()) {
      candidates = csv_files_;
    } else if (s.file.find_first_of("*?") != std::string::npos) {
      for (const auto& f : csv_files_)
        if (wildcard_match(s.file, f.filename().string())) candidates.push_back(f);
    } else if (fs::exists(run_dir_ / s.file)) {
      candidates.push_back(run_dir_ / s.file);
    }
    if (candidates.empty()) {
      std::string files;
      for (const auto& f : csv_files_) files += "\n  " + f.filename().string();
      throw InputError(cd_.path, s.line, "signal '" + s.name + "': no file '" + s.file + "' in run folder " +
                                             run_dir_.string() + "; CSV files there:" + files);
    }
    std::vector<std::pair<const TimeHistoryTable*, long>> hits;
    std::vector<const TimeHistoryTable*> searched;
    std::string skipped;
    for (const auto& f : candidates) {
      const TimeHistoryTable* t = nullptr;
      if (s.file.empty()) {
        // searching the whole folder: a CSV that is not a time history (no time column,
        // other data) is passed over, and named if the column is not found elsewhere
        try {
          t = &table(f);
        } catch (const InputError& e) {
          skipped += std::string("\n  skipped (not a readable time history): ") + e.what();
          continue;
        }
      } else {
        t = &table(f);
      }
      searched.push_back(t);
      if (s.sum_columns) {
        for (std::size_t c = 0; c < t->names.size(); ++c)
          if (c != t->time_column && wildcard_match(s.column, t->names[c])) hits.emplace_back(t, static_cast<long>(c));
        continue;
      }
      const long c = find_column(*t, s.column);
      if (c >= 0 && static_cast<std::size_t>(c) != t->time_column) hits.emplace_back(t, c);
    }
    if (hits.empty()) {
      std::string avail;
      for (const TimeHistoryTable* t : searched) avail += "\n " + t->path + ":" + list_columns(*t);
      avail += skipped;
      const std::string what = s.sum_columns ? "no column name matches '" + s.column + "'"
                                             : "column '" + s.column + "' not found (exact header, name or unique substring)";
      throw InputError(cd_.path, s.line, "signal '" + s.name + "': " + what + "; available columns:" + avail);
    }
    if (s.sum_columns) return sum_of_columns(s, hits);
    if (hits.size() > 1) {
      std::string which;
      for (const auto& [t, c] : hits) which += "\n  " + t->path + ": " + t->headers[static_cast<std::size_t>(c)];
      throw InputError(cd_.path, s.line, "signal '" + s.name + "': column '" + s.column +
                                             "' is found in more than one file; give 'file':" + which);
    }
    const TimeHistoryTable& t = *hits[0].first;
    const auto c = static_cast<std::size_t>(hits[0].second);
    return to_raw(s, t, t.columns[c], t.headers[c], t.units[c]);
  }

  // A signal that sums every column whose name matches the pattern `column` ('*' and '?'
  // wildcards; sum_columns = true), e.g. the deleted elements of every rib part. The columns
  // must share one file (one time base) and one unit.
  RawSignal sum_of_columns(const SignalDef& s, const std::vector<std::pair<const TimeHistoryTable*, long>>& hits) {
    const TimeHistoryTable& t = *hits[0].first;
    const auto c0 = static_cast<std::size_t>(hits[0].second);
    std::vector<double> sum(t.n_rows(), 0.0);
    for (const auto& [tt, c] : hits) {
      const auto cc = static_cast<std::size_t>(c);
      if (tt != &t)
        throw InputError(cd_.path, s.line, "signal '" + s.name + "': columns matching '" + s.column + "' are in " + t.path +
                                               " and " + tt->path + "; give 'file'");
      if (tt->units[cc] != t.units[c0])
        throw InputError(cd_.path, s.line, "signal '" + s.name + "': columns matching '" + s.column + "' have different units ('" +
                                               t.headers[c0] + "', '" + tt->headers[cc] + "')");
      for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += tt->columns[cc][i];
    }
    const std::string header = "sum of " + std::to_string(hits.size()) + " columns matching '" + s.column + "'";
    return to_raw(s, t, sum, header, t.units[c0]);
  }

  // Unit checks, scaling, time base, optional CFC filter of one column's values.
  RawSignal to_raw(const SignalDef& s, const TimeHistoryTable& t, const std::vector<double>& values, const std::string& header,
                   const std::string& column_unit) {
    std::string unit = column_unit;
    if (unit.empty()) unit = s.unit;
    if (unit.empty())
      throw InputError(cd_.path, s.line, "signal '" + s.name + "': column '" + header + "' in " + t.path +
                                             " has no [unit] in its header; give unit = \"...\" in the case");
    if (!s.unit.empty() && !column_unit.empty() && s.unit != column_unit)
      throw InputError(cd_.path, s.line, "signal '" + s.name + "': case says unit '" + s.unit + "' but " + t.path +
                                             " header says '" + header + "'");
    if (!is_known_unit(unit))
      throw InputError(cd_.path, s.line, "signal '" + s.name + "': unit '" + unit + "' of column '" + header +
                                             "' is not known (see docs/corridors.md for the unit list)");
    std::string tunit = t.units[t.time_column].empty() ? cd_.time_unit : t.units[t.time_column];
    if (!is_known_unit(tunit) || unit_dimension(tunit) != "time")
      throw InputError(t.path, t.header_line, "time column '" + t.headers[t.time_column] + "' has unit '" + tunit +
                                                  "', which is not a time unit");
    const double tf = unit_conversion_factor(tunit, "ms");
    const std::string scaled_unit = s.scaled_unit.empty() ? unit : s.scaled_unit;
    const std::string final_unit = s.to_unit.empty() ? scaled_unit : s.to_unit;
    const double yf = s.scale * factor(scaled_unit, final_unit, cd_.path, s.line, "signal '" + s.name + "'");
    RawSignal r;
    r.t_ms.resize(t.n_rows());
    r.y.resize(t.n_rows());
    for (std::size_t i = 0; i < t.n_rows(); ++i) {
      r.t_ms[i] = t.columns[t.time_column][i] * tf;
      r.y[i] = values[i] * yf;
    }
    // drop repeated time stamps (keep the last value), then make the sampling uniform
    RawSignal u;
    for (std::size_t i = 0; i < r.t_ms.size(); ++i) {
      if (!u.t_ms.empty() && r.t_ms[i] <= u.t_ms.back()) {
        u.y.back() = r.y[i];
        continue;
      }
      u.t_ms.push_back(r.t_ms[i]);
      u.y.push_back(r.y[i]);
    }
    if (u.t_ms.size() < 3) throw InputError(t.path, 0, "fewer than 3 distinct time stamps");
    if (!is_uniform(u.t_ms)) {
      std::vector<double> d(u.t_ms.size() - 1);
      for (std::size_t i = 0; i + 1 < u.t_ms.size(); ++i) d[i] = u.t_ms[i + 1] - u.t_ms[i];
      std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
      const auto g = uniform_grid(u.t_ms.front(), u.t_ms.back(), d[d.size() / 2]);
      u.y = resample_linear(u.t_ms, u.y, g);
      u.t_ms = g;
    }
    unfiltered_[s.name] = u;
    if (s.cfc > 0.0) {
      const double dt_s = (u.t_ms.back() - u.t_ms.front()) / static_cast<double>(u.t_ms.size() - 1) * 1e-3;
      try {
        u.y = cfc_filter(u.y, dt_s, s.cfc);
      } catch (const std::invalid_argument& e) {
        throw InputError(cd_.path, s.line, "signal '" + s.name + "' from " + t.path + ": " + e.what());
      }
    }
    units_[s.name] = final_unit;
    sources_[s.name] = fs::path(t.path).filename().string() + ": " + header;
    return u;
  }

  void combine(const SignalDef& s, ProcessedSignal& p) {
    const ProcessedSignal& first = out_.signal(s.of[0]);
    p.unit = first.unit;
    p.y.assign(out_.time_ms.size(), 0.0);
    p.source = s.combine + " of";
    for (std::size_t k = 0; k < s.of.size(); ++k) {
      const ProcessedSignal& o = out_.signal(s.of[k]);
      const double f = factor(o.unit, p.unit, cd_.path, s.line, "signal '" + s.name + "' combines '" + o.name + "'");
      for (std::size_t i = 0; i < p.y.size(); ++i) {
        const double v = f * o.y[i];
        if (s.combine == "resultant")
          p.y[i] += v * v;
        else if (s.combine == "difference" && k == 1)
          p.y[i] -= v;
        else
          p.y[i] += v;
      }
      p.source += (k ? ", " : " ") + o.name;
    }
    if (s.combine == "resultant")
      for (double& v : p.y) v = std::sqrt(v);
    const std::string scaled_unit = s.scaled_unit.empty() ? p.unit : s.scaled_unit;
    const std::string final_unit = s.to_unit.empty() ? scaled_unit : s.to_unit;
    const double yf = s.scale * factor(scaled_unit, final_unit, cd_.path, s.line, "signal '" + s.name + "'");
    for (double& v : p.y) v *= yf;
    p.unit = final_unit;
  }

  const CaseDefinition& cd_;
  fs::path run_dir_;
  EvaluationResult& out_;
  std::vector<fs::path> csv_files_;
  std::map<std::string, TimeHistoryTable> tables_;
  std::map<std::string, std::string> units_, sources_;
  std::map<std::string, RawSignal> unfiltered_;

public:
  std::map<std::string, std::vector<double>> out_unfiltered_;  ///< raw signals before filtering, on the grid
};

double find_time_zero(const CaseDefinition& cd, const EvaluationResult& r,
                      const std::map<std::string, std::vector<double>>& unfiltered) {
  const TimeZeroDef& tz = cd.time_zero;
  if (tz.method == "given") return tz.time_ms;
  const ProcessedSignal& s = r.signal(tz.signal);
  const auto it = unfiltered.find(tz.signal);
  // unfiltered by default: a zero-phase filter spreads a contact onset backwards in time
  const std::vector<double>& y = (tz.use_filtered || it == unfiltered.end()) ? s.y : it->second;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (y[i] >= tz.threshold) {
      if (i == 0) return r.time_ms[0];
      const double w = (tz.threshold - y[i - 1]) / (y[i] - y[i - 1]);
      return r.time_ms[i - 1] + w * (r.time_ms[i] - r.time_ms[i - 1]);
    }
  }
  const double mx = *std::max_element(y.begin(), y.end());
  throw InputError(cd.path, tz.line, "[time_zero]: signal '" + tz.signal + "' never reaches the threshold " +
                                         fmt(tz.threshold) + " " + s.unit + " (its maximum is " + fmt(mx) + ")");
}

std::vector<double> converted(const CaseDefinition& cd, const EvaluationResult& r, const std::string& name,
                              const std::string& unit, long line, const std::string& who) {
  const ProcessedSignal& s = r.signal(name);
  const double f = factor(s.unit, unit, cd.path, line, who + " uses signal '" + name + "'");
  std::vector<double> y = s.y;
  for (double& v : y) v *= f;
  return y;
}

void rate_time(const CaseDefinition& cd, EvaluationResult& r, RatingResult& rr) {
  const double dt_ms = 1000.0 / cd.rate_hz;
  const auto y = converted(cd, r, rr.def.y_signal, rr.y_unit, rr.def.line, "rating '" + rr.def.name + "'");
  std::vector<double> t(r.time_ms.size());
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = r.time_ms[i] - r.t0_ms;
  const Polyline poly = corridor_polygon(rr.corridor);
  const double xmin = *std::min_element(poly.x.begin(), poly.x.end());
  const double xmax = *std::max_element(poly.x.begin(), poly.x.end());
  if (rr.corridor.has_mean()) {
    rr.reference = rr.corridor.mean;
  } else {
    rr.reference_is_mean = false;
    rr.reference.x = uniform_grid(xmin, xmax, (xmax - xmin) / 400.0);
    rr.reference.y = corridor_midline(rr.corridor, rr.reference.x);
  }
  const double a = std::max(rr.reference.x.front(), t.front());
  const double b = std::min(rr.reference.x.back(), t.back());
  rr.rated_abscissa = uniform_grid(a, b, dt_ms);
  if (rr.rated_abscissa.size() < 10)
    throw InputError(r.run_dir, 0, "rating '" + rr.def.name + "': the run covers only " + fmt(t.back()) +
                                       " ms after time zero, the corridor spans " + fmt(rr.reference.x.front()) + " to " +
                                       fmt(rr.reference.x.back()) + " ms");
  if (b < rr.reference.x.back() - 1e-9)
    rr.notes.push_back("the run ends " + fmt(b) + " ms after time zero, before the corridor's end at " +
                       fmt(rr.reference.x.back()) + " ms: rated up to the run's end");
  if (rr.reference_is_mean)
    rr.rated_reference = resample_linear(rr.reference.x, rr.reference.y, rr.rated_abscissa);
  else
    rr.rated_reference = corridor_midline(rr.corridor, rr.rated_abscissa);
  rr.rated_model = resample_linear(t, y, rr.rated_abscissa);
  rr.parameterisation = "time after time zero [ms], uniform at " + fmt(cd.rate_hz) + " Hz";
  // inside fraction over the corridor's time span
  std::vector<double> ix, iy;
  const double span = xmax - xmin;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] >= xmin && t[i] <= xmax) {
      ix.push_back(t[i]);
      iy.push_back(y[i]);
    }
    if (t[i] >= xmin - 0.1 * span && t[i] <= xmax + 0.25 * span) {
      rr.model.x.push_back(t[i]);
      rr.model.y.push_back(y[i]);
    }
  }
  rr.inside_fraction = inside_fraction(poly, ix, iy);
}

void rate_cross(const CaseDefinition& cd, EvaluationResult& r, RatingResult& rr) {
  const auto y = converted(cd, r, rr.def.y_signal, rr.y_unit, rr.def.line, "rating '" + rr.def.name + "'");
  const auto x = converted(cd, r, rr.def.x_signal, rr.x_unit, rr.def.line, "rating '" + rr.def.name + "'");
  // model event: from time zero until the force has dropped below 5 % of its peak after the
  // largest deflection (the unloading end), or the end of the run
  std::size_t i0 = 0;
  while (i0 < r.time_ms.size() && r.time_ms[i0] < r.t0_ms) ++i0;
  if (i0 + 10 >= r.time_ms.size())
    throw InputError(r.run_dir, 0, "rating '" + rr.def.name + "': fewer than 10 samples after time zero");
  std::size_t ixmax = i0;
  double ymax = 0.0;
  for (std::size_t i = i0; i < x.size(); ++i) {
    if (x[i] > x[ixmax]) ixmax = i;
    ymax = std::max(ymax, y[i]);
  }
  std::size_t iend = x.size() - 1;
  for (std::size_t i = ixmax; i < x.size(); ++i)
    if (y[i] < 0.05 * ymax) {
      iend = i;
      break;
    }
  for (std::size_t i = i0; i <= iend; ++i) {
    rr.model.x.push_back(x[i]);
    rr.model.y.push_back(y[i]);
  }
  const Polyline poly = corridor_polygon(rr.corridor);
  if (rr.corridor.has_mean()) {
    rr.reference = rr.corridor.mean;
  } else {
    rr.reference_is_mean = false;
    const double xmin = *std::min_element(poly.x.begin(), poly.x.end());
    const double xmax = *std::max_element(poly.x.begin(), poly.x.end());
    rr.reference.x = uniform_grid(xmin, xmax, (xmax - xmin) / 400.0);
    rr.reference.y = corridor_midline(rr.corridor, rr.reference.x);
  }
  ParameterisedCurves pc;
  try {
    pc = rr.def.method == "arc_length" ? parameterise_arc_length(rr.reference, rr.model, rr.def.points)
                                       : parameterise_loading(rr.reference, rr.model, rr.def.points);
  } catch (const std::invalid_argument& e) {
    throw InputError(r.run_dir, 0, "rating '" + rr.def.name + "': " + e.what());
  }
  rr.rated_abscissa = pc.abscissa;
  rr.rated_reference = pc.reference;
  rr.rated_model = pc.model;
  rr.model_peak_deflection = pc.model_reach;
  rr.reference_peak_deflection = pc.reference_reach;
  if (rr.def.method == "arc_length") {
    rr.parameterisation = "whole loop by arc-length fraction (coordinates normalised by the reference's largest "
                          "deflection and force), " + std::to_string(rr.def.points) + " points";
  } else {
    rr.parameterisation = "loading branch, force over deflection " + fmt(pc.abscissa.front()) + " to " +
                          fmt(pc.abscissa.back()) + " " + rr.x_unit + ", " + std::to_string(rr.def.points) + " points";
    if (pc.model_reach < pc.reference_reach)
      rr.notes.push_back("the model's largest deflection " + fmt(pc.model_reach) + " " + rr.x_unit +
                         " is below the reference's " + fmt(pc.reference_reach) + " " + rr.x_unit +
                         ": force beyond it counts as 0 in the ratings");
  }
  // inside fraction over what is rated: the loading branch (points up to the largest
  // deflection) for "loading", the whole loop for "arc_length"
  if (rr.def.method == "arc_length") {
    rr.inside_fraction = inside_fraction(poly, rr.model.x, rr.model.y);
  } else {
    const auto imax = static_cast<std::size_t>(std::max_element(rr.model.x.begin(), rr.model.x.end()) - rr.model.x.begin());
    const std::vector<double> lx(rr.model.x.begin(), rr.model.x.begin() + static_cast<long>(imax) + 1);
    const std::vector<double> ly(rr.model.y.begin(), rr.model.y.begin() + static_cast<long>(imax) + 1);
    rr.inside_fraction = inside_fraction(poly, lx, ly);
  }
}

CriterionResult evaluate_criterion(const CaseDefinition& cd, const EvaluationResult& r, const CriterionDef& c,
                                   const std::vector<double>& t_rel) {
  CriterionResult out;
  out.def = c;
  out.limit = c.limit;
  const std::string who = "criterion '" + c.name + "'";
  auto in = [&](const std::string& name, const std::string& unit) { return converted(cd, r, name, unit, c.line, who); };
  if (c.kind == "peak") {
    const std::string unit = c.unit.empty() ? r.signal(c.signal).unit : c.unit;
    const auto p = signed_peak(t_rel, in(c.signal, unit));
    out.quantity = c.name != "peak" ? c.name : "peak " + c.signal;
    out.value = p.value;
    out.unit = unit;
    out.t1_ms = out.t2_ms = p.t1;
  } else if (c.kind == "hic") {
    const auto h = head_injury_criterion(t_rel, in(c.signal, "g"), c.window_ms);
    out.quantity = "HIC" + fmt(c.window_ms);
    out.value = h.value;
    out.unit = "-";
    out.t1_ms = h.t1;
    out.t2_ms = h.t2;
    if (out.limit < 0.0 && (c.window_ms == 15.0 || c.window_ms == 36.0)) {
      out.limit = c.window_ms == 15.0 ? 700.0 : 1000.0;
      out.limit_source = "FMVSS 208 (49 CFR 571.208 S6.2)";
    }
    if (c.window_ms == 15.0) {
      out.risk = hic15_ais3_risk_nhtsa(h.value);
      out.risk_source = "AIS3+ head, NHTSA NCAP 2008 lognormal [check]";
    }
  } else if (c.kind == "a3ms") {
    const auto a = in(c.signal, "g");
    out.quantity = "a3ms (cumulative)";
    out.value = a3ms_cumulative(t_rel, a);
    out.unit = "g";
    const auto clip = a3ms_continuous(t_rel, a);
    out.detail = "continuous 3 ms clip: " + fmt(clip.value) + " g at " + fmt(clip.t1) + " to " + fmt(clip.t2) + " ms";
    if (out.limit < 0.0) {
      out.limit = 60.0;
      out.limit_source = "FMVSS 208 S6.3";
    }
  } else if (c.kind == "chest_deflection") {
    const auto p = signed_peak(t_rel, in(c.signal, "mm"));
    out.quantity = "peak chest deflection";
    out.value = std::abs(p.value);
    out.unit = "mm";
    out.t1_ms = out.t2_ms = p.t1;
    out.risk = chest_deflection_ais3_risk_laituri2005(out.value, c.age_years);
    out.risk_source = "AIS3+ thorax at age " + fmt(c.age_years) + ", Laituri et al. 2005 [check]";
    if (out.limit >= 0.0) out.limit_source = "case file";
  } else if (c.kind == "vc") {
    const auto vc = viscous_criterion(t_rel, in(c.signal, "mm"), c.scale_factor, c.d0_mm);
    const auto p = signed_peak(t_rel, vc);
    out.quantity = "VC max";
    out.value = p.value;
    out.unit = "m/s";
    out.t1_ms = out.t2_ms = p.t1;
    out.detail = "scale factor " + fmt(c.scale_factor) + ", D0 = " + fmt(c.d0_mm) + " mm";
    if (out.limit < 0.0) {
      out.limit = 1.0;
      out.limit_source = "Lau & Viano 1986 (25 % AIS4+ risk level) [check]";
    }
  } else if (c.kind == "nij") {
    const auto n = neck_injury_criterion(t_rel, in(c.fz, "N"), in(c.my, "N*m"),
                                         c.fx.empty() ? std::vector<double>{} : in(c.fx, "N"), c.e_m);
    out.quantity = "Nij";
    out.value = n.value;
    out.unit = "-";
    out.t1_ms = out.t2_ms = n.t_ms;
    out.detail = "mode " + n.mode + "; NTE " + fmt(n.nte) + ", NTF " + fmt(n.ntf) + ", NCE " + fmt(n.nce) + ", NCF " +
                 fmt(n.ncf) + (c.fx.empty() ? "" : "; My corrected by " + fmt(c.e_m) + " m x Fx");
    if (out.limit < 0.0) {
      out.limit = 1.0;
      out.limit_source = "FMVSS 208 S6.6";
    }
    out.risk = nij_ais3_risk_nhtsa(n.value);
    out.risk_source = "AIS3+ neck, NHTSA NCAP 2008 [check]";
  } else if (c.kind == "belt_force") {
    const auto p = signed_peak(t_rel, in(c.signal, "kN"));
    out.quantity = "peak belt force " + (c.name != "belt_force" ? c.name : c.signal);
    out.value = std::abs(p.value);
    out.unit = "kN";
    out.t1_ms = out.t2_ms = p.t1;
    if (out.limit < 0.0) {
      out.limit = foret_bruno_belt_force_50pct_kN;
      out.limit_source = "50 % AIS3+ thorax, Foret-Bruno et al. 1998";
    }
  }
  return out;
}

}  // namespace

const ProcessedSignal& EvaluationResult::signal(const std::string& name) const {
  for (const auto& s : signals)
    if (s.name == name) return s;
  throw std::logic_error("signal '" + name + "' not built");
}

EvaluationResult evaluate_case(const CaseDefinition& cd, const fs::path& run_dir) {
  EvaluationResult r;
  r.definition = cd;
  r.run_dir = run_dir.string();
  SignalBuilder builder(cd, run_dir, r);
  builder.build();
  r.t0_ms = find_time_zero(cd, r, builder.out_unfiltered_);
  for (const auto& sd : cd.signals) {
    if (!sd.zero_at_time_zero) continue;
    for (auto& s : r.signals)
      if (s.name == sd.name) {
        const double v0 = resample_linear(r.time_ms, s.y, {r.t0_ms})[0];
        for (double& v : s.y) v -= v0;
        s.source += "; zeroed at time zero";
      }
  }
  for (const auto& d : cd.ratings) {
    RatingResult rr;
    rr.def = d;
    rr.corridor = load_corridor(d.corridor);
    rr.y_unit = d.corridor.y_unit;
    rr.x_unit = d.kind == "time" ? "ms" : d.corridor.x_unit;
    scale_corridor(rr.corridor, unit_conversion_factor(d.corridor.x_unit, rr.x_unit), 1.0);
    rr.corridor.x_unit = rr.x_unit;
    if (d.kind == "time")
      rate_time(cd, r, rr);
    else
      rate_cross(cd, r, rr);
    rr.iso = iso18571_rating(rr.rated_reference, rr.rated_model);
    rr.cora = cora_rating(rr.rated_reference, rr.rated_model);
    std::size_t im = 0, ir = 0;
    for (std::size_t i = 0; i < rr.rated_model.size(); ++i) {
      if (std::abs(rr.rated_model[i]) > std::abs(rr.rated_model[im])) im = i;
      if (std::abs(rr.rated_reference[i]) > std::abs(rr.rated_reference[ir])) ir = i;
    }
    if (d.kind == "cross") {
      // peaks over the whole curves (the rated grid may stop at the reference's reach)
      im = 0;
      for (std::size_t i = 0; i < rr.model.y.size(); ++i)
        if (std::abs(rr.model.y[i]) > std::abs(rr.model.y[im])) im = i;
      rr.model_peak = rr.model.y[im];
      rr.model_peak_x = rr.model.x[im];
      ir = 0;
      for (std::size_t i = 0; i < rr.reference.y.size(); ++i)
        if (std::abs(rr.reference.y[i]) > std::abs(rr.reference.y[ir])) ir = i;
      rr.reference_peak = rr.reference.y[ir];
      rr.reference_peak_x = rr.reference.x[ir];
    } else {
      rr.model_peak = rr.rated_model[im];
      rr.model_peak_x = rr.rated_abscissa[im];
      rr.reference_peak = rr.rated_reference[ir];
      rr.reference_peak_x = rr.rated_abscissa[ir];
    }
    r.ratings.push_back(std::move(rr));
  }
  std::vector<double> t_rel(r.time_ms.size());
  for (std::size_t i = 0; i < t_rel.size(); ++i) t_rel[i] = r.time_ms[i] - r.t0_ms;
  for (const auto& c : cd.criteria) {
    if (c.kind == "failed_elements") {
      for (const auto& n : c.signals) {
        CriterionDef one = c;
        one.signal = n;
        CriterionResult out;
        out.def = one;
        const auto& s = r.signal(n);
        const auto p = signed_peak(t_rel, s.y);
        out.quantity = "failed elements: " + n;
        out.value = std::round(std::abs(p.value));
        out.unit = "-";
        out.t1_ms = out.t2_ms = p.t1;
        out.limit = c.limit;
        if (c.limit >= 0.0) out.limit_source = "case file";
        out.detail = s.source;
        r.criteria.push_back(out);
      }
      continue;
    }
    r.criteria.push_back(evaluate_criterion(cd, r, c, t_rel));
  }
  return r;
}

}  // namespace hbm::corridors
