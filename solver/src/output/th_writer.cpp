// SPDX-License-Identifier: GPL-3.0-or-later
// CSV time histories (format in th_writer.hpp).
#include "output/th_writer.hpp"

#include "output/units.hpp"

#include <charconv>

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
  // One row built in a buffer and written at once. std::to_chars with scientific format and
  // precision 9 writes what printf's "%.9e" writes (C locale), a few times faster: a
  // /TH/PART row of every part holds some 300 values and is written every few cycles.
  row_.clear();
  auto put = [&](double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific, 9);
    row_.append(buf, r.ptr);
  };
  put(time);
  for (double v : {e.kinetic + e.rotational, e.internal, e.hourglass, e.contact, e.external_work, e.added_mass,
                   e.mass_ratio(), e.energy_error()}) {
    row_ += ',';
    put(v);
  }
  for (const ThProbe& p : group_->columns) {
    row_ += ',';
    put(p.read());
  }
  row_ += '\n';
  out_.write(row_.data(), static_cast<std::streamsize>(row_.size()));
  out_.flush();
}

}  // namespace hbm::solver
