// SPDX-License-Identifier: GPL-3.0-or-later
// /INTER/TYPE7 penalty contact kernel: sort (bucket grid), per-cycle projection, normal
// penalty with damping, regularised Coulomb friction, energies.
#include "penalty_contact.hpp"

#include "segment_projection.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace hbm::solver::contact {

namespace {

V3 node_x(const NodalState& n, Index i) {
  const auto k = static_cast<std::size_t>(i);
  return {n.x.x[k], n.x.y[k], n.x.z[k]};
}
V3 node_v(const NodalState& n, Index i) {
  const auto k = static_cast<std::size_t>(i);
  return {n.v.x[k], n.v.y[k], n.v.z[k]};
}
void add_force(NodalState& n, Index i, V3 f) {
  const auto k = static_cast<std::size_t>(i);
  n.force.x[k] += f.x;
  n.force.y[k] += f.y;
  n.force.z[k] += f.z;
  n.contact_force.x[k] += f.x;
  n.contact_force.y[k] += f.y;
  n.contact_force.z[k] += f.z;
}

std::array<V3, 4> corners(const NodalState& n, const std::array<Index, 4>& s) {
  return {node_x(n, s[0]), node_x(n, s[1]), node_x(n, s[2]), node_x(n, s[3])};
}

// Istf 2..5: combination of main and secondary stiffness (Radioss TYPE7 Istf).
double combine(int istf, double km, double ks) {
  switch (istf) {
    case 2: return 0.5 * (km + ks);
    case 3: return std::max(km, ks);
    case 4: return std::min(km, ks);
    default: return (km + ks) > 0 ? km * ks / (km + ks) : 0.0;
  }
}

}  // namespace

// Shell law K(p) = kp g/(g-p) (F = K p) up to the penetration pt where its tangent
// stiffness dF/dp = kp g^2/(g-p)^2 reaches kmax, pt = g (1 - sqrt(kp/kmax)); beyond pt
// the force goes on linearly with slope kmax. Capping the tangent (not the secant K) keeps
// every increment of force within what the node's fixed step carries: with the secant
// capped, F = kp g p/(g-p) rose with a slope up to kmax^2/kp just before the cap, so a
// node of a soft contact (kp 5e-4 kN/mm against kmax 270 kN/mm) reaching the last
// micrometres before a shell's mid-surface took 131 kN in one cycle (docs/engine-design.md
// section 12.5). Radioss' law is the same below pt.
double PenaltyContact::law_tangent_limit(double g, double kp, double kmax) {
  return kmax > kp ? g * (1.0 - std::sqrt(kp / kmax)) : 0.0;
}

double PenaltyContact::law_force(double p, double g, double kp, double kmax, bool linear) {
  if (p <= 0) return 0;
  if (linear || g <= 0) return std::min(kp, kmax) * p;
  const double pt = law_tangent_limit(g, kp, kmax);
  if (p < pt) return kp * g * p / (g - p);
  const double ft = pt > 0 ? kp * g * pt / (g - pt) : 0.0;
  return ft + kmax * (p - pt);
}

double PenaltyContact::law_stiffness(double p, double g, double kp, double kmax, bool linear) {
  if (linear || g <= 0) return std::min(kp, kmax);
  const double pt = law_tangent_limit(g, kp, kmax);
  if (p < pt) return kp * g * g / ((g - std::max(p, 0.0)) * (g - std::max(p, 0.0)));
  return kmax;
}

double PenaltyContact::law_energy(double p, double g, double kp, double kmax, bool linear) {
  if (p <= 0) return 0;
  if (linear || g <= 0) return 0.5 * std::min(kp, kmax) * p * p;
  const double pt = law_tangent_limit(g, kp, kmax);
  // U(p) = kp g (-p - g ln(1 - p/g)) below pt, then the linear branch.
  auto u = [&](double q) { return kp * g * (-q - g * std::log1p(-q / g)); };
  if (p < pt) return u(p);
  const double ft = pt > 0 ? kp * g * pt / (g - pt) : 0.0;
  return u(pt) + ft * (p - pt) + 0.5 * kmax * (p - pt) * (p - pt);
}

