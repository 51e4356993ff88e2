// SPDX-License-Identifier: GPL-3.0-or-later
// /DT/BRICK/CST: a brick (or 4-node tetra) whose time step falls to Tmin switches to the small strain
// formulation (OpenRadioss engine keyword /DT/BRICK/CST/Iflag: "elements are switched to
// small strain formulation to maintain the constant time step Tmin"; with Iflag 1 also
// the bricks whose volume ratio V/V0 falls to VDEF_min).
//
// Small strain here is OpenRadioss' meaning: from the switch on, the element's geometry
// (the coordinates that give its shape-function gradients, volume, hourglass vectors and
// time step) stays the one it had at the switch; the nodal velocities still give the
// strain rate, the material law and its history go on as before. The element can no
// longer invert, its time step stays at the switch value, so nodal mass scaling stops
// growing on its nodes. A crushed soft-tissue brick keeps carrying load instead of
// stopping the run with a negative volume.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hbm::solver {

struct SmallStrainSwitch {
  bool enabled = false;
  double tsca = 0.9;       // Tsca: the element step compared is Tsca x critical step
  double tmin = 0.0;       // Tmin [time]
  double vdef_min = 0.0;   // VDEF_min: switch when V / V0 <= VDEF_min (0: not used)

  // True when an element with critical step dte and volume ratio v_ratio must switch.
  bool triggers(double dte, double v_ratio) const {
    return enabled && (tsca * dte < tmin || v_ratio <= vdef_min);
  }
};

// Frozen geometry of the switched elements of one solid group: flag per element and the
// n x 3 coordinates at the switch (n = 8 bricks, 4 tetras), [e * 3n + 3 * i + k] (node i,
// component k).
struct FrozenGeometry {
  std::vector<std::uint8_t> frozen;
  std::vector<double> x;

  void allocate(std::size_t n_elements, std::size_t nodes_per_element = 8) {
    frozen.assign(n_elements, 0);
    x.assign(3 * nodes_per_element * n_elements, 0.0);
  }
  bool active() const { return !frozen.empty(); }
  std::size_t count() const {
    std::size_t c = 0;
    for (std::uint8_t f : frozen) c += f;
    return c;
  }
};

}  // namespace hbm::solver
