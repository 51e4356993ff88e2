// SPDX-License-Identifier: GPL-3.0-or-later
// Markdown, HTML, JSON and CSV report of an evaluation (see report.hpp).
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "hbm/corridors/report.hpp"

namespace fs = std::filesystem;

namespace hbm::corridors {
namespace {

std::string num(double v, int digits = 4) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

std::string fixed(double v, int d) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(d);
  s << v;
  return s.str();
}

std::string json_num(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string json_str(const std::string& in) {
  std::string o = "\"";
  for (char c : in) {
    switch (c) {
      case '"': o += "\\\""; break;
      case '\\': o += "\\\\"; break;
      case '\n': o += "\\n"; break;
      case '\t': o += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          o += buf;
        } else {
          o += c;
        }
    }
  }
  return o + "\"";
}

std::string html(const std::string& in) {
  std::string o;
  for (char c : in) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else if (c == '"') o += "&quot;";
    else o += c;
  }
  return o;
}

std::string md(const std::string& in) {
  std::string o;
  for (char c : in) {
    if (c == '|') o += "\\|";
    else o += c;
  }
  return o;
}

std::string csv(const std::string& in) {
  if (in.find_first_of(",\"\n") == std::string::npos) return in;
  std::string o = "\"";
  for (char c : in) {
    if (c == '"') o += "\"\"";
    else o += c;
  }
  return o + "\"";
}

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
  if (!f) throw std::runtime_error("cannot write " + p.string());
}

std::string peak_text(const RatingResult& r, bool model) {
  const double v = model ? r.model_peak : r.reference_peak;
  const double x = model ? r.model_peak_x : r.reference_peak_x;
  return num(v) + " " + r.y_unit + " at " + num(x) + " " + r.x_unit;
}

std::string risk_text(const CriterionResult& c) {
  return c.risk >= 0.0 ? fixed(100.0 * c.risk, 1) + " % (" + c.risk_source + ")" : "";
}

std::string limit_text(const CriterionResult& c) {
  if (c.limit < 0.0) return "";
  std::string s = num(c.limit) + (c.unit == "-" ? "" : " " + c.unit);
  if (!c.limit_source.empty()) s += " (" + c.limit_source + ")";
  return s;
}

std::string window_text(const CriterionResult& c) {
  if (c.t1_ms == c.t2_ms) return num(c.t1_ms) + " ms";
  return num(c.t1_ms) + " to " + num(c.t2_ms) + " ms";
}

}  // namespace