PenaltyContact::PenaltyContact(ContactSurface main, std::vector<Index> secondary,
                               PenaltyContactParams p, const NodalState& nodes,
                               std::vector<double> node_gap, std::vector<double> node_k0)
    : surf_(std::move(main)), secondary_(std::move(secondary)), p_(p),
      node_gap_(std::move(node_gap)), node_k0_(std::move(node_k0)) {
  const std::size_t ns = secondary_.size();
  tangential_.assign(ns, V3{});
  prev_force_.assign(ns, V3{});
  prev_segment_.assign(ns, kNoIndex);
  prev_weight_.assign(ns, {0, 0, 0, 0});
  prev_damping_.assign(ns, 0.0);
  prev_friction_.assign(ns, V3{});
  prev_vrel_.assign(ns, V3{});
  prev_vn_.assign(ns, 0.0);
  prev_normal_.assign(ns, V3{});
  if (p_.inacti == 5 || p_.inacti == 6) gap_cap_.assign(ns, std::numeric_limits<double>::infinity());
  prev_pen_.assign(ns, 0.0);
  prev_energy_.assign(ns, 0.0);
  pair_friction_stored_.assign(ns, 0.0);

  // Margin: half the mean segment edge unless given.
  double edge_sum = 0;
  std::size_t n_edges = 0;
  for (const auto& s : surf_.nodes) {
    const std::array<V3, 4> c = corners(nodes, s);
    for (int k = 0; k < 4; ++k) {
      const double l = norm(c[static_cast<std::size_t>((k + 1) & 3)] - c[static_cast<std::size_t>(k)]);
      if (l > 0) edge_sum += l, ++n_edges;
    }
  }
  const double mean_edge = n_edges ? edge_sum / static_cast<double>(n_edges) : 1.0;
  margin_ = p_.margin > 0 ? p_.margin : 0.5 * mean_edge;

  // Largest gap any pair can have (box inflation).
  max_gap_ = p_.gapmin;
  if (p_.igap >= 1) {
    double tm = 0, gs = 0;
    for (double t : surf_.thickness) tm = std::max(tm, t);
    for (double g : node_gap_) gs = std::max(gs, g);
    double g = p_.gap_scale * (0.5 * tm + gs);
    if (p_.gapmax > 0) g = std::min(g, p_.gapmax);
    max_gap_ = std::max(max_gap_, g);
  }

  // Fixed-step stiffness cap: 2 f (Tsca/dt)^2, times the node's current mass (which
  // includes the mass its elements already needed) in add_forces.
  cap_per_mass_ = p_.fixed_dt > 0 ? 2.0 * p_.cap_fraction * (p_.tsca / p_.fixed_dt) * (p_.tsca / p_.fixed_dt)
                                  : std::numeric_limits<double>::infinity();

  // Exclusions: segments containing the node, and segments sharing a node with those.
  std::vector<std::vector<Index>> node_segs(nodes.n_nodes);
  for (std::size_t s = 0; s < surf_.size(); ++s)
    for (int k = 0; k < (surf_.is_triangle(s) ? 3 : 4); ++k)
      node_segs[static_cast<std::size_t>(surf_.nodes[s][static_cast<std::size_t>(k)])].push_back(static_cast<Index>(s));
  excl_start_.assign(ns + 1, 0);
  std::vector<Index> tmp;
  for (std::size_t i = 0; i < ns; ++i) {
    tmp.clear();
    for (Index s : node_segs[static_cast<std::size_t>(secondary_[i])]) {
      tmp.push_back(s);
      for (Index n : surf_.nodes[static_cast<std::size_t>(s)])
        for (Index s2 : node_segs[static_cast<std::size_t>(n)]) tmp.push_back(s2);
    }
    std::sort(tmp.begin(), tmp.end());
    tmp.erase(std::unique(tmp.begin(), tmp.end()), tmp.end());
    excl_seg_.insert(excl_seg_.end(), tmp.begin(), tmp.end());
    excl_start_[i + 1] = static_cast<std::uint32_t>(excl_seg_.size());
  }

  // Tracked nodes: secondary and main, each once.
  std::vector<std::uint8_t> mark(nodes.n_nodes, 0);
  for (Index i : secondary_) mark[static_cast<std::size_t>(i)] = 1;
  for (const auto& s : surf_.nodes)
    for (Index i : s) mark[static_cast<std::size_t>(i)] = 1;
  for (std::size_t i = 0; i < nodes.n_nodes; ++i)
    if (mark[i]) tracked_.push_back(static_cast<Index>(i));
  sort(nodes);
}

