// SPDX-License-Identifier: GPL-3.0-or-later
// /RBODY constraint: gather, symplectic rotation update, rigid secondaries (see
// rigid_body.hpp for the scheme and its reference).
#include "rigid/rigid_body.hpp"
#include "rigid/nodal_vec3.hpp"

#include "rigid/rigid_rotation.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

namespace hbm::solver::rigid {

namespace {

// Rotation vector of a rotation matrix (log map), accurate for small angles.
Eigen::Vector3d rotation_vector(const Eigen::Matrix3d& R) {
  Eigen::Quaterniond q(R);
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const double s = q.vec().norm();
  if (s < 1e-300) return Eigen::Vector3d::Zero();
  return (2.0 * std::atan2(s, q.w()) / s) * q.vec();
}
Eigen::Matrix3d rotation_matrix(const Eigen::Vector3d& w) {
  const double a = w.norm();
  if (a < 1e-300) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(a, w / a).toRotationMatrix();
}

}  // namespace

void RigidBody::assemble(NodalState& nodes, double added_mass, const Eigen::Matrix3d& given_inertia,
                         bool include_main_in_centre, bool spherical) {
  std::vector<PointMass> points;
  points.reserve(secondary.size() + 1);
  for (Index s : secondary) {
    const auto k = static_cast<std::size_t>(s);
    points.push_back({nodes.mass0[k], load(nodes.x, s), nodes.inertia0[k]});
  }
  const auto m = static_cast<std::size_t>(main);
  double extra = added_mass;
  Eigen::Matrix3d extra_j = given_inertia;
  if (include_main_in_centre)
    points.push_back({nodes.mass0[m], load(nodes.x, main), nodes.inertia0[m]});
  else {
    extra += nodes.mass0[m];  // main node mass placed at the centre
    extra_j.diagonal().array() += nodes.inertia0[m];
  }
  MassProperties mp = compute_mass_properties(points, extra, extra_j);
  if (spherical) {
    // Ispher = 1: spherical inertia, Jxx on every axis when given, else the mean of the
    // computed principal moments.
    const double jm = given_inertia(0, 0) > 0 ? given_inertia(0, 0) : mp.principal.sum() / 3.0;
    mp.principal.setConstant(jm);
  }
  mass = mp.mass;
  principal = mp.principal;
  Q = mp.axes;
  Q_next_ = Q;
  r_body.clear();
  for (Index s : secondary) r_body.push_back(Q.transpose() * (load(nodes.x, s) - mp.centre));
  store(nodes.x0, main, mp.centre);
  store(nodes.x, main, mp.centre);
  nodes.mass0[m] = mass;
  nodes.mass[m] = mass;
  nodes.inertia0[m] = principal.minCoeff();
  nodes.inertia[m] = nodes.inertia0[m];
  nodes.has_rotation[m] = 1;
  for (Index s : secondary) nodes.is_secondary[static_cast<std::size_t>(s)] = 1;
  mass_used_ = mass;
  inv_inertia_used_ = principal.cwiseInverse();
}

void RigidBody::start_motion(NodalState& nodes) {
  // Momentum and angular momentum of the initial nodal velocities (/INIVEL) about the
  // centre: the body starts with the rigid motion that carries them.
  double m_sec = 0;
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (Index s : secondary) {
    const double ms = nodes.mass0[static_cast<std::size_t>(s)];
    m_sec += ms;
    p += ms * load(nodes.v, s);
  }
  p += std::max(0.0, mass - m_sec) * load(nodes.v, main);
  const Eigen::Vector3d vc = p / mass;
  const Eigen::Vector3d xc = load(nodes.x, main);
  Eigen::Vector3d l = Eigen::Vector3d::Zero();
  for (Index s : secondary) {
    const double ms = nodes.mass0[static_cast<std::size_t>(s)];
    l += ms * (load(nodes.x, s) - xc).cross(load(nodes.v, s) - vc);
  }
  const Eigen::Vector3d w0 = load(nodes.omega, main);
  l += Q * principal.cwiseProduct(Q.transpose() * w0);  // main node's own spin, if any
  L = l;
  store(nodes.v, main, vc);
  const Eigen::Vector3d w = angular_velocity(Q, L, principal.cwiseInverse());
  store(nodes.omega, main, w);
  // Scalar inertia seen by the core: 0.5 inertia |w|^2 = 0.5 w . J w, the body's spin
  // energy, so that E_kin at t = 0 (computed from the nodes before the first cycle)
  // includes the rotation. Also in inertia0: the build phase ends with inertia =
  // inertia0 (the body sets inertia itself every cycle; the Rayleigh quotient is at
  // least the smallest principal moment, so no step limit is relaxed).
  const auto mi = static_cast<std::size_t>(main);
  const Eigen::Vector3d wb = Q.transpose() * w;
  if (w.squaredNorm() > 0) nodes.inertia0[mi] = nodes.inertia[mi] = wb.dot(principal.cwiseProduct(wb)) / w.squaredNorm();
  velocity_ = velocity_prev_ = vc;
  omega_ = omega_prev_ = w;
  omega_written_ = w;
  L_prev_ = L;
  kinetic_prev_ = 0.5 * mass * vc.squaredNorm() + rotational_energy(Q, L, principal.cwiseInverse());
  initialised_ = true;
}

void RigidBody::gather_forces(const StepContext& step, NodalState& nodes) {
  if (!initialised_) start_motion(nodes);
  const Eigen::Vector3d xm = load(nodes.x, main);
  Eigen::Vector3d F = load(nodes.force, main);
  Eigen::Vector3d M = load(nodes.moment, main);
  const auto mi = static_cast<std::size_t>(main);
  double k = nodes.stiffness[mi], kr = nodes.rot_stiffness[mi];
  for (Index s : secondary) {
    const auto si = static_cast<std::size_t>(s);
    const Eigen::Vector3d f = load(nodes.force, s);
    const Eigen::Vector3d r = load(nodes.x, s) - xm;
    F += f;
    M += r.cross(f) + load(nodes.moment, s);
    k += nodes.stiffness[si];
    kr += nodes.stiffness[si] * r.squaredNorm() + nodes.rot_stiffness[si];
    nodes.force.x[si] = nodes.force.y[si] = nodes.force.z[si] = 0.0;
    nodes.moment.x[si] = nodes.moment.y[si] = nodes.moment.z[si] = 0.0;
    nodes.stiffness[si] = 0.0;
    nodes.rot_stiffness[si] = 0.0;
  }
  store(nodes.force, main, F);
  store(nodes.moment, main, M);
  nodes.stiffness[mi] = k;
  nodes.rot_stiffness[mi] = kr;
  force_ = F;
  moment_ = M;
}

void RigidBody::impose_velocities(const StepContext& step, NodalState& nodes) {
  const auto mi = static_cast<std::size_t>(main);
  const double dt_n = 0.5 * (step.dt_prev + step.dt_next);
  if (step.cycle > 0) {  // half-step history for the values at t^n
    L_prev_ = L;
    velocity_prev_ = velocity_;
    omega_prev_ = omega_;
    kinetic_prev_ = kinetic_energy();
  }
  L += dt_n * load(nodes.moment, main);  // kick with the torque at t^n
  // Rotational mass scaling on the smallest principal moment (the core's check on the
  // scalar inertia is then never stricter).
  const double need = rot_scaling_coef * nodes.rot_stiffness[mi];
  if (need > principal.minCoeff() + added_inertia) added_inertia = need - principal.minCoeff();
  inv_inertia_used_ = inverse_inertia();
  mass_used_ = nodes.mass[mi];
  predict_rotation(nodes, step.dt_next);
}

void RigidBody::predict_rotation(NodalState& nodes, double dt) {
  const auto mi = static_cast<std::size_t>(main);
  Q_next_ = free_rotation_step(Q, L, inv_inertia_used_, dt);  // exact free flow
  omega_written_ = rotation_vector(Q_next_ * Q.transpose()) / dt;
  store(nodes.omega, main, omega_written_);
  // Scalar inertia seen by the core: Rayleigh quotient of the tensor for this omega.
  const double w2 = omega_written_.squaredNorm();
  const Eigen::Vector3d wb = Q.transpose() * omega_written_;
  nodes.inertia[mi] = w2 > 0 ? wb.dot(inv_inertia_used_.cwiseInverse().cwiseProduct(wb)) / w2
                             : principal.minCoeff() + added_inertia;
}

void RigidBody::impose_dependent(const StepContext& step, NodalState& nodes) {
  const double dt = step.dt_next;
  const Eigen::Vector3d w = load(nodes.omega, main);
  if (w != omega_written_) {
    // A later constraint (/BCS, /IMPVEL on rotations) changed the main node's spin:
    // rotate with that spin and keep the momentum consistent with it.
    Q_next_ = rotation_matrix(dt * w) * Q;
    L = Q * inv_inertia_used_.cwiseInverse().cwiseProduct(Q.transpose() * w);
  }
  const Eigen::Vector3d vm = load(nodes.v, main);
  const Eigen::Vector3d xm_next = load(nodes.x, main) + dt * vm;
  for (std::size_t j = 0; j < secondary.size(); ++j) {
    const Index s = secondary[j];
    const Eigen::Vector3d target = xm_next + Q_next_ * r_body[j];
    store(nodes.v, s, (target - load(nodes.x, s)) / dt);
    store(nodes.omega, s, w);
  }
  Q = Q_next_;
  if (++steps_since_orthonormalize_ >= 100) {
    Q = reorthonormalize(Q);
    steps_since_orthonormalize_ = 0;
  }
  velocity_ = vm;
  omega_ = w;
}

double RigidBody::kinetic_energy() const {
  return 0.5 * mass_used_ * velocity_.squaredNorm() + rotational_energy(Q, L, inv_inertia_used_);
}

bool RigidBody::owns_th_object(ThKind kind, std::int64_t oid) const {
  return kind == ThKind::Rbody && oid == id;
}

std::vector<std::string> RigidBody::th_default_variables(ThKind kind) const {
  if (kind != ThKind::Rbody) return {};
  return {"FX", "FY", "FZ", "MX", "MY", "MZ"};
}

std::optional<ThProbe> RigidBody::th_probe(ThKind kind, std::int64_t oid,
                                           std::string_view variable) const {
  if (!owns_th_object(kind, oid)) return std::nullopt;
  using hbm::deck::Dimension;
  ThProbe p;
  p.object = "rbody";
  p.id = id;
  p.title = title;
  p.variable = std::string(variable);
  struct Vec { std::string_view prefix; Dimension dim; int which; };
  static constexpr Vec kVecs[] = {{"F", Dimension::Force, 0}, {"M", Dimension::Moment, 1},
                                  {"V", Dimension::Velocity, 2}, {"W", Dimension::Frequency, 3},
                                  {"AM", Dimension::None, 4}};
  for (const Vec& v : kVecs) {
    if (variable.size() != v.prefix.size() + 1 || variable.substr(0, v.prefix.size()) != v.prefix) continue;
    const char c = variable.back();
    if (c < 'X' || c > 'Z') continue;
    const int comp = c - 'X';
    const int which = v.which;
    p.unit = v.dim;
    p.read = [this, which, comp] {
      switch (which) {
        case 0: return force_(comp);
        case 1: return moment_(comp);
        case 2: return velocity_at_n()(comp);
        case 3: return omega_at_n()(comp);
        default: return momentum_at_n()(comp);
      }
    };
    return p;
  }
  if (variable == "KE") {
    p.unit = Dimension::Energy;
    p.read = [this] { return kinetic_energy_at_n(); };
    return p;
  }
  return std::nullopt;
}

}  // namespace hbm::solver::rigid
