// SPDX-License-Identifier: GPL-3.0-or-later
// TOML case-definition reader (see case_definition.hpp and docs/corridors.md).
#include "hbm/corridors/case_definition.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "hbm/corridors/input_error.hpp"
#include "hbm/corridors/units.hpp"

namespace hbm::corridors {
namespace {

class TableReader {
public:
  TableReader(const toml::table& t, std::string file, std::string context)
      : t_(t), file_(std::move(file)), context_(std::move(context)) {}

  long line() const { return static_cast<long>(t_.source().begin.line); }
  long line_of(const char* key) const {
    const toml::node* n = t_.get(key);
    return n ? static_cast<long>(n->source().begin.line) : line();
  }
  bool has(const char* key) const { return t_.contains(key); }

  void only(std::initializer_list<const char*> keys) const {
    for (const auto& [k, v] : t_) {
      bool ok = false;
      for (const char* a : keys)
        if (k.str() == a) ok = true;
      if (!ok) {
        std::string known;
        for (const char* a : keys) known += std::string(known.empty() ? "" : ", ") + a;
        throw InputError(file_, static_cast<long>(v.source().begin.line),
                         "unknown key '" + std::string(k.str()) + "' in " + context_ + " (known keys: " + known + ")");
      }
    }
  }

  std::string str(const char* key, const std::string& fallback, bool required = false) const {
    const toml::node* n = t_.get(key);
    if (!n) {
      if (required) throw InputError(file_, line(), context_ + ": missing required key '" + key + "'");
      return fallback;
    }
    if (!n->is_string())
      throw InputError(file_, line_of(key), context_ + ": key '" + key + "' must be a string");
    return std::string(*n->value<std::string>());
  }

  double num(const char* key, double fallback, bool required = false) const {
    const toml::node* n = t_.get(key);
    if (!n) {
      if (required) throw InputError(file_, line(), context_ + ": missing required key '" + key + "'");
      return fallback;
    }
    if (!n->is_number())
      throw InputError(file_, line_of(key), context_ + ": key '" + key + "' must be a number");
    const double v = *n->value<double>();
    if (!std::isfinite(v))
      throw InputError(file_, line_of(key), context_ + ": key '" + key + "' must be finite (not nan or inf)");
    return v;
  }

  bool boolean(const char* key, bool fallback) const {
    const toml::node* n = t_.get(key);
    if (!n) return fallback;
    if (!n->is_boolean())
      throw InputError(file_, line_of(key), context_ + ": key '" + key + "' must be true or false");
    return *n->value<bool>();
  }

  std::vector<std::string> strings(const char* key) const {
    std::vector<std::string> out;
    const toml::node* n = t_.get(key);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a) throw InputError(file_, line_of(key), context_ + ": key '" + key + "' must be an array of strings");
    for (const auto& e : *a) {
      if (!e.is_string())
        throw InputError(file_, static_cast<long>(e.source().begin.line),
                         context_ + ": key '" + key + "' must be an array of strings");
      out.emplace_back(*e.value<std::string>());
    }
    return out;
  }

  // An array of two-string arrays, e.g. tests = [["R_5_t", "R_5_f"], ["R_7_t", "R_7_f"]].
  std::vector<std::pair<std::string, std::string>> string_pairs(const char* key) const {
    std::vector<std::pair<std::string, std::string>> out;
    const toml::node* n = t_.get(key);
    if (!n) return out;
    const std::string what = context_ + ": key '" + key + "' must be an array of [\"x column\", \"y column\"] pairs";
    const toml::array* a = n->as_array();
    if (!a) throw InputError(file_, line_of(key), what);
    for (const auto& e : *a) {
      const toml::array* p = e.as_array();
      if (!p || p->size() != 2 || !(*p)[0].is_string() || !(*p)[1].is_string())
        throw InputError(file_, static_cast<long>(e.source().begin.line), what);
      out.emplace_back(*(*p)[0].value<std::string>(), *(*p)[1].value<std::string>());
    }
    return out;
  }

  const toml::table* table(const char* key) const {
    const toml::node* n = t_.get(key);
    if (!n) return nullptr;
    if (!n->is_table()) throw InputError(file_, line_of(key), context_ + ": key '" + key + "' must be a table");
    return n->as_table();
  }

