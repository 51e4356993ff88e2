// SPDX-License-Identifier: GPL-3.0-or-later
// /BCS, /IMPVEL, /GRAV, /INIVEL/TRA: the constraints and loads and their builder.
#include "loads/loads.hpp"

#include "hbm/solver/build_context.hpp"

#include <algorithm>
#include <cctype>
#include <limits>

namespace hbm::solver {

namespace {

double& component(Vec3Soa& v, int d, std::size_t i) { return d == 0 ? v.x[i] : d == 1 ? v.y[i] : v.z[i]; }

std::string trimmed(std::string s) {
  const auto b = s.find_first_not_of(' ');
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(' ');
  s = s.substr(b, e - b + 1);
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

// Text of a field on fixed line k, or "" when the line is absent.
std::string fixed_text(const hbm::deck::Deck& d, const hbm::deck::Card& c, std::size_t k, std::string_view f) {
  if (k >= c.lines.size()) return {};
  return trimmed(d.text(c, c.lines[k], f));
}

}  // namespace

void FixedDofs::impose_velocities(const StepContext&, NodalState& n) {
  for (Index node : nodes) {
    const auto i = static_cast<std::size_t>(node);
    for (int d = 0; d < 3; ++d)
      if (fixed[d]) {
        component(n.v, d, i) = 0.0;
        component(n.a, d, i) = 0.0;
      }
    if (n.has_rotation[i])
      for (int d = 0; d < 3; ++d)
        if (fixed[3 + d]) component(n.omega, d, i) = 0.0;
  }
}

void ImposedVelocity::impose_velocities(const StepContext& step, NodalState& n) {
  // v^{n+1/2} = mean of Fscale f(t / Ascale) over [t^n, t^{n+1}] within [Tstart, Tstop]:
  // the imposed displacement is then exact at every step for any function.
  const double t0 = std::max(step.time, t_start);
  const double t1 = t_stop > 0.0 ? std::min(step.time + step.dt_next, t_stop) : step.time + step.dt_next;
  if (!(t1 > t0)) {
    work_ = work_done_;
    return;
  }
  const double value = fscale * ascale * function->integral(t0 / ascale, t1 / ascale) / step.dt_next;
  const double dt = 0.5 * (step.dt_prev + step.dt_next);
  double half = 0.0, full = 0.0;
  for (Index node : nodes) {
    const auto i = static_cast<std::size_t>(node);
    if (dof < 3) {
      double& v = component(n.v, dof, i);
      double& a = component(n.a, dof, i);
      const double v_old = v - dt * a;       // v^{n-1/2}
      const double impulse = n.mass[i] * (value - v);  // R^n dt^n
      half += 0.5 * impulse * v_old;
      full += impulse * 0.5 * (v_old + value);
      a = dt > 0 ? (value - v_old) / dt : 0.0;
      v = value;
    } else if (n.has_rotation[i]) {
      double& w = component(n.omega, dof - 3, i);
      const double impulse = n.inertia[i] * (value - w);
      full += impulse * 0.5 * (w + value);
      w = value;
    }
  }
  work_ = work_done_ + half;
  work_done_ += full;
}

void Gravity::add_forces(const StepContext& step, NodalState& n) {
  const double g = fscale * (*function)(step.time / ascale);
  if (f_prev_.size() != nodes.size()) f_prev_.assign(nodes.size(), 0.0);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const auto i = static_cast<std::size_t>(nodes[k]);
    // A rigid body's main node carries the whole body mass (secondaries included): its
    // secondaries take no share of their own, or the body would get gravity twice.
    if (n.is_secondary[i]) continue;
    const double f = n.mass[i] * g;
    // Work over [t^{n-1}, t^n]: 0.5 (f^{n-1} + f^n) v^{n-1/2} dt^{n-1/2}.
    work_ += 0.5 * (f_prev_[k] + f) * component(n.v, dir, i) * step.dt_prev;
    f_prev_[k] = f;
    component(n.force, dir, i) += f;
    component(n.force_ext, dir, i) += f;
  }
}

void build_loads(BuildContext& ctx) {
  const hbm::deck::Deck& d = ctx.starter();
  for (std::string_view kw : {"/BCS", "/IMPVEL", "/GRAV", "/INIVEL/TRA"}) ctx.claim(kw);
  for (const hbm::deck::Card* c : d.cards_of("/BCS")) {
    auto b = std::make_unique<FixedDofs>();
    b->id = c->id;
    const std::string tra = fixed_text(d, *c, 0, "Tra"), rot = fixed_text(d, *c, 0, "rot");
    auto flags = [&](const std::string& s, int off, std::string_view field) {
      if (s.empty()) return;
      if (s.size() > 3 || s.find_first_not_of("01") != std::string::npos) {
        ctx.error(*c, c->lines.at(0), field, "'" + s + "' must be three digits 0/1 (e.g. 111)");
        return;
      }
      const std::string p = std::string(3 - s.size(), '0') + s;  // right-aligned digits
      for (int k = 0; k < 3; ++k) b->fixed[static_cast<std::size_t>(off + k)] = p[static_cast<std::size_t>(k)] == '1';
    };
    flags(tra, 0, "Tra");
    flags(rot, 3, "rot");
    if (c->integer(0, "skew_id") != 0) ctx.error(*c, c->lines.at(0), "skew_id", "skew systems are not supported");
    if (const auto* g = ctx.require_node_group(*c, c->lines.at(0), "grnod_id")) b->nodes = *g;
    ctx.add_constraint(std::move(b));
  }
  for (const hbm::deck::Card* c : d.cards_of("/IMPVEL")) {
    auto v = std::make_unique<ImposedVelocity>();
    v->id = c->id;
    v->function = ctx.require_function(*c, c->lines.at(0), "fct_id");
    const std::string dir = fixed_text(d, *c, 0, "Dir");
    static const char* names[] = {"X", "Y", "Z", "XX", "YY", "ZZ"};
    v->dof = -1;
    for (int k = 0; k < 6; ++k)
      if (dir == names[k]) v->dof = k;
    if (v->dof < 0) ctx.error(*c, c->lines.at(0), "Dir", "'" + dir + "' must be X, Y, Z, XX, YY or ZZ");
    if (c->integer(0, "skew_id") != 0) ctx.error(*c, c->lines.at(0), "skew_id", "skew systems are not supported");
    if (c->integer(0, "sens_id") != 0) ctx.error(*c, c->lines.at(0), "sens_id", "sensors are not supported");
    v->ascale = c->real(1, "Ascale_x");
    v->fscale = c->real(1, "Fscale_y");
    v->t_start = c->real(1, "Tstart");
    v->t_stop = c->real(1, "Tstop");
    if (const auto* g = ctx.require_node_group(*c, c->lines.at(0), "grnod_id")) v->nodes = *g;
    if (v->dof >= 3)
      for (Index n : v->nodes) ctx.enable_rotation(n);
    if (v->function && v->dof >= 0) ctx.add_constraint(std::move(v));
  }
  for (const hbm::deck::Card* c : d.cards_of("/GRAV")) {
    auto g = std::make_unique<Gravity>();
    g->id = c->id;
    g->function = ctx.require_function(*c, c->lines.at(0), "fct_id");
    const std::string dir = fixed_text(d, *c, 0, "Dir");
    g->dir = dir == "X" ? 0 : dir == "Y" ? 1 : dir == "Z" ? 2 : -1;
    if (g->dir < 0) ctx.error(*c, c->lines.at(0), "Dir", "'" + dir + "' must be X, Y or Z");
    if (c->integer(0, "skew_id") != 0) ctx.error(*c, c->lines.at(0), "skew_id", "skew systems are not supported");
    g->ascale = c->real(1, "Ascale_x");
    g->fscale = c->real(1, "Fscale_y");
    if (const auto* grp = ctx.require_node_group(*c, c->lines.at(0), "grnod_id")) g->nodes = *grp;
    if (g->function && g->dir >= 0) ctx.add_interaction(std::move(g));
  }
  for (const hbm::deck::Card* c : d.cards_of("/INIVEL/TRA")) {
    if (c->integer(0, "skew_id") != 0) ctx.error(*c, c->lines.at(0), "skew_id", "skew systems are not supported");
    const auto* g = ctx.require_node_group(*c, c->lines.at(0), "grnod_id");
    if (!g) continue;
    NodalState& n = ctx.nodes();
    for (Index node : *g) {
      const auto i = static_cast<std::size_t>(node);
      n.v.x[i] = c->real(0, "Vx");
      n.v.y[i] = c->real(0, "Vy");
      n.v.z[i] = c->real(0, "Vz");
    }
  }
}

}  // namespace hbm::solver
