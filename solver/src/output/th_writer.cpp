// SPDX-License-Identifier: GPL-3.0-or-later
// CSV time histories (format in th_writer.hpp).
#include "output/th_writer.hpp"

#include "output/units.hpp"

#include <cstdio>

namespace hbm::solver {

std::string th_file_name(const std::string& run_name, const ThGroup& g) {
  std::string kind = g.keyword.substr(g.keyword.rfind('/') + 1);
  return run_name + "_TH_" + kind + "_" + std::to_string(g.id) + ".csv";
}

namespace {
std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}
}  // namespace

bool ThWriter::open(const std::filesystem::path& file, const ThGroup& group, const hbm::deck::Units& u,
                    std::string& error) {
  using D = hbm::deck::Dimension;
  path_ = file;
  group_ = &group;
  out_.open(file, std::ios::trunc);
  if (!out_) {
    error = "cannot write " + file.string();
    return false;
  }
  const std::string E = unit_text(D::Energy, u), M = unit_text(D::Mass, u);
  out_ << "time [" << unit_text(D::Time, u) << "],kinetic energy [" << E << "],internal energy [" << E
       << "],hourglass energy [" << E << "],contact energy [" << E << "],external work [" << E
       << "],added mass [" << M << "],mass ratio [-],energy error [-]";
  for (const ThProbe& p : group.columns) {
    std::string h = p.object + " " + std::to_string(p.id);
    if (!p.title.empty()) h += " " + p.title;
    h += " " + p.variable + " [" + unit_text(p.unit, u) + "]";
    out_ << "," << csv_quote(h);
  }
  out_ << "\n";
  out_.flush();
  return static_cast<bool>(out_);
}

void ThWriter::write_row(double time, const GlobalEnergies& e) {
  char buf[64];
  auto put = [&](double v) {
    std::snprintf(buf, sizeof buf, "%.9e", v);
    out_ << buf;
  };
  put(time);
  for (double v : {e.kinetic + e.rotational, e.internal, e.hourglass, e.contact, e.external_work, e.added_mass,
                   e.mass_ratio(), e.energy_error()}) {
    out_ << ",";
    put(v);
  }
  for (const ThProbe& p : group_->columns) {
    out_ << ",";
    put(p.read());
  }
  out_ << "\n";
  out_.flush();
}

}  // namespace hbm::solver