  const std::string& file() const { return file_; }

private:
  const toml::table& t_;
  std::string file_, context_;
};

void check_unit(const std::string& file, long line, const std::string& unit, const std::string& what) {
  if (!unit.empty() && !is_known_unit(unit)) {
    try {
      (void)unit_dimension(unit);
    } catch (const std::exception& e) {
      throw InputError(file, line, what + ": " + e.what());
    }
  }
}

std::vector<const toml::table*> table_array(const toml::table& root, const char* key, const std::string& file) {
  std::vector<const toml::table*> out;
  const toml::node* n = root.get(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    throw InputError(file, static_cast<long>(n->source().begin.line),
                     std::string("'") + key + "' must be an array of tables: write [[" + key + "]]");
  for (const auto& e : *a) out.push_back(e.as_table());
  return out;
}

SignalDef read_signal(const TableReader& r) {
  r.only({"name", "file", "column", "sum_columns", "unit", "scale", "scaled_unit", "to_unit", "cfc", "combine", "of",
          "zero_at_time_zero"});
  SignalDef s;
  s.line = r.line();
  s.name = r.str("name", "", true);
  s.file = r.str("file", "");
  s.column = r.str("column", "");
  s.sum_columns = r.boolean("sum_columns", false);
  s.unit = r.str("unit", "");
  s.scale = r.num("scale", 1.0);
  s.scaled_unit = r.str("scaled_unit", "");
  s.to_unit = r.str("to_unit", "");
  s.cfc = r.num("cfc", 0.0);
  s.combine = r.str("combine", "");
  s.of = r.strings("of");
  s.zero_at_time_zero = r.boolean("zero_at_time_zero", false);
  check_unit(r.file(), r.line_of("unit"), s.unit, "signal '" + s.name + "' unit");
  check_unit(r.file(), r.line_of("scaled_unit"), s.scaled_unit, "signal '" + s.name + "' scaled_unit");
  check_unit(r.file(), r.line_of("to_unit"), s.to_unit, "signal '" + s.name + "' to_unit");
  if (s.cfc != 0.0 && s.cfc != 60.0 && s.cfc != 180.0 && s.cfc != 600.0 && s.cfc != 1000.0)
    throw InputError(r.file(), r.line_of("cfc"),
                     "signal '" + s.name + "': cfc = " + std::to_string(s.cfc) +
                         " is not an SAE J211 channel class (60, 180, 600, 1000; 0 = unfiltered)");
  if (s.combine.empty()) {
    if (s.column.empty())
      throw InputError(r.file(), s.line, "signal '" + s.name + "': give 'column' (a CSV column) or 'combine' and 'of'");
    if (!s.of.empty()) throw InputError(r.file(), r.line_of("of"), "signal '" + s.name + "': 'of' needs 'combine'");
  } else if (s.sum_columns) {
    throw InputError(r.file(), r.line_of("sum_columns"), "signal '" + s.name + "': sum_columns sums CSV columns; it takes no 'combine'");
  } else {
    if (s.combine != "difference" && s.combine != "sum" && s.combine != "resultant")
      throw InputError(r.file(), r.line_of("combine"),
                       "signal '" + s.name + "': combine = '" + s.combine + "' (use difference, sum or resultant)");
    if (!s.column.empty() || !s.file.empty())
      throw InputError(r.file(), r.line_of("combine"), "signal '" + s.name + "': a combined signal takes no 'column'/'file'");
    if (s.of.size() < 2 || (s.combine == "difference" && s.of.size() != 2))
      throw InputError(r.file(), r.line_of("of"),
                       "signal '" + s.name + "': 'of' must name " +
                           (s.combine == "difference" ? std::string("exactly 2 signals (a - b)") : std::string("at least 2 signals")));
    if (s.cfc != 0.0)
      throw InputError(r.file(), r.line_of("cfc"), "signal '" + s.name + "': filter the component signals, not the combination");
  }
  return s;
}

RatingDef read_rating(const TableReader& r, const std::filesystem::path& case_dir) {
  r.only({"name", "title", "kind", "signal", "x_signal", "method", "points", "x_label", "y_label", "corridor"});
  RatingDef d;
  d.line = r.line();
  d.name = r.str("name", "", true);
  d.title = r.str("title", d.name);
  d.kind = r.str("kind", "", true);
  d.y_signal = r.str("signal", "", true);
  d.x_signal = r.str("x_signal", "");
  d.method = r.str("method", "loading");
  const double points = r.num("points", 500.0);
  if (!(points >= 10.0 && points <= 20000.0) || points != std::floor(points))
    throw InputError(r.file(), r.line_of("points"), "rating '" + d.name + "': points must be a whole number in [10, 20000]");
  d.points = static_cast<std::size_t>(points);
  d.x_label = r.str("x_label", d.kind == "time" ? "Time" : "Deflection");
  d.y_label = r.str("y_label", "Force");
  if (d.kind != "time" && d.kind != "cross")
    throw InputError(r.file(), r.line_of("kind"), "rating '" + d.name + "': kind = '" + d.kind + "' (use time or cross)");
  if (d.kind == "cross" && d.x_signal.empty())
    throw InputError(r.file(), d.line, "rating '" + d.name + "': kind = cross needs x_signal");
  if (d.kind == "time" && !d.x_signal.empty())
    throw InputError(r.file(), r.line_of("x_signal"), "rating '" + d.name + "': x_signal is only for kind = cross");
  if (d.method != "loading" && d.method != "arc_length")
    throw InputError(r.file(), r.line_of("method"), "rating '" + d.name + "': method = '" + d.method + "' (use loading or arc_length)");
  if (d.points < 10 || d.points > 20000)
    throw InputError(r.file(), r.line_of("points"), "rating '" + d.name + "': points must be in [10, 20000]");
  if (d.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.") != std::string::npos)
    throw InputError(r.file(), r.line_of("name"), "rating name '" + d.name + "' may hold only letters, digits, '_', '-', '.' (it names the plot files)");
  const toml::table* ct = r.table("corridor");
  if (!ct) throw InputError(r.file(), d.line, "rating '" + d.name + "': missing [rating.corridor] table");
  TableReader c(*ct, r.file(), "corridor of rating '" + d.name + "'");
  c.only({"file", "curve_column", "x_column", "y_column", "upper", "lower", "mean", "tests_file", "tests", "x_unit",
          "y_unit", "where"});
  CorridorSpec& s = d.corridor;
  s.case_file = r.file();
  s.case_line = c.line_of("file");
  const std::string rel = c.str("file", "", true);
  s.file = case_dir / rel;
  if (!std::filesystem::exists(s.file))
    throw InputError(r.file(), c.line_of("file"), "corridor file '" + rel + "' not found (looked for " + s.file.string() + ")");
  s.curve_column = c.str("curve_column", "curve");
  s.x_column = c.str("x_column", "", true);
  s.y_column = c.str("y_column", "", true);
  s.upper_label = c.str("upper", "upper");
  s.lower_label = c.str("lower", "lower");
  s.mean_label = c.str("mean", "");
  // Reference = the average of individual tests (test_curves.hpp; docs/corridors.md, Ratings).
  if (c.has("tests_file") || c.has("tests")) {
    if (!c.has("tests_file") || !c.has("tests"))
      throw InputError(r.file(), c.line_of(c.has("tests") ? "tests" : "tests_file"),
                       "rating '" + d.name + "': 'tests_file' and 'tests' go together");
    if (!s.mean_label.empty())
      throw InputError(r.file(), c.line_of("tests_file"),
                       "rating '" + d.name + "': give either 'mean' (a mean curve in the corridor file) or 'tests' (its average is the reference), not both");
    const std::string trel = c.str("tests_file", "", true);
    s.tests.file = case_dir / trel;
    if (!std::filesystem::exists(s.tests.file))
      throw InputError(r.file(), c.line_of("tests_file"), "test curves file '" + trel + "' not found (looked for " + s.tests.file.string() + ")");
    s.tests.curves = c.string_pairs("tests");
    if (s.tests.curves.empty())
      throw InputError(r.file(), c.line_of("tests"), "rating '" + d.name + "': 'tests' lists no test");
    s.tests.case_file = r.file();
    s.tests.case_line = c.line_of("tests");
  }
  s.x_unit = c.str("x_unit", "", true);
  s.y_unit = c.str("y_unit", "", true);
  check_unit(r.file(), c.line_of("x_unit"), s.x_unit, "corridor x_unit");
  check_unit(r.file(), c.line_of("y_unit"), s.y_unit, "corridor y_unit");
  if (d.kind == "time" && unit_dimension(s.x_unit) != "time")
    throw InputError(r.file(), c.line_of("x_unit"), "rating '" + d.name + "': a time corridor needs a time x_unit, not '" + s.x_unit + "'");
  if (const toml::table* w = c.table("where")) {
    for (const auto& [k, v] : *w) {
      if (!v.is_string())
        throw InputError(r.file(), static_cast<long>(v.source().begin.line),
                         "corridor 'where' values must be strings (they are compared as text)");
      s.where[std::string(k.str())] = std::string(*v.value<std::string>());
    }
  }
  return d;
}

CriterionDef read_criterion(const TableReader& r) {
  r.only({"kind", "name", "signal", "signals", "fz", "my", "fx", "window_ms", "age", "scale_factor", "d0_mm", "e_m", "limit", "unit"});
  CriterionDef c;
  c.line = r.line();
  c.kind = r.str("kind", "", true);
  static const std::set<std::string> kinds{"peak", "hic", "a3ms", "chest_deflection", "vc", "nij", "belt_force", "failed_elements"};
  if (!kinds.count(c.kind))
    throw InputError(r.file(), r.line_of("kind"),
                     "criterion kind '" + c.kind + "' (use peak, hic, a3ms, chest_deflection, vc, nij, belt_force, failed_elements)");
  c.name = r.str("name", c.kind);
  c.signal = r.str("signal", "");
  c.signals = r.strings("signals");
  c.fz = r.str("fz", "");
  c.my = r.str("my", "");
  c.fx = r.str("fx", "");
  c.window_ms = r.num("window_ms", 15.0);
  c.age_years = r.num("age", 45.0);
  c.scale_factor = r.num("scale_factor", 1.3);
  c.d0_mm = r.num("d0_mm", 229.0);
  c.e_m = r.num("e_m", 0.01778);
  c.limit = r.num("limit", -1.0);
  c.unit = r.str("unit", "");
  check_unit(r.file(), r.line_of("unit"), c.unit, "criterion unit");
  if (c.kind == "nij") {
    if (c.fz.empty() || c.my.empty())
      throw InputError(r.file(), c.line, "criterion nij needs fz and my signals (fx optional)");
  } else if (c.kind == "failed_elements") {
    if (c.signals.empty()) throw InputError(r.file(), c.line, "criterion failed_elements needs 'signals' (an array)");
  } else if (c.signal.empty()) {
    throw InputError(r.file(), c.line, "criterion " + c.kind + " needs 'signal'");
  }
  if (c.kind == "hic" && !(c.window_ms > 0.0 && c.window_ms <= 100.0))
    throw InputError(r.file(), r.line_of("window_ms"), "hic window_ms must be in (0, 100]");
  if (c.kind == "vc" && !(c.d0_mm > 0.0)) throw InputError(r.file(), r.line_of("d0_mm"), "vc d0_mm must be > 0");
  return c;
}

}  // namespace

const SignalDef* CaseDefinition::find_signal(const std::string& n) const {
  for (const auto& s : signals)
    if (s.name == n) return &s;
  return nullptr;
}

CaseDefinition load_case(const std::filesystem::path& path) {
  CaseDefinition cd;
  cd.path = path.string();
  if (!std::filesystem::exists(path)) throw InputError(cd.path, 0, "case file not found");
  toml::table root;
  try {
    root = toml::parse_file(path.string());
  } catch (const toml::parse_error& e) {
    throw InputError(cd.path, static_cast<long>(e.source().begin.line), std::string(e.description()));
  }
  const std::filesystem::path dir = path.parent_path();
  TableReader top(root, cd.path, "case file");
  top.only({"case", "processing", "time_zero", "signal", "rating", "criterion"});
  if (const toml::table* t = top.table("case")) {
    TableReader r(*t, cd.path, "[case]");
    r.only({"name", "title", "description"});
    cd.name = r.str("name", "", true);
    cd.title = r.str("title", cd.name);
    cd.description = r.str("description", "");
  } else {
    throw InputError(cd.path, 1, "missing [case] table (name, title, description)");
  }
  if (const toml::table* t = top.table("processing")) {
    TableReader r(*t, cd.path, "[processing]");
    r.only({"rate_hz", "time_unit"});
    cd.rate_hz = r.num("rate_hz", 10000.0);
    cd.time_unit = r.str("time_unit", "ms");
    // upper bound keeps the ratings' dynamic time warping (N x 0.2 N) within memory
    if (!(cd.rate_hz >= 100.0 && cd.rate_hz <= 1e5))
      throw InputError(cd.path, r.line_of("rate_hz"), "[processing] rate_hz must be in [100, 100000] Hz (ISO/TS 18571 uses 10000)");
    check_unit(cd.path, r.line_of("time_unit"), cd.time_unit, "[processing] time_unit");
    if (unit_dimension(cd.time_unit) != "time")
      throw InputError(cd.path, r.line_of("time_unit"), "[processing] time_unit '" + cd.time_unit + "' is not a time unit");
  }
  for (const toml::table* t : table_array(root, "signal", cd.path)) {
    SignalDef s = read_signal(TableReader(*t, cd.path, "[[signal]]"));
    if (cd.find_signal(s.name))
      throw InputError(cd.path, s.line, "signal name '" + s.name + "' is defined twice");
    cd.signals.push_back(std::move(s));
  }
  if (cd.signals.empty()) throw InputError(cd.path, 1, "no [[signal]] defined");
  auto require_signal = [&](const std::string& n, long line, const std::string& who) {
    if (!cd.find_signal(n)) {
      std::string names;
      for (const auto& s : cd.signals) names += " " + s.name;
      throw InputError(cd.path, line, who + " refers to undefined signal '" + n + "' (defined:" + names + ")");
    }
  };
  // combinations may only use signals defined before them (no cycles)
  for (std::size_t i = 0; i < cd.signals.size(); ++i)
    for (const auto& o : cd.signals[i].of) {
      bool earlier = false;
      for (std::size_t j = 0; j < i; ++j) earlier |= cd.signals[j].name == o;
      if (!earlier)
        throw InputError(cd.path, cd.signals[i].line,
                         "signal '" + cd.signals[i].name + "' combines '" + o + "', which is not a signal defined above it");
    }
  if (const toml::table* t = top.table("time_zero")) {
    TableReader r(*t, cd.path, "[time_zero]");
    r.only({"method", "time_ms", "signal", "threshold", "use_filtered"});
    cd.time_zero.line = r.line();
    cd.time_zero.method = r.str("method", "given");
    if (cd.time_zero.method == "given") {
      cd.time_zero.time_ms = r.num("time_ms", 0.0);
    } else if (cd.time_zero.method == "first_exceed") {
      cd.time_zero.signal = r.str("signal", "", true);
      cd.time_zero.threshold = r.num("threshold", 0.0, true);
      cd.time_zero.use_filtered = r.boolean("use_filtered", false);
      require_signal(cd.time_zero.signal, r.line_of("signal"), "[time_zero]");
    } else {
      throw InputError(cd.path, r.line_of("method"), "[time_zero] method = '" + cd.time_zero.method + "' (use given or first_exceed)");
    }
  }
  for (const toml::table* t : table_array(root, "rating", cd.path)) {
    RatingDef d = read_rating(TableReader(*t, cd.path, "[[rating]]"), dir);
    require_signal(d.y_signal, d.line, "rating '" + d.name + "'");
    if (!d.x_signal.empty()) require_signal(d.x_signal, d.line, "rating '" + d.name + "'");
    for (const auto& o : cd.ratings)
      if (o.name == d.name) throw InputError(cd.path, d.line, "rating name '" + d.name + "' is used twice");
    cd.ratings.push_back(std::move(d));
  }
  for (const toml::table* t : table_array(root, "criterion", cd.path)) {
    CriterionDef c = read_criterion(TableReader(*t, cd.path, "[[criterion]]"));
    for (const std::string* n : {&c.signal, &c.fz, &c.my, &c.fx})
      if (!n->empty()) require_signal(*n, c.line, "criterion '" + c.name + "'");
    for (const auto& n : c.signals) require_signal(n, c.line, "criterion '" + c.name + "'");
    cd.criteria.push_back(std::move(c));
  }
  if (cd.ratings.empty() && cd.criteria.empty())
    throw InputError(cd.path, 1, "the case defines neither [[rating]] nor [[criterion]]: nothing to do");
  return cd;
}

}  // namespace hbm::corridors
