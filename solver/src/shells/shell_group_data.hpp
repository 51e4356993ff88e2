// SPDX-License-Identifier: GPL-3.0-or-later
// Struct-of-arrays state of one shell element group (one formulation, one material, one
// section) and the views the element kernels read and write. Independent of the engine
// core: the engine adaptor (shell_element_group.cpp) owns one ShellGroupData and hands
// the kernels views of the nodal arrays.
//
// Layout: per-element arrays indexed [e]; per-point arrays element-major
// [e * n_points + p] (the point update loops over an element's points innermost).
// (Rows of n per component were tried for the stresses and the extra resultants: no
// faster on hbm-shells-bench, so the simpler element-major layout stays.)
#pragma once

#include "solid/small_strain_switch.hpp"
#include "shells/shell_material.hpp"
#include "shells/shell_section.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace hbm::solver::shells {

enum class ShellKind : std::uint8_t { QuadBT, TriaDKT };

// Read-only nodal fields (global frame, struct of arrays).
struct ShellNodalView {
  const double *x, *y, *z;     // positions x^n
  const double *vx, *vy, *vz;  // velocities v^{n-1/2}
  const double *wx, *wy, *wz;  // angular velocities omega^{n-1/2}
};

struct ShellGroupData {
  ShellKind kind = ShellKind::QuadBT;
  int nodes_per_element = 4;
  std::size_t n = 0;
  ShellMaterial mat;
  ShellSection sec;
  // mat.plate_wave_speed(), taken once by allocate(): for LAW42 it samples the law's
  // tangent over a range of stretches, too dear for every cycle.
  double wave_speed = 0;  // [length/time]

  std::vector<std::int32_t> conn;      // n * nodes_per_element, 0-based node indices
  std::vector<std::int64_t> user_id;   // element ids
  std::vector<std::int32_t> part;      // part index (engine's numbering) per element
  std::vector<double> thick;           // current thickness [length]
  std::vector<double> thick0;          // initial thickness [length]
  std::vector<double> stress;          // n * np * 3: sxx, syy, sxy (corotational) [stress]
  std::vector<double> epsp;            // n * np equivalent plastic strain [-]
  std::vector<double> eps_rate;        // per element: filtered strain rate (rate_filter > 0) [1/time]
  std::vector<double> hist;            // n * np * mat.n_history()
  std::vector<double> extra;           // per element: quad 7 (qx qy transverse shear
                                       // resultants, 5 hourglass forces); tria 9
                                       // (deviatoric moments at 3 points)
  std::vector<std::uint8_t> n_failed;  // failed through-thickness points
  std::vector<std::uint8_t> deleted;   // 1: element deleted (no force)
  std::vector<double> eint;            // cumulative internal energy [energy]
  std::vector<double> ehg;             // cumulative hourglass energy [energy]
  std::vector<double> dt_elem;         // stable step L_c / c of the last evaluation [time]
  std::vector<double> area;            // current area [length^2]
  // /DT/SHELL/CST (quads) and /DT/SH_3N/CST (triangles): an element whose step Tsca x
  // dt_elem falls below Tmin keeps, from then on, the in-plane shape it had at the switch
  // (local coordinates of its corners and area, in its corotational frame) and that step;
  // the nodal velocities still give the rates (OpenRadioss: "switched to small strain
  // formulation to maintain the constant time step"). A shell squeezed flat cannot fold
  // through, its B matrix (~1/A) stays bounded and nodal mass scaling stops growing on its
  // nodes. frozen_shape per element, kFrozenShapeStride values: quads x[4], y[4];
  // triangles l21, x3, y3 (node 2 on the local x axis, node 3 at (x3, y3)); then at
  // kFrozenArea the area, kFrozenStep the step, kFrozenNormal the unit normal of the last
  // evaluation (3 values).
  static constexpr std::size_t kFrozenShapeStride = 13, kFrozenArea = 8, kFrozenStep = 9, kFrozenNormal = 10;
  SmallStrainSwitch small_strain;      // Tsca, Tmin (the volume criterion is for bricks)
  std::vector<std::uint8_t> frozen;    // 1: switched (empty when the switch is off)
  std::vector<double> frozen_shape;