double PenaltyContact::gap_of_pair(std::size_t slot, Index seg) const {
  if (p_.igap == 0) return p_.gapmin;
  const double gs = node_gap_.empty() ? 0.0 : node_gap_[slot];
  double g = p_.gap_scale * (0.5 * surf_.thickness[static_cast<std::size_t>(seg)] + gs);
  if (p_.gapmax > 0) g = std::min(g, p_.gapmax);
  return std::max(g, p_.gapmin);
}

bool PenaltyContact::needs_sort(const NodalState& nodes) const {
  // Relative motion of a node and a segment is at most twice the largest displacement.
  const double limit2 = 0.25 * margin_ * margin_;
  for (std::size_t k = 0; k < tracked_.size(); ++k) {
    const auto i = static_cast<std::size_t>(tracked_[k]);
    const double dx = nodes.x.x[i] - sort_x_[k], dy = nodes.x.y[i] - sort_y_[k],
                 dz = nodes.x.z[i] - sort_z_[k];
    if (dx * dx + dy * dy + dz * dz > limit2) return true;
  }
  return false;
}

void PenaltyContact::sort(const NodalState& nodes) {
  ++n_sorts_;
  const double inflate = max_gap_ + margin_;
  boxes_.resize(surf_.size());
  double size_sum = 0;
  for (std::size_t s = 0; s < surf_.size(); ++s) {
    const std::array<V3, 4> c = corners(nodes, surf_.nodes[s]);
    Box b{c[0], c[0]};
    for (const V3& q : c) {
      b.lo = {std::min(b.lo.x, q.x), std::min(b.lo.y, q.y), std::min(b.lo.z, q.z)};
      b.hi = {std::max(b.hi.x, q.x), std::max(b.hi.y, q.y), std::max(b.hi.z, q.z)};
    }
    // One-sided faces also catch nodes that went past them, down to `depth` behind the
    // face: the box also holds the corners moved by -depth along the face normal.
    if (surf_.one_sided[s]) {
      const V3 nrm = normalized(segment_area_vector(c, surf_.is_triangle(s)));
      for (const V3& q0 : c) {
        const V3 q = q0 - surf_.depth[s] * nrm;
        b.lo = {std::min(b.lo.x, q.x), std::min(b.lo.y, q.y), std::min(b.lo.z, q.z)};
        b.hi = {std::max(b.hi.x, q.x), std::max(b.hi.y, q.y), std::max(b.hi.z, q.z)};
      }
    }
    b.lo -= V3{inflate, inflate, inflate};
    b.hi += V3{inflate, inflate, inflate};
    size_sum += (b.hi.x - b.lo.x + b.hi.y - b.lo.y + b.hi.z - b.lo.z) / 3.0;
    boxes_[s] = b;
  }
  grid_.build(boxes_, surf_.size() ? size_sum / static_cast<double>(surf_.size()) : 1.0);
  cand_start_.assign(secondary_.size() + 1, 0);
  cand_segment_.clear();
  std::vector<Index> found;
  for (std::size_t i = 0; i < secondary_.size(); ++i) {
    found.clear();
    grid_.for_each_containing(node_x(nodes, secondary_[i]), boxes_, [&](Index s) {
      const auto b = excl_seg_.begin() + excl_start_[i], e = excl_seg_.begin() + excl_start_[i + 1];
      if (!std::binary_search(b, e, s)) found.push_back(s);
    });
    std::sort(found.begin(), found.end());  // deterministic order
    cand_segment_.insert(cand_segment_.end(), found.begin(), found.end());
    cand_start_[i + 1] = static_cast<std::uint32_t>(cand_segment_.size());
  }
  cand_segments_used_.assign(cand_segment_.begin(), cand_segment_.end());
  std::sort(cand_segments_used_.begin(), cand_segments_used_.end());
  cand_segments_used_.erase(std::unique(cand_segments_used_.begin(), cand_segments_used_.end()),
                            cand_segments_used_.end());
  sort_x_.resize(tracked_.size());
  sort_y_.resize(tracked_.size());
  sort_z_.resize(tracked_.size());
  for (std::size_t k = 0; k < tracked_.size(); ++k) {
    const auto i = static_cast<std::size_t>(tracked_[k]);
    sort_x_[k] = nodes.x.x[i];
    sort_y_[k] = nodes.x.y[i];
    sort_z_[k] = nodes.x.z[i];
  }
}

