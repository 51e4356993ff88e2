// SPDX-License-Identifier: GPL-3.0-or-later
// /RWALL/PLANE kinematic wall: joint normal impulse solve, friction and tied options,
// wall force and reaction work.
#include "rigid_wall_plane.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hbm::solver::contact {

namespace {
V3 get(const Vec3Soa& a, std::size_t i) { return {a.x[i], a.y[i], a.z[i]}; }
void put(Vec3Soa& a, std::size_t i, V3 v) { a.x[i] = v.x; a.y[i] = v.y; a.z[i] = v.z; }
}  // namespace

RigidWallPlane::RigidWallPlane(RigidWallPlaneParams p, std::vector<Index> secondary)
    : p_(std::move(p)), secondary_(std::move(secondary)) {
  p_.normal = normalized(p_.normal);
  tied_.assign(secondary_.size(), 0);
  r_.assign(secondary_.size(), 0.0);
  hit_.assign(secondary_.size(), 0);
  v_prev_.assign(secondary_.size(), V3{});
}

void RigidWallPlane::add_body(rigid::WallContactBody& body, const std::vector<std::size_t>& js) {
  if (js.empty()) return;
  bodies_.push_back({&body, body_points_.size(), js.size()});
  for (std::size_t j : js) {
    rigid::WallContactPoint p;
    p.secondary = j;
    body_points_.push_back(p);
    body_point_node_.push_back(body.secondary_nodes()[j]);
    body_point_tied_.push_back(0);
  }
}

void RigidWallPlane::gather_forces(const StepContext&, NodalState& nodes) {
  for (std::size_t k = 0; k < secondary_.size(); ++k) v_prev_[k] = get(nodes.v, static_cast<std::size_t>(secondary_[k]));
  if (p_.wall_node != kNoIndex) wall_v_prev_ = get(nodes.v, static_cast<std::size_t>(p_.wall_node));
}

void RigidWallPlane::impose_velocities(const StepContext& step, NodalState& nodes) {
  const double dt = step.dt_next;
  const double dtn = 0.5 * (step.dt_prev + step.dt_next);  // the step a^n acted over
  fn_ = {};
  ft_ = {};
  reaction_work_ += pending_work_;
  pending_work_ = 0;
  if (dt <= 0) return;
  const V3 n = p_.normal;
  const bool moving = p_.wall_node != kNoIndex;
  const auto w = static_cast<std::size_t>(moving ? p_.wall_node : 0);
  const V3 wall_x = moving ? get(nodes.x, w) : p_.point;
  const V3 wall_v0 = moving ? get(nodes.v, w) : V3{};
  const double wall_m = moving ? nodes.mass[w] : 0.0;

  // 1. Which nodes touch at t^{n+1}, and their target relative normal velocity.
  double sum_m = 0, sum_mv = 0;
  for (std::size_t k = 0; k < secondary_.size(); ++k) {
    const auto i = static_cast<std::size_t>(secondary_[k]);
    const double d = dot(get(nodes.x, i) - wall_x, n);
    const double vrn = dot(get(nodes.v, i) - wall_v0, n);
    hit_[k] = tied_[k] || d + dt * vrn < 0;
    if (!hit_[k]) continue;
    r_[k] = tied_[k] ? 0.0 : -std::max(d, 0.0) / dt;
    sum_m += nodes.mass[i];
    sum_mv += nodes.mass[i] * (dot(get(nodes.v, i), n) - r_[k]);
  }
  if (sum_m == 0) {
    impose_on_bodies(step, nodes, wall_x);
    return;
  }

  // 2. Joint normal solve (a fixed wall has infinite mass: V_n' = 0).
  const double vwn0 = dot(wall_v0, n);
  const double vwn = moving ? (wall_m * vwn0 + sum_mv) / (wall_m + sum_m) : 0.0;
  V3 wall_dv = (vwn - vwn0) * n;
  V3 impulse_n{}, impulse_t{};
  double work = 0;
  for (std::size_t k = 0; k < secondary_.size(); ++k) {
    if (!hit_[k]) continue;
    const auto i = static_cast<std::size_t>(secondary_[k]);
    const double m = nodes.mass[i];
    const V3 v_old = get(nodes.v, i);
    V3 v = v_old + ((vwn + r_[k]) - dot(v_old, n)) * n;
    const double dvn = std::abs(vwn + r_[k] - dot(v_old, n));
    // Tangential: friction (Slide 2) or stick (Slide 1) relative to the wall.
    const V3 vt_rel = (v - wall_v0) - dot(v - wall_v0, n) * n;
    const double vt = norm(vt_rel);
    double dvt = 0;
    if (p_.slide == 1) dvt = vt;
    else if (p_.slide == 2) dvt = std::min(vt, p_.fric * dvn);
    if (dvt > 0) v -= (dvt / vt) * vt_rel;
    if (p_.slide == 1) tied_[k] = 1;
    const V3 dv = v - v_old;
    put(nodes.v, i, v);
    // Wall reaction on the node for the animation: m dv / dt^n.
    if (dtn > 0) {
      nodes.contact_force.x[i] += m * dv.x / dtn;
      nodes.contact_force.y[i] += m * dv.y / dtn;
      nodes.contact_force.z[i] += m * dv.z / dtn;
    }
    impulse_n += (m * dot(dv, n)) * n;
    impulse_t += m * (dv - dot(dv, n) * n);
    // Reaction m dv/dt working on the mid-step velocity (v^{n-1/2} + v^{n+1/2})/2: with
    // the engine's half-step kinetic energy the balance is then exact (a node resting on
    // the wall, v^{n-1/2} = v^{n+1/2} = 0, takes reactions that do no work).
    work += m * dot(dv, 0.5 * (v_prev_[k] + v));
  }
  if (moving) {
    // Tangential impulses go back to the wall node (normal part solved above).
    wall_dv -= (1.0 / wall_m) * impulse_t;
    const V3 vw_old = wall_v0, vw = wall_v0 + wall_dv;
    put(nodes.v, w, vw);
    work += wall_m * dot(wall_dv, 0.5 * (wall_v_prev_ + vw));
    (void)vw_old;
  }
  reaction_work_ += work;
  // Force of the model on the wall = -(impulse given to the nodes) / dt^n.
  const double inv = dtn > 0 ? 1.0 / dtn : 0.0;
  fn_ = -inv * impulse_n;
  ft_ = -inv * impulse_t;
  impose_on_bodies(step, nodes, wall_x);
}