  bool is_frozen(std::size_t e) const { return !frozen.empty() && frozen[e] != 0; }
  double* frozen_values(std::size_t e) { return &frozen_shape[e * kFrozenShapeStride]; }
  double frozen_step(std::size_t e) const { return frozen_shape[e * kFrozenShapeStride + kFrozenStep]; }
  // Lanes of switched elements (idx: element of each of the n lanes) keep the step they
  // had at the switch.
  void use_frozen_steps(double* dte, const std::int32_t* idx, std::size_t n) const {
    if (frozen.empty()) return;
    for (std::size_t l = 0; l < n; ++l)
      if (is_frozen(static_cast<std::size_t>(idx[l]))) dte[l] = frozen_step(static_cast<std::size_t>(idx[l]));
  }
  // After element e's evaluation with step dte, area A and unit normal n: switches it if
  // the criterion holds and returns where its in-plane shape goes (the caller writes it),
  // else nullptr.
  double* freeze_if_due(std::size_t e, double dte, double A, const double n[3]) {
    if (frozen.empty() || frozen[e] || !small_strain.triggers(dte, 1.0)) return nullptr;
    frozen[e] = 1;
    double* f = frozen_values(e);
    f[kFrozenArea] = A;
    f[kFrozenStep] = dte;
    for (int c = 0; c < 3; ++c) f[kFrozenNormal + c] = n[c];
    return f;
  }
  std::size_t n_frozen() const { return static_cast<std::size_t>(std::count(frozen.begin(), frozen.end(), 1)); }

  int extra_per_element() const { return kind == ShellKind::QuadBT ? 7 : 9; }
  // Stress component c (sxx, syy, sxy) at through-thickness point p of element e.
  double point_stress(std::size_t e, int p, int c) const {
    return stress[(e * static_cast<std::size_t>(sec.n_points) + static_cast<std::size_t>(p)) * 3 +
                  static_cast<std::size_t>(c)];
  }
  // Sizes every array for n elements (conn, user_id, part, thick must be filled first).
  void allocate();
  // Von Mises stress (mean over points) and maximum plastic strain of element e.
  double von_mises(std::size_t e) const;
  double max_epsp(std::size_t e) const;
};

// Where the kernels write, per slot s = e * nodes_per_element + k: the force and moment
// the element exerts ON its node k (= minus the internal force), global frame
// [force], [force*length]. Deleted elements write zeros.
struct ShellSlotOut {
  double *fx, *fy, *fz;
  double *mx, *my, *mz;
};

// Per-call totals returned by the kernels (sums over the elements of the call, in
// element order).
struct ShellKernelTotals {
  double dt_min = 1e300;          // smallest stable element step L_c / c [time]
  std::int64_t dt_element = -1;   // its element (local index)
  std::int64_t inverted = -1;     // lowest element with non-positive area, or -1
  double de_int = 0;              // internal energy increment [energy]
  double de_hg = 0;               // hourglass energy increment [energy]
  std::size_t newly_deleted = 0;  // elements deleted in this call
};

// Element forces of the listed elements (indices in increasing order): reads the nodal
// view, updates the element state with the step dt (the step the velocities act over),
// writes the slots and energies. Slots of elements not listed are not touched.
ShellKernelTotals quad_bt_forces(ShellGroupData& g, const ShellNodalView& nv,
                                 const ShellSlotOut& out, double dt,
                                 std::span<const std::int32_t> elements);
ShellKernelTotals tria_dkt_forces(ShellGroupData& g, const ShellNodalView& nv,
                                  const ShellSlotOut& out, double dt,
                                  std::span<const std::int32_t> elements);

}  // namespace hbm::solver::shells
