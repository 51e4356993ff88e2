// SPDX-License-Identifier: GPL-3.0-or-later
// /INTER/TYPE2 kinematic tie: projection at build, mass lumping, force gathering,
// dependent velocities.
#include "tied_contact.hpp"

#include "bucket_grid.hpp"
#include "segment_projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hbm::solver::contact {

namespace {
V3 get(const Vec3Soa& a, Index i) {
  const auto k = static_cast<std::size_t>(i);
  return {a.x[k], a.y[k], a.z[k]};
}
}  // namespace

TiedContact::TiedContact(std::int64_t id, std::string title, const ContactSurface& main,
                         const std::vector<Index>& secondary, double dsearch,
                         const NodalState& nodes, std::vector<Index>& untied)
    : id_(id), title_(std::move(title)) {
  // Boxes of the segments inflated by the search distance (or by the mean edge when
  // dsearch is 0, then the closest segment is taken whatever its distance).
  std::vector<Box> boxes(main.size());
  double edge = 0;
  for (std::size_t s = 0; s < main.size(); ++s) {
    const V3 a = get(nodes.x, main.nodes[s][0]), b = get(nodes.x, main.nodes[s][2]);
    edge += norm(b - a);
  }
  edge = main.size() ? edge / static_cast<double>(main.size()) : 1.0;
  const double reach = dsearch > 0 ? dsearch : edge;
  for (std::size_t s = 0; s < main.size(); ++s) {
    Box b{get(nodes.x, main.nodes[s][0]), get(nodes.x, main.nodes[s][0])};
    for (Index n : main.nodes[s]) {
      const V3 q = get(nodes.x, n);
      b.lo = {std::min(b.lo.x, q.x), std::min(b.lo.y, q.y), std::min(b.lo.z, q.z)};
      b.hi = {std::max(b.hi.x, q.x), std::max(b.hi.y, q.y), std::max(b.hi.z, q.z)};
    }
    b.lo -= V3{reach, reach, reach};
    b.hi += V3{reach, reach, reach};
    boxes[s] = b;
  }
  BucketGrid grid;
  grid.build(boxes, 2 * reach + edge);
  for (Index sn : secondary) {
    const V3 p = get(nodes.x, sn);
    double best_d = std::numeric_limits<double>::infinity();
    TiedLink best;
    grid.for_each_containing(p, boxes, [&](Index s) {
      const auto su = static_cast<std::size_t>(s);
      if (std::find(main.nodes[su].begin(), main.nodes[su].end(), sn) != main.nodes[su].end())
        return;  // a node of the segment itself is not tied to it
      std::array<V3, 4> c{};
      for (std::size_t k = 0; k < 4; ++k) c[k] = get(nodes.x, main.nodes[su][k]);
      const SegmentProjection pr = project_on_segment(p, c, main.is_triangle(su));
      // Ties are made in a fixed order: smallest distance, then lowest segment index.
      if (pr.distance < best_d) {
        best_d = pr.distance;
        best.secondary = sn;
        best.main = main.nodes[su];
        best.weight = pr.weight;
        if (main.is_triangle(su)) best.weight[3] = 0;
        best.distance = pr.distance;
      }
    });
    if (best.secondary == kNoIndex || (dsearch > 0 && best_d > dsearch)) {
      untied.push_back(sn);
      continue;
    }
    links_.push_back(best);
  }
}

void TiedContact::transfer_mass(NodalState& nodes) const {
  for (const TiedLink& l : links_) {
    const auto s = static_cast<std::size_t>(l.secondary);
    for (std::size_t k = 0; k < 4; ++k) {
      if (l.weight[k] == 0) continue;
      const auto m = static_cast<std::size_t>(l.main[k]);
      nodes.mass0[m] += l.weight[k] * nodes.mass0[s];
      nodes.mass[m] = nodes.mass0[m] + nodes.added_mass[m];
    }
    nodes.is_secondary[s] = 1;
  }
}

void TiedContact::gather_forces(const StepContext&, NodalState& nodes) {
  force_ = {};
  for (const TiedLink& l : links_) {
    const auto s = static_cast<std::size_t>(l.secondary);
    const V3 f = get(nodes.force, l.secondary);
    const double k = nodes.stiffness[s];
    for (std::size_t j = 0; j < 4; ++j) {
      const double w = l.weight[j];
      if (w == 0) continue;
      const auto m = static_cast<std::size_t>(l.main[j]);
      nodes.force.x[m] += w * f.x;
      nodes.force.y[m] += w * f.y;
      nodes.force.z[m] += w * f.z;
      nodes.stiffness[m] += w * k;
    }
    force_ += f;
    nodes.force.x[s] = nodes.force.y[s] = nodes.force.z[s] = 0;
    nodes.stiffness[s] = 0;
  }
}

void TiedContact::impose_dependent(const StepContext&, NodalState& nodes) {
  for (const TiedLink& l : links_) {
    V3 v{};
    for (std::size_t j = 0; j < 4; ++j)
      if (l.weight[j] != 0) v += l.weight[j] * get(nodes.v, l.main[j]);
    const auto s = static_cast<std::size_t>(l.secondary);
    nodes.v.x[s] = v.x;
    nodes.v.y[s] = v.y;
    nodes.v.z[s] = v.z;
  }
}

std::vector<std::string> TiedContact::th_default_variables(ThKind kind) const {
  if (kind != ThKind::Inter) return {};
  return {"FX", "FY", "FZ"};
}

std::optional<ThProbe> TiedContact::th_probe(ThKind kind, std::int64_t id,
                                             std::string_view var) const {
  if (kind != ThKind::Inter || id != id_) return std::nullopt;
  ThProbe p;
  p.object = "inter";
  p.id = id_;
  p.title = title_;
  p.variable = std::string(var);
  p.unit = hbm::deck::Dimension::Force;
  const TiedContact* self = this;
  if (var == "FX") p.read = [self] { return self->force_.x; };
  else if (var == "FY") p.read = [self] { return self->force_.y; };
  else if (var == "FZ") p.read = [self] { return self->force_.z; };
  else if (var == "F") p.read = [self] { return norm(self->force_); };
  else return std::nullopt;
  return p;
}

}  // namespace hbm::solver::contact