double PenaltyContact::pair_power(const NodalState& nodes, std::size_t i, V3 f, Index seg,
                                  const std::array<double, 4>& w) const {
  if (seg == kNoIndex) return 0.0;
  V3 vc{};
  const auto& sg = surf_.nodes[static_cast<std::size_t>(seg)];
  for (std::size_t k = 0; k < 4; ++k) vc += w[k] * node_v(nodes, sg[k]);
  return dot(f, node_v(nodes, secondary_[i]) - vc);
}

void PenaltyContact::update_segment_cache(const NodalState& nodes) {
  const std::size_t ns = surf_.size();
  seg_centre_.resize(ns);
  seg_normal_.resize(ns);
  seg_warp_.resize(ns);
  seg_radius_.resize(ns);
  for (const Index si : cand_segments_used_) {
    const auto s = static_cast<std::size_t>(si);
    const std::array<V3, 4> c = corners(nodes, surf_.nodes[s]);
    const bool tri = surf_.is_triangle(s);
    const V3 ctr = tri ? (1.0 / 3.0) * (c[0] + c[1] + c[2]) : 0.25 * (c[0] + c[1] + c[2] + c[3]);
    const V3 n = normalized(segment_area_vector(c, tri));
    double w = 0, r2 = 0;
    for (const V3& q : c) {
      const V3 d = q - ctr;
      w = std::max(w, std::abs(dot(d, n)));
      r2 = std::max(r2, dot(d, d));
    }
    seg_centre_[s] = ctr;
    seg_normal_[s] = n;
    seg_warp_[s] = w * (1 + 1e-12) + 1e-300;
    seg_radius_[s] = std::sqrt(r2) * (1 + 1e-12);
  }
}

bool PenaltyContact::project_candidate(const NodalState& nodes, std::size_t i, Index seg, const V3& xs,
                                       SegmentProjection& pr, double& g, double& signed_d, V3& n) const {
  const auto su = static_cast<std::size_t>(seg);
  // Cheap rejection on the segment's mean plane and bounding sphere (conservative:
  // the warp is the largest corner distance to the mean plane).
  g = gap_of_pair(i, seg);
  {
    const V3 d0 = xs - seg_centre_[su];
    const double dn = dot(d0, seg_normal_[su]);
    const double w = seg_warp_[su];
    const double below = surf_.one_sided[su] ? surf_.depth[su] : g;
    if (dn > g + w || dn < -(below + w)) return false;
    const double r = seg_radius_[su] + g;
    if (dot(d0, d0) - dn * dn > r * r) return false;
  }
  pr = project_on_segment(xs, corners(nodes, surf_.nodes[su]), surf_.is_triangle(su));
  const V3 d = xs - pr.point;
  signed_d = pr.distance;
  n = V3{};
  if (surf_.one_sided[su]) {
    const double side = dot(d, pr.normal);
    if (side < 0) {
      // Past the face: only a node right under the face (its closest point is its
      // projection along the normal, edges and corners included), not too deep.
      if (pr.distance > surf_.depth[su] || side * side < (1.0 - 1e-9) * pr.distance * pr.distance)
        return false;
      signed_d = -pr.distance;
      n = pr.normal;
    } else {
      n = pr.distance > 1e-12 * (g + margin_) ? (1.0 / pr.distance) * d : pr.normal;
    }
  } else {
    // Two-sided shell: push away from the mid-surface on the node's side.
    if (pr.distance > 1e-12 * (g + margin_)) n = (1.0 / pr.distance) * d;
    else n = pr.normal;
  }
  return true;
}

std::pair<double, double> PenaltyContact::pair_stiffness(const NodalState& nodes, std::size_t i, Index seg) const {
  const double km = surf_.k0[static_cast<std::size_t>(seg)];
  double kp;
  if (p_.istf == 1) kp = p_.stfac;
  else if (p_.istf >= 2 && !node_k0_.empty()) kp = p_.stfac * combine(p_.istf, km, node_k0_[i]);
  else kp = p_.stfac * km;
  if (p_.stmin > 0) kp = std::max(kp, p_.stmin);
  double kmax = std::isfinite(cap_per_mass_) ? cap_per_mass_ * nodes.mass[static_cast<std::size_t>(secondary_[i])]
                                              : std::numeric_limits<double>::infinity();
  if (p_.stmax > 0) kmax = std::min(kmax, p_.stmax);
  if (!std::isfinite(kmax)) kmax = 100.0 * kp;
  return {std::min(kp, kmax), kmax};
}