void write_report(const EvaluationResult& r, const fs::path& dir) {
  const CaseDefinition& cd = r.definition;
  // ---------------- summary.json
  {
    std::ostringstream j;
    j << "{\n  \"tool\": \"hbm-corridors\",\n  \"case\": " << json_str(cd.name) << ",\n  \"case_file\": " << json_str(cd.path)
      << ",\n  \"title\": " << json_str(cd.title) << ",\n  \"run_dir\": " << json_str(r.run_dir)
      << ",\n  \"time_zero_ms\": " << json_num(r.t0_ms) << ",\n  \"rate_hz\": " << json_num(cd.rate_hz)
      << ",\n  \"ratings\": [";
    for (std::size_t i = 0; i < r.ratings.size(); ++i) {
      const auto& x = r.ratings[i];
      j << (i ? "," : "") << "\n    {\"name\": " << json_str(x.def.name) << ", \"title\": " << json_str(x.def.title)
        << ", \"kind\": " << json_str(x.def.kind) << ", \"corridor_file\": " << json_str(x.corridor.file)
        << ", \"x_unit\": " << json_str(x.x_unit) << ", \"y_unit\": " << json_str(x.y_unit)
        << ", \"reference\": " << json_str(x.reference_is_mean ? x.corridor.mean_name : std::string("corridor mid-line"))
        << ", \"parameterisation\": " << json_str(x.parameterisation)
        << ",\n     \"iso18571\": {\"Z\": " << json_num(x.iso.corridor) << ", \"EP\": " << json_num(x.iso.phase)
        << ", \"EM\": " << json_num(x.iso.magnitude) << ", \"ES\": " << json_num(x.iso.slope) << ", \"R\": " << json_num(x.iso.overall)
        << ", \"shift_samples\": " << x.iso.shift << ", \"grade\": " << json_str(x.iso.grade) << "}"
        << ",\n     \"cora\": {\"corridor\": " << json_num(x.cora.corridor) << ", \"phase\": " << json_num(x.cora.phase)
        << ", \"size\": " << json_num(x.cora.size) << ", \"progression\": " << json_num(x.cora.progression)
        << ", \"cross_correlation\": " << json_num(x.cora.cross_correlation) << ", \"overall\": " << json_num(x.cora.overall) << "}"
        << ",\n     \"inside_fraction\": " << json_num(x.inside_fraction)
        << ", \"model_peak\": " << json_num(x.model_peak) << ", \"model_peak_at\": " << json_num(x.model_peak_x)
        << ", \"reference_peak\": " << json_num(x.reference_peak) << ", \"reference_peak_at\": " << json_num(x.reference_peak_x);
      if (x.def.kind == "cross")
        j << ", \"model_peak_deflection\": " << json_num(x.model_peak_deflection)
          << ", \"reference_peak_deflection\": " << json_num(x.reference_peak_deflection);
      j << ", \"plots\": [" << json_str("plots/" + x.def.name + ".png") << ", " << json_str("plots/" + x.def.name + ".svg") << "]"
        << ", \"notes\": [";
      for (std::size_t k = 0; k < x.notes.size(); ++k) j << (k ? ", " : "") << json_str(x.notes[k]);
      j << "]}";
    }
    j << "\n  ],\n  \"criteria\": [";
    for (std::size_t i = 0; i < r.criteria.size(); ++i) {
      const auto& c = r.criteria[i];
      j << (i ? "," : "") << "\n    {\"name\": " << json_str(c.def.name) << ", \"kind\": " << json_str(c.def.kind)
        << ", \"quantity\": " << json_str(c.quantity) << ", \"value\": " << json_num(c.value) << ", \"unit\": " << json_str(c.unit)
        << ", \"t1_ms\": " << json_num(c.t1_ms) << ", \"t2_ms\": " << json_num(c.t2_ms)
        << ", \"limit\": " << (c.limit >= 0.0 ? json_num(c.limit) : "null") << ", \"limit_source\": " << json_str(c.limit_source)
        << ", \"risk\": " << (c.risk >= 0.0 ? json_num(c.risk) : "null") << ", \"risk_source\": " << json_str(c.risk_source)
        << ", \"detail\": " << json_str(c.detail) << "}";
    }
    j << "\n  ],\n  \"signals\": [";
    for (std::size_t i = 0; i < r.signals.size(); ++i) {
      const auto& s = r.signals[i];
      j << (i ? "," : "") << "\n    {\"name\": " << json_str(s.name) << ", \"unit\": " << json_str(s.unit)
        << ", \"source\": " << json_str(s.source) << ", \"cfc\": " << json_num(s.cfc) << "}";
    }
    j << "\n  ]\n}\n";
    write_file(dir / "summary.json", j.str());
  }
  // ---------------- summary.csv
  {
    std::ostringstream c;
    c << "rating,kind,x_unit,y_unit,model_peak,model_peak_at,reference_peak,reference_peak_at,iso_Z,iso_EP,iso_EM,iso_ES,iso_R,"
         "iso_grade,cora_corridor,cora_phase,cora_size,cora_progression,cora_overall,inside_fraction\n";
    c.precision(8);
    for (const auto& x : r.ratings)
      c << csv(x.def.name) << ',' << x.def.kind << ',' << csv(x.x_unit) << ',' << csv(x.y_unit) << ',' << x.model_peak << ','
        << x.model_peak_x << ',' << x.reference_peak << ',' << x.reference_peak_x << ',' << x.iso.corridor << ',' << x.iso.phase
        << ',' << x.iso.magnitude << ',' << x.iso.slope << ',' << x.iso.overall << ',' << x.iso.grade << ',' << x.cora.corridor
        << ',' << x.cora.phase << ',' << x.cora.size << ',' << x.cora.progression << ',' << x.cora.overall << ','
        << x.inside_fraction << '\n';
    write_file(dir / "summary.csv", c.str());
  }
  // ---------------- processed_signals.csv (time after time zero)
  {
    std::ostringstream c;
    c.precision(9);
    c << "time after t0 [ms]";
    for (const auto& s : r.signals) c << ',' << csv(s.name + " [" + s.unit + "]");
    c << '\n';
    for (std::size_t i = 0; i < r.time_ms.size(); ++i) {
      c << r.time_ms[i] - r.t0_ms;
      for (const auto& s : r.signals) c << ',' << s.y[i];
      c << '\n';
    }
    write_file(dir / "processed_signals.csv", c.str());
  }
  // ---------------- report.md
  {
    std::ostringstream m;
    m << "# " << md(cd.title) << "\n\n";
    if (!cd.description.empty()) m << md(cd.description) << "\n\n";
    m << "- case file: `" << cd.path << "`\n- run folder: `" << r.run_dir << "`\n- time zero: " << num(r.t0_ms)
      << " ms on the solver clock";
    if (cd.time_zero.method == "first_exceed")
      m << " (first time `" << cd.time_zero.signal << "` reaches " << num(cd.time_zero.threshold) << " "
        << r.signal(cd.time_zero.signal).unit << ")";
    m << "\n- processing: SAE J211 CFC filters per channel (below), resampled to " << fixed(cd.rate_hz, 0) << " Hz\n\n";
    m << "## Ratings\n\n| channel | model peak | test peak | ISO Z | ISO EP | ISO EM | ISO ES | ISO R | grade | CORA | inside corridor |\n"
         "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& x : r.ratings)
      m << "| " << md(x.def.title) << " | " << peak_text(x, true) << " | " << peak_text(x, false) << " | "
        << fixed(x.iso.corridor, 3) << " | " << fixed(x.iso.phase, 3) << " | " << fixed(x.iso.magnitude, 3) << " | "
        << fixed(x.iso.slope, 3) << " | **" << fixed(x.iso.overall, 3) << "** | " << x.iso.grade << " | "
        << fixed(x.cora.overall, 3) << " | " << fixed(100.0 * x.inside_fraction, 1) << " % |\n";
    if (!r.criteria.empty()) {
      m << "\n## Injury criteria\n\n| criterion | value | at | limit | AIS3+ risk | detail |\n|---|---|---|---|---|---|\n";
      for (const auto& c : r.criteria)
        m << "| " << md(c.quantity) << " | " << num(c.value) << " " << (c.unit == "-" ? std::string() : c.unit) << " | " << window_text(c)
          << " | " << md(limit_text(c)) << " | " << md(risk_text(c)) << " | " << md(c.detail) << " |\n";
    }
    for (const auto& x : r.ratings) {
      m << "\n## " << md(x.def.title) << "\n\n![" << md(x.def.title) << "](plots/" << x.def.name << ".png)\n\n";
      m << "- reference: " << (x.reference_is_mean ? x.corridor.mean_name : std::string("corridor mid-line (the file gives no mean)"))
        << "; rated on: " << x.parameterisation << "\n";
      if (x.def.kind == "cross")
        m << "- largest deflection: model " << num(x.model_peak_deflection) << " " << x.x_unit << ", reference "
          << num(x.reference_peak_deflection) << " " << x.x_unit << "\n";
      m << "- ISO/TS 18571: Z " << fixed(x.iso.corridor, 3) << ", EP " << fixed(x.iso.phase, 3) << " (shift " << x.iso.shift
        << " samples), EM " << fixed(x.iso.magnitude, 3) << ", ES " << fixed(x.iso.slope, 3) << ", R " << fixed(x.iso.overall, 3)
        << " (" << x.iso.grade << ")\n";
      m << "- CORA: corridor " << fixed(x.cora.corridor, 3) << ", phase " << fixed(x.cora.phase, 3) << ", size "
        << fixed(x.cora.size, 3) << ", progression " << fixed(x.cora.progression, 3) << ", total " << fixed(x.cora.overall, 3) << "\n";
      for (const auto& n : x.notes) m << "- note: " << md(n) << "\n";
      m << "- corridor file `" << x.corridor.file << "`; source:\n";
      for (const auto& s : x.corridor.source_lines) m << "  > " << md(s) << "\n";
    }
    m << "\n## Signals\n\n| signal | unit | source | CFC |\n|---|---|---|---|\n";
    for (const auto& s : r.signals)
      m << "| " << md(s.name) << " | " << s.unit << " | " << md(s.source) << " | " << (s.cfc > 0 ? num(s.cfc) : "none") << " |\n";
    write_file(dir / "report.md", m.str());
  }
  // ---------------- report.html
  {
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << html(cd.title)
      << "</title>\n<style>body{font-family:sans-serif;max-width:1250px;margin:auto;padding:1em;color:#222}"
         "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:4px 8px;text-align:left}"
         "th{background:#eef}td.num{text-align:right}.excellent{background:#c8f0c8}.good{background:#e2f5c8}"
         ".fair{background:#fff2c0}.poor{background:#f8d0d0}img{max-width:100%;border:1px solid #ccc}"
         "blockquote{color:#555;font-size:90%}</style></head><body>\n";
    h << "<h1>" << html(cd.title) << "</h1>\n";
    if (!cd.description.empty()) h << "<p>" << html(cd.description) << "</p>\n";
    h << "<ul><li>case file: <code>" << html(cd.path) << "</code></li><li>run folder: <code>" << html(r.run_dir)
      << "</code></li><li>time zero: " << num(r.t0_ms) << " ms on the solver clock</li><li>resampled to " << fixed(cd.rate_hz, 0)
      << " Hz after SAE J211 filtering</li></ul>\n";
    h << "<h2>Ratings</h2>\n<table><tr><th>channel</th><th>model peak</th><th>test peak</th><th>ISO Z</th><th>ISO EP</th>"
         "<th>ISO EM</th><th>ISO ES</th><th>ISO R</th><th>grade</th><th>CORA</th><th>inside corridor</th></tr>\n";
    for (const auto& x : r.ratings)
      h << "<tr><td><a href=\"#" << html(x.def.name) << "\">" << html(x.def.title) << "</a></td><td>" << html(peak_text(x, true))
        << "</td><td>" << html(peak_text(x, false)) << "</td><td class=\"num\">" << fixed(x.iso.corridor, 3)
        << "</td><td class=\"num\">" << fixed(x.iso.phase, 3) << "</td><td class=\"num\">" << fixed(x.iso.magnitude, 3)
        << "</td><td class=\"num\">" << fixed(x.iso.slope, 3) << "</td><td class=\"num\"><b>" << fixed(x.iso.overall, 3)
        << "</b></td><td class=\"" << x.iso.grade << "\">" << x.iso.grade << "</td><td class=\"num\">" << fixed(x.cora.overall, 3)
        << "</td><td class=\"num\">" << fixed(100.0 * x.inside_fraction, 1) << " %</td></tr>\n";
    h << "</table>\n";
    if (!r.criteria.empty()) {
      h << "<h2>Injury criteria</h2>\n<table><tr><th>criterion</th><th>value</th><th>at</th><th>limit</th><th>AIS3+ risk</th><th>detail</th></tr>\n";
      for (const auto& c : r.criteria)
        h << "<tr><td>" << html(c.quantity) << "</td><td class=\"num\">" << num(c.value) << (c.unit == "-" ? " " : " ") << (c.unit == "-" ? std::string() : html(c.unit))
          << "</td><td>" << window_text(c) << "</td><td>" << html(limit_text(c)) << "</td><td>" << html(risk_text(c)) << "</td><td>"
          << html(c.detail) << "</td></tr>\n";
      h << "</table>\n";
    }
    for (const auto& x : r.ratings) {
      h << "<h2 id=\"" << html(x.def.name) << "\">" << html(x.def.title) << "</h2>\n<p><img src=\"plots/" << html(x.def.name)
        << ".svg\" alt=\"" << html(x.def.title) << "\"></p>\n<ul><li>reference: "
        << (x.reference_is_mean ? x.corridor.mean_name : std::string("corridor mid-line (the file gives no mean)")) << "; rated on: "
        << html(x.parameterisation) << "</li>";
      if (x.def.kind == "cross")
        h << "<li>largest deflection: model " << num(x.model_peak_deflection) << " " << html(x.x_unit) << ", reference "
          << num(x.reference_peak_deflection) << " " << html(x.x_unit) << "</li>";
      h << "<li>ISO/TS 18571: Z " << fixed(x.iso.corridor, 3) << ", EP " << fixed(x.iso.phase, 3) << " (shift " << x.iso.shift
        << " samples), EM " << fixed(x.iso.magnitude, 3) << ", ES " << fixed(x.iso.slope, 3) << ", R " << fixed(x.iso.overall, 3)
        << " (" << x.iso.grade << ")</li><li>CORA: corridor " << fixed(x.cora.corridor, 3) << ", phase " << fixed(x.cora.phase, 3)
        << ", size " << fixed(x.cora.size, 3) << ", progression " << fixed(x.cora.progression, 3) << ", total "
        << fixed(x.cora.overall, 3) << "</li>";
      for (const auto& n : x.notes) h << "<li>note: " << html(n) << "</li>";
      h << "<li>corridor file <code>" << html(x.corridor.file) << "</code>; plots: <a href=\"plots/" << html(x.def.name)
        << ".png\">PNG</a>, <a href=\"plots/" << html(x.def.name) << ".svg\">SVG</a></li></ul>\n<blockquote>";
      for (const auto& s : x.corridor.source_lines) h << html(s) << "<br>\n";
      h << "</blockquote>\n";
    }
    h << "<h2>Signals</h2>\n<table><tr><th>signal</th><th>unit</th><th>source</th><th>CFC</th></tr>\n";
    for (const auto& s : r.signals)
      h << "<tr><td>" << html(s.name) << "</td><td>" << html(s.unit) << "</td><td>" << html(s.source) << "</td><td>"
        << (s.cfc > 0 ? num(s.cfc) : "none") << "</td></tr>\n";
    h << "</table>\n<p>Written by hbm-corridors; machine-readable: <a href=\"summary.json\">summary.json</a>, "
         "<a href=\"summary.csv\">summary.csv</a>, <a href=\"processed_signals.csv\">processed_signals.csv</a>.</p>\n</body></html>\n";
    write_file(dir / "report.html", h.str());
  }
}

}  // namespace hbm::corridors
