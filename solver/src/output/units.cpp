// SPDX-License-Identifier: GPL-3.0-or-later
// Unit names: derived units composed from mass, length and time; named for the
// consistent systems used in crash (kg-mm-ms: kN, GPa, J; t-mm-s: N, MPa, mJ;
// kg-m-s: N, Pa, J).
#include "output/units.hpp"

namespace hbm::solver {

namespace {

struct Named {
  const char *force, *stress, *energy;
};

bool named(const hbm::deck::Units& u, Named& n) {
  if (u.mass == "kg" && u.length == "mm" && u.time == "ms") n = {"kN", "GPa", "J"};
  else if (u.mass == "Mg" && u.length == "mm" && u.time == "s") n = {"N", "MPa", "mJ"};
  else if (u.mass == "t" && u.length == "mm" && u.time == "s") n = {"N", "MPa", "mJ"};
  else if (u.mass == "kg" && u.length == "m" && u.time == "s") n = {"N", "Pa", "J"};
  else if (u.mass == "g" && u.length == "mm" && u.time == "ms") n = {"N", "MPa", "mJ"};
  else return false;
  return true;
}

}  // namespace

std::string unit_text(hbm::deck::Dimension d, const hbm::deck::Units& u) {
  using D = hbm::deck::Dimension;
  Named n{};
  const bool has = named(u, n);
  const std::string M = u.mass, L = u.length, T = u.time;
  const std::string F = has ? n.force : M + "*" + L + "/" + T + "^2";
  const std::string S = has ? n.stress : F + "/" + L + "^2";
  const std::string E = has ? n.energy : F + "*" + L;
  switch (d) {
    case D::None: case D::Id: case D::Count: case D::Flag: return "-";
    case D::Length: return L;
    case D::Area: return L + "^2";
    case D::Time: return T;
    case D::Mass: return M;
    case D::Density: return M + "/" + L + "^3";
    case D::Velocity: return L + "/" + T;
    case D::Acceleration: return L + "/" + T + "^2";
    case D::Force: return F;
    case D::Moment: return F + "*" + L;
    case D::Stress: return S;
    case D::Stiffness: return F + "/" + L;
    case D::RotStiffness: return F + "*" + L + "/rad";
    case D::Damping: return F + "*" + T + "/" + L;
    case D::RotDamping: return F + "*" + L + "*" + T + "/rad";
    case D::Energy: return E;
    case D::Inertia: return M + "*" + L + "^2";
    case D::Momentum: return F + "*" + T;
    case D::Angle: return "rad";
    case D::Frequency: return "1/" + T;
    case D::Strain: return "-";
    case D::StrainRate: return "1/" + T;
    case D::Temperature: return "K";
  }
  return "-";
}

}  // namespace hbm::solver