void RigidWallPlane::impose_on_bodies(const StepContext& step, NodalState& nodes, V3 wall_x) {
  if (bodies_.empty()) return;
  const double dt = step.dt_next;
  const double dtn = 0.5 * (step.dt_prev + step.dt_next);
  const V3 n = p_.normal;
  const Eigen::Vector3d ne(n.x, n.y, n.z);
  const double wall_level = dot(wall_x, n);
  const double fric = p_.slide == 2 ? p_.fric : p_.slide == 1 ? std::numeric_limits<double>::infinity() : 0.0;
  V3 impulse_n{}, impulse_t{};
  for (const BodyOnWall& b : bodies_) {
    bool contact = false;
    for (std::size_t k = b.first; k < b.first + b.count && !contact; ++k) {
      const Eigen::Vector3d x1 = b.body->predicted_position(nodes, body_points_[k].secondary, dt);
      contact = body_point_tied_[k] || ne.dot(x1) < wall_level;
    }
    if (!contact) continue;
    for (std::size_t k = b.first; k < b.first + b.count; ++k) {
      rigid::WallContactPoint& p = body_points_[k];
      const V3 x = get(nodes.x, static_cast<std::size_t>(body_point_node_[k]));
      const double d = dot(x, n) - wall_level;
      p.normal = ne;
      p.floor = wall_level + std::min(d, 0.0);
      const V3 target = x - std::max(d, 0.0) * n;
      p.target = {target.x, target.y, target.z};
      p.tied = body_point_tied_[k] != 0;
      p.fric = fric;
    }
    const rigid::WallContactWork w =
        b.body->resolve_wall_contacts(step, nodes, std::span(body_points_).subspan(b.first, b.count));
    reaction_work_ += w.at_n;
    pending_work_ += w.at_next;
    for (std::size_t k = b.first; k < b.first + b.count; ++k) {
      const rigid::WallContactPoint& p = body_points_[k];
      if (!p.touched) continue;
      const V3 imp{p.impulse.x(), p.impulse.y(), p.impulse.z()};
      const auto i = static_cast<std::size_t>(body_point_node_[k]);
      if (dtn > 0) {
        nodes.contact_force.x[i] += imp.x / dtn;
        nodes.contact_force.y[i] += imp.y / dtn;
        nodes.contact_force.z[i] += imp.z / dtn;
      }
      impulse_n += dot(imp, n) * n;
      impulse_t += imp - dot(imp, n) * n;
      if (p_.slide == 1) body_point_tied_[k] = 1;
    }
  }
  const double inv = dtn > 0 ? 1.0 / dtn : 0.0;
  fn_ -= inv * impulse_n;
  ft_ -= inv * impulse_t;
}

std::vector<std::string> RigidWallPlane::th_default_variables(ThKind kind) const {
  if (kind != ThKind::Rwall) return {};
  return {"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ"};
}

std::optional<ThProbe> RigidWallPlane::th_probe(ThKind kind, std::int64_t id,
                                                std::string_view var) const {
  if (kind != ThKind::Rwall || id != p_.id) return std::nullopt;
  ThProbe p;
  p.object = "rwall";
  p.id = p_.id;
  p.title = p_.title;
  p.variable = std::string(var);
  p.unit = hbm::deck::Dimension::Force;
  const RigidWallPlane* self = this;
  if (var == "FNX") p.read = [self] { return self->fn_.x; };
  else if (var == "FNY") p.read = [self] { return self->fn_.y; };
  else if (var == "FNZ") p.read = [self] { return self->fn_.z; };
  else if (var == "FTX") p.read = [self] { return self->ft_.x; };
  else if (var == "FTY") p.read = [self] { return self->ft_.y; };
  else if (var == "FTZ") p.read = [self] { return self->ft_.z; };
  else if (var == "FN") p.read = [self] { return norm(self->fn_); };
  else if (var == "FT") p.read = [self] { return norm(self->ft_); };
  else return std::nullopt;
  return p;
}

}  // namespace hbm::solver::contact