double PenaltyContact::initial_gap_cap(const NodalState& nodes, std::size_t i, const V3& xs) const {
  // Inacti 5: the gap of an initially penetrated node is its distance d0 to the closest
  // segment it penetrates; Inacti 6: Gap - P0 - 5 % (Gap - P0) = 0.95 d0 (OpenRadioss).
  double near_d = std::numeric_limits<double>::infinity();
  for (std::uint32_t k = cand_start_[i]; k < cand_start_[i + 1]; ++k) {
    SegmentProjection pr;
    double g = 0, signed_d = 0;
    V3 n{};
    if (project_candidate(nodes, i, cand_segment_[k], xs, pr, g, signed_d, n) && g - signed_d > 0)
      near_d = std::min(near_d, signed_d);
  }
  return std::isfinite(near_d) ? gap_cap_factor() * near_d : std::numeric_limits<double>::infinity();
}

void PenaltyContact::add_forces(NodalState& nodes, double time, double dt) {
  resultant_ = {};
  elastic_energy_ = 0;
  critical_step_ = std::numeric_limits<double>::infinity();
  // Work of last cycle's forces over v^{n-1/2} (first half of the trapezoid).
  double power_prev = 0;
  for (std::size_t i = 0; i < secondary_.size(); ++i) {
    power_prev += pair_power(nodes, i, prev_force_[i], prev_segment_[i], prev_weight_[i]);
    // Damping force of the last cycle: its work over that step is f_d . (v^{n-1/2} +
    // v^{n+1/2})/2 dt (central difference), known only now that v^{n+1/2} is.
    if (prev_segment_[i] != kNoIndex && prev_damping_[i] != 0.0) {
      const double vn_now = pair_power(nodes, i, prev_normal_[i], prev_segment_[i], prev_weight_[i]);
      damping_dissipated_ += -prev_damping_[i] * 0.5 * (prev_vn_[i] + vn_now) * dt;
    }
    // The same for the viscous friction force (Iform 1).
    if (prev_segment_[i] != kNoIndex && (prev_friction_[i].x != 0.0 || prev_friction_[i].y != 0.0 ||
                                         prev_friction_[i].z != 0.0)) {
      const double p_now = pair_power(nodes, i, prev_friction_[i], prev_segment_[i], prev_weight_[i]);
      friction_dissipated_ += -0.5 * (dot(prev_friction_[i], prev_vrel_[i]) + p_now) * dt;
    }
    prev_friction_[i] = V3{};
  }
  double power_now = 0;
  if (time < p_.tstart || time > p_.tstop) {
    std::fill(tangential_.begin(), tangential_.end(), V3{});
    std::fill(prev_segment_.begin(), prev_segment_.end(), kNoIndex);
    std::fill(prev_energy_.begin(), prev_energy_.end(), 0.0);
    friction_dissipated_ += friction_stored_;
    friction_stored_ = 0;
    work_ += 0.5 * dt * power_prev;
    return;
  }
  if (needs_sort(nodes)) sort(nodes);
  friction_stored_ = 0;
  update_segment_cache(nodes);
  const double mu = p_.fric;

  for (std::size_t i = 0; i < secondary_.size(); ++i) {
    const Index sn = secondary_[i];
    const V3 xs = node_x(nodes, sn);
    // Closest in-contact candidate. With Inacti 5/6 the gap of every pair of the node is
    // at most gap_cap_[i]; near_d: smallest signed distance of a candidate within its full
    // gap (+inf if none), from which the cap is set at the first cycle and raised after.
    Index best_seg = kNoIndex;
    SegmentProjection best{};
    double best_abs = 0, best_pen = 0, best_gap = 0, best_full_gap = 0, best_signed = 0;
    V3 best_n{};
    double near_d = std::numeric_limits<double>::infinity();
    const bool capped = !gap_cap_.empty();
    if (capped && !gap_cap_set_) gap_cap_[i] = initial_gap_cap(nodes, i, xs);
    const double cap = capped ? gap_cap_[i] : std::numeric_limits<double>::infinity();
    for (std::uint32_t k = cand_start_[i]; k < cand_start_[i + 1]; ++k) {
      const Index seg = cand_segment_[k];
      SegmentProjection pr;
      double g = 0, signed_d = 0;
      V3 n{};
      if (!project_candidate(nodes, i, seg, xs, pr, g, signed_d, n)) continue;
      if (g - signed_d > 0) near_d = std::min(near_d, signed_d);
      const double ge = std::min(g, cap);
      const double pen = ge - signed_d;
      if (pen <= 0) continue;
      if (best_seg == kNoIndex || std::abs(signed_d) < best_abs) {
        best_seg = seg;
        best = pr;
        best_abs = std::abs(signed_d);
        best_pen = pen;
        best_gap = ge;
        best_full_gap = g;
        best_signed = signed_d;
        best_n = n;
      }
    }
    // Inacti 5/6 during the run: a node that enters a segment's gap deeper than
    // kEntryJump g (full gap) in one cycle beyond its last penetration (it came past the segment's
    // edge, or its closest segment changed to one it is deep inside) is treated as an
    // initial penetration: its gap is reduced to f d (d signed: negative for a node past a
    // solid face, as at t = 0), no force this cycle. An approaching
    // node gains v dt of penetration per cycle (0.015 mm at 10 m/s). Without this the
    // potential of the penetration found (up to ~10 J for a node near a shell's
    // mid-surface under the stiffening law) appears at once: energy made from nothing.
    // The same for a node in contact whose closest segment changes to a much stiffer one at
    // the same depth (segment stiffness follows the element under it): the new pair's
    // potential may exceed the old one's by more than an entry of kEntryJump g would make.
    // The pair's stiffness and potential (used by the check and, kept, by the force).
    double kp = 0, kmax = 0, e_pair = 0;
    bool linear = false;
    if (best_seg != kNoIndex) {
      std::tie(kp, kmax) = pair_stiffness(nodes, i, best_seg);
      linear = surf_.one_sided[static_cast<std::size_t>(best_seg)] != 0;
      e_pair = law_energy(best_pen, best_gap, kp, kmax, linear);
    }
    const bool stiffer_switch =
        capped && best_seg != kNoIndex && gap_cap_set_ && prev_segment_[i] != kNoIndex && best_seg != prev_segment_[i] &&
        e_pair - prev_energy_[i] > law_energy(std::min(kEntryJump * best_full_gap, best_gap), best_gap, kp, kmax, linear);
    if (capped && best_seg != kNoIndex && gap_cap_set_ &&
        (best_pen - prev_pen_[i] > kEntryJump * best_full_gap || stiffer_switch) && best_signed != 0.0) {
      gap_cap_[i] = gap_cap_factor() * best_signed;
      ++n_entry_caps_;
      best_seg = kNoIndex;
    }
    const double cap_now = capped ? gap_cap_[i] : cap;
    // Inacti 5/6: the reduced gap only grows, following the node as it moves away
    // (f d, f = 0.95 for Inacti 6), and is dropped once the node is clear of every
    // segment's full gap. Raised after this cycle's force and only to a value the node is
    // not inside (f d <= d), so the potential is 0 before and after: no energy jump.
    if (capped) {
      const double raised = gap_cap_factor() * near_d;
      if (!std::isfinite(near_d)) gap_cap_[i] = std::numeric_limits<double>::infinity();
      else if (raised > cap_now && raised <= near_d) gap_cap_[i] = raised;
    }
    prev_pen_[i] = best_seg == kNoIndex ? 0.0 : best_pen;
    if (best_seg == kNoIndex) {
      prev_energy_[i] = 0;
      // Released: what the tangential spring held is lost to friction.
      friction_dissipated_ += pair_friction_stored_[i];
      pair_friction_stored_[i] = 0;
      tangential_[i] = {};
      prev_segment_[i] = kNoIndex;
      continue;
    }
    const auto su = static_cast<std::size_t>(best_seg);
    const std::array<Index, 4>& sg = surf_.nodes[su];
    const int nn = surf_.is_triangle(su) ? 3 : 4;

    const double fn_el = law_force(best_pen, best_gap, kp, kmax, linear);
    elastic_energy_ += e_pair;
    prev_energy_[i] = e_pair;
    // Tangent stiffness of the law: the nodal step, damping and friction spring see it.
    const double k_now = law_stiffness(best_pen, best_gap, kp, kmax, linear);

    // Relative velocity of the node and the contact point.
    V3 vm{};
    double mm = 0;
    for (int k = 0; k < nn; ++k) {
      const double w = best.weight[static_cast<std::size_t>(k)];
      vm += w * node_v(nodes, sg[static_cast<std::size_t>(k)]);
      mm += w * nodes.mass[static_cast<std::size_t>(sg[static_cast<std::size_t>(k)])];
    }
    const double ms = nodes.mass[static_cast<std::size_t>(sn)];
    const V3 vrel = node_v(nodes, sn) - vm;
    const double vn = dot(vrel, best_n);
    const double m_red = (ms + mm) > 0 ? ms * mm / (ms + mm) : ms;
    double fd = -2.0 * p_.vis_s * std::sqrt(k_now * m_red) * vn;
    double fn = fn_el + fd;
    if (fn < 0) {  // never pull: limit the damping part
      fd = -fn_el;
      fn = 0;
    }
    prev_damping_[i] = fd;  // dissipation accounted next cycle (mid-step velocity)
    prev_vn_[i] = vn;
    prev_normal_[i] = best_n;

    V3 ft{};
    if (mu > 0 && p_.friction_form != 2) {
      // Viscous friction (Iform 1, OpenRadioss's default; i7for3.F): a tangential damper
      // of VISF times the critical coefficient sqrt(2 K m_s) of the secondary node on the
      // contact spring, capped by Coulomb's mu F_n; no history, all of its work dissipated.
      const V3 vt = vrel - vn * best_n;
      const double speed = norm(vt);
      const double mag = std::min(p_.visf * std::sqrt(2.0 * k_now * ms) * speed, mu * fn);
      if (speed > 0 && mag > 0) ft = (-mag / speed) * vt;
      prev_friction_[i] = ft;
      prev_vrel_[i] = vrel;
    } else if (mu > 0) {
      // Incremental friction (Iform 2): elastic-plastic tangential spring of stiffness k_now.
      V3 t = tangential_[i];
      t -= dot(t, best_n) * best_n;  // keep it in the current tangent plane
      const V3 vt = vrel - vn * best_n;
      t -= (k_now * dt) * vt;
      const double tn = norm(t), limit = mu * fn;
      if (tn > limit) {
        // Slip: the excess of the trial force is plastic slip (tn - limit)/k dissipated at mu*Fn.
        friction_dissipated_ += limit * (tn - limit) / k_now;
        t = tn > 0 ? (limit / tn) * t : V3{};
      }
      tangential_[i] = t;
      const double stored = dot(t, t) / (2.0 * k_now);
      friction_stored_ += stored;
      pair_friction_stored_[i] = stored;
      ft = t;
    }

    const V3 f = fn * best_n + ft;
    add_force(nodes, sn, f);
    nodes.stiffness[static_cast<std::size_t>(sn)] += k_now;
    for (int k = 0; k < nn; ++k) {
      const double w = best.weight[static_cast<std::size_t>(k)];
      const Index m = sg[static_cast<std::size_t>(k)];
      add_force(nodes, m, -w * f);
      nodes.stiffness[static_cast<std::size_t>(m)] += w * k_now;
    }
    prev_force_[i] = f;
    prev_segment_[i] = best_seg;
    prev_weight_[i] = best.weight;
    if (nn == 3) prev_weight_[i][3] = 0;
    power_now += pair_power(nodes, i, f, best_seg, prev_weight_[i]);
    resultant_.normal_force += fn * best_n;
    resultant_.tangential_force += ft;
    ++resultant_.n_active;
  }
  if (!gap_cap_.empty()) gap_cap_set_ = true;
  work_ += 0.5 * dt * (power_prev + power_now);
  // Nodal step of the nodes in contact, once all pairs added their stiffness.
  if (resultant_.n_active > 0) {
    auto node_step = [&](Index n) {
      const auto k = static_cast<std::size_t>(n);
      if (nodes.stiffness[k] > 0 && nodes.mass[k] > 0)
        critical_step_ = std::min(critical_step_, std::sqrt(2.0 * nodes.mass[k] / nodes.stiffness[k]));
    };
    for (std::size_t i = 0; i < secondary_.size(); ++i) {
      if (prev_segment_[i] == kNoIndex) continue;
      node_step(secondary_[i]);
      const auto& sg = surf_.nodes[static_cast<std::size_t>(prev_segment_[i])];
      for (std::size_t k = 0; k < 4; ++k)
        if (prev_weight_[i][k] > 0) node_step(sg[k]);
    }
  }
}

}  // namespace hbm::solver::contact
