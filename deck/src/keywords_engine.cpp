// SPDX-License-Identifier: GPL-3.0-or-later
// Keyword tables of the engine deck (NAME_0001.rad). Engine cards are read in free
// format: the values of a line are separated by blanks and taken in field order.
#include "field_builders.hpp"

namespace hbm::deck::tables {

namespace {

// Engine cards have no title line.
KeywordSpec card(std::string_view kw, IdKind id, std::string_view meaning) {
  return keyword(kw, Section::Engine, id, false, meaning);
}

// The "Tsca Tmin" line shared by the /DT/.../CST time step controls.
LineSpec tsca_tmin_line() {
  return line("line 1", {
      real_field("Tsca", 0, Dimension::None, {0, 1, true, false}, 0.9, "time step scale factor"),
      real_field("Tmin", 20, Dimension::Time, kNonNegative, 0, "minimum time step"),
  });
}

}  // namespace

void add_engine(std::vector<KeywordSpec>& out) {
  {
    KeywordSpec k = card("/RUN", IdKind::Object,
                         "/RUN/name/restart: run name (as /BEGIN) and final time. The name is Card::title.");
    k.lines.push_back(line("line 1", {real_field("Tstop", 0, Dimension::Time, kPositive, 0, "final time")}));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = card("/TFILE", IdKind::Optional, "/TFILE/format: time-history output interval.");
    k.lines.push_back(line("line 1", {real_field("dt_his", 0, Dimension::Time, kPositive, 0, "interval")}));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = card("/ANIM/DT", IdKind::None, "Animation frames: first frame time and interval.");
    k.lines.push_back(line("line 1", {
        real_field("Tstart", 0, Dimension::Time, kNonNegative, 0, "first frame time"),
        real_field("Tfreq", 20, Dimension::Time, kPositive, 0, "frame interval"),
    }));
    out.push_back(std::move(k));
  }
  struct Anim { std::string_view kw, meaning; };
  static constexpr Anim anims[] = {
      {"/ANIM/VECT/DISP", "Animation: displacement vectors."},
      {"/ANIM/VECT/VEL", "Animation: velocity vectors."},
      {"/ANIM/VECT/ACC", "Animation: acceleration vectors."},
      {"/ANIM/VECT/CONT", "Animation: contact force vectors."},
      {"/ANIM/VECT/FINT", "Animation: internal force vectors."},
      {"/ANIM/VECT/FEXT", "Animation: external force vectors."},
      {"/ANIM/ELEM/VONM", "Animation: von Mises stress per element."},
      {"/ANIM/ELEM/EPSP", "Animation: plastic strain per element."},
      {"/ANIM/ELEM/ENER", "Animation: specific internal energy per element."},
      {"/ANIM/ELEM/HOURG", "Animation: hourglass energy per element."},
      {"/ANIM/ELEM/DENS", "Animation: density per element."},
      {"/ANIM/ELEM/THIC", "Animation: shell thickness per element."},
      {"/ANIM/NODA/DMAS", "Animation: added mass per node (mass scaling)."},
  };
  for (const Anim& a : anims) out.push_back(card(a.kw, IdKind::None, a.meaning));
  {
    KeywordSpec k = card("/DT/NODA/CST", IdKind::Optional,
                         "Nodal time step with added mass: dt_n = Tsca sqrt(2m/k) kept >= Tmin.");
    k.lines.push_back(tsca_tmin_line());
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = card("/DT/BRICK/CST", IdKind::Optional,
                         "/DT/BRICK/CST/Iflag: a brick whose time step Tsca dt_crit falls below Tmin (Iflag 1: or whose "
                         "volume ratio V/V0 falls to VDEF_min) switches to the small strain formulation (geometry kept "
                         "from the switch on).");
    k.lines.push_back(tsca_tmin_line());
    k.lines.push_back(line("line 2", {
        real_field("ASP_min", 0, Dimension::None, kNonNegative, 0, "minimum aspect ratio (tetra collapse; 0 = none)"),
        real_field("VDEF_min", 20, Dimension::None, {0, 1, false, true}, 0, "minimum volume ratio V/V0 (0 = none)"),
    }, true));
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = card("/DT/SHELL/CST", IdKind::Optional,
                         "A 4-node shell whose time step Tsca dt_crit falls below Tmin switches to the small strain "
                         "formulation (in-plane shape and step kept from the switch on). Eltyp SHELL: 4-node shells only "
                         "(3-node shells: /DT/SH_3N/CST).");
    k.lines.push_back(tsca_tmin_line());
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = card("/DT/SH_3N/CST", IdKind::Optional,
                         "A 3-node shell whose time step Tsca dt_crit falls below Tmin switches to the small strain "
                         "formulation (in-plane shape and step kept from the switch on).");
    k.lines.push_back(tsca_tmin_line());
    out.push_back(std::move(k));
  }
  {
    KeywordSpec k = card("/STOP", IdKind::None, "Stop criteria on energy error and added mass.");
    k.lines.push_back(line("line 1", {
        real_field("Emax", 0, Dimension::None, kNonNegative, 0, "maximum energy error ratio (0 = none)"),
        real_field("DMmax", 20, Dimension::None, kNonNegative, 0, "maximum added mass ratio (M-M0)/M0 (0 = none)"),
        real_field("DNmax", 40, Dimension::None, kNonNegative, 0, "maximum nodal mass ratio (0 = none)"),
        int_field("NTH", 60, 0, 1, 0, "write time history at stop"),
        int_field("NANIM", 70, 0, 1, 0, "write animation at stop"),
    }, true));
    out.push_back(std::move(k));
  }
  out.push_back(card("/PRINT", IdKind::Optional,
                     "/PRINT/-N: listing line every N cycles (negative: also to standard output)."));
}

}  // namespace hbm::deck::tables
