// SPDX-License-Identifier: GPL-3.0-or-later
// The --check command (see check_command.hpp).
#include "hbm/deck/check_command.hpp"

#include "hbm/deck/io.hpp"
#include "hbm/deck/summary.hpp"

#include <ostream>
#include <system_error>

namespace hbm::deck {

namespace {

constexpr std::string_view kStarterSuffix = "_0000.rad";

std::size_t count_errors(const ReadResult& r) {
  std::size_t n = 0;
  for (const Diagnostic& d : r.diagnostics) n += d.severity == Severity::Error ? 1 : 0;
  return n;
}

}  // namespace

int run_check(const std::filesystem::path& starter, std::ostream& out, std::ostream& err) {
  const std::string name = starter.filename().string();
  if (name.size() <= kStarterSuffix.size() ||
      name.compare(name.size() - kStarterSuffix.size(), kStarterSuffix.size(), kStarterSuffix) != 0) {
    err << "hbm-solver --check: expected a starter deck named NAME_0000.rad, got '" << starter.string() << "'\n";
    return 2;
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(starter, ec)) {
    err << "hbm-solver --check: no such file: " << starter.string() << "\n";
    return 2;
  }
  ReadResult s = read_deck(starter, Section::Starter);
  print_diagnostics(err, s);
  std::size_t errors = count_errors(s);

  const std::filesystem::path engine =
      starter.parent_path() / (name.substr(0, name.size() - kStarterSuffix.size()) + "_0001.rad");
  bool has_engine = std::filesystem::is_regular_file(engine, ec);
  ReadResult e;
  if (has_engine) {
    e = read_deck(engine, Section::Engine);
    // The engine deck runs the model of the starter deck: same run name.
    const auto runs = e.deck.cards_of("/RUN");
    if (!runs.empty() && !s.deck.run_name.empty() && runs[0]->title != s.deck.run_name) {
      e.diagnostics.push_back(Diagnostic{Severity::Error, runs[0]->loc, 6,
                                         "/RUN run name '" + runs[0]->title + "' differs from the starter's /BEGIN run name '" +
                                             s.deck.run_name + "'"});
    }
    print_diagnostics(err, e);
    errors += count_errors(e);
  }
  if (errors > 0) {
    err << "hbm-solver --check: " << errors << (errors == 1 ? " error" : " errors") << "; deck rejected\n";
    return 1;
  }
  out << "Starter deck " << starter.string() << ": OK\n";
  print_model_summary(out, s.deck);
  if (has_engine) {
    out << "Engine deck " << engine.string() << ": OK\n";
    for (const Card& c : e.deck.cards) {
      if (c.keyword() == "/RUN") out << "  final time Tstop " << c.real(0, "Tstop") << " " << s.deck.work_units.time << "\n";
      if (c.keyword() == "/DT/NODA/CST")
        out << "  nodal time step with added mass: Tsca " << c.real(0, "Tsca") << ", Tmin " << c.real(0, "Tmin") << " "
            << s.deck.work_units.time << "\n";
      if (c.keyword() == "/STOP")
        out << "  stop if energy error > " << c.real(0, "Emax") << " or added mass ratio > " << c.real(0, "DMmax")
            << " (0 = no limit)\n";
    }
  } else {
    out << "No engine deck " << engine.string() << "\n";
  }
  return 0;
}

}  // namespace hbm::deck
