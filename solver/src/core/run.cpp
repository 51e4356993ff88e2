// SPDX-License-Identifier: GPL-3.0-or-later
// Run loop: the cycle phases in docs/cycle.md order, outputs at t^n between the velocity
// and position updates, stop criteria (end time, inverted element, DMmax, Emax),
// listing with ETA, final per-part mass report and per-phase timing table.
#include "hbm/solver/run.hpp"

#include "core/thread_chooser.hpp"
#include "output/th_writer.hpp"
#include "output/units.hpp"
#include "output/vtk_writer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <limits>
#include <memory>
#include <ostream>
#include <sstream>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace hbm::solver {

namespace {

using Clock = std::chrono::steady_clock;

class Listing {
 public:
  Listing(const std::filesystem::path& file, std::ostream* console) : console_(console) { file_.open(file); }
  bool ok() const { return static_cast<bool>(file_); }
  void line(const std::string& s, bool to_console = true) {
    file_ << s << "\n";
    file_.flush();
    if (console_ && to_console) (*console_) << s << "\n" << std::flush;
  }

 private:
  std::ofstream file_;
  std::ostream* console_;
};

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::string where_mass_went(const Model& m, const CycleState& c, const hbm::deck::Units& u) {
  std::vector<std::size_t> parts(m.parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) parts[i] = i;
  std::sort(parts.begin(), parts.end(), [&](auto a, auto b) { return m.parts[a].added_mass > m.parts[b].added_mass; });
  std::ostringstream s;
  const std::string mu = unit_text(hbm::deck::Dimension::Mass, u);
  int shown = 0;
  for (std::size_t pi : parts) {
    const Part& p = m.parts[pi];
    if (!(p.added_mass > 0) || shown++ >= 5) break;
    s << "\n  part " << p.id << " '" << p.title << "': added " << fmt("%.4e", p.added_mass) << " " << mu
      << " (" << fmt("%.3f", 100.0 * p.added_mass / std::max(p.mass0, 1e-300)) << " % of its mass); elements:";
    std::vector<std::pair<double, std::int64_t>> el;
    for (std::size_t g = 0; g < m.groups.size() && g < c.element_added_mass.size(); ++g) {
      if (static_cast<std::size_t>(m.groups[g]->part) != pi) continue;
      const auto& log = c.element_added_mass[g];
      for (std::size_t e = 0; e < log.size(); ++e)
        if (log[e] > 0) el.emplace_back(log[e], m.groups[g]->element_id[e]);
    }
    std::sort(el.begin(), el.end(), [](auto& a, auto& b) { return a.first > b.first; });
    for (std::size_t k = 0; k < el.size() && k < 5; ++k) s << " " << el[k].second << " (" << fmt("%.3e", el[k].first) << ")";
    if (el.size() > 5) s << " ... " << el.size() << " elements";
  }
  return s.str();
}

}  // namespace

RunResult run_model(Model& model, const RunOptions& opt) {
  RunResult res;
#ifdef _OPENMP
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  // Without a thread count the run measures 1 thread against all and keeps the faster.
  ThreadChooser chooser(opt.threads > 0 ? 1 : omp_get_max_threads());
  const int fixed_threads = opt.threads > 0 ? opt.threads : 0;
#else
  ThreadChooser chooser(1);
  const int fixed_threads = 1;
#endif
  const RunControl& rc = model.control;
  const hbm::deck::Units& u = model.units;
  std::error_code ec;
  std::filesystem::create_directories(opt.out_dir, ec);
  Listing listing(opt.out_dir / (model.run_name + "_0001.out"), opt.console);
  if (!listing.ok()) {
    res.exit_code = 1;
    res.message = "cannot write the listing in " + opt.out_dir.string();
    return res;
  }
  std::vector<std::unique_ptr<ThWriter>> th;
  for (const ThGroup& g : model.th_groups) {
    auto w = std::make_unique<ThWriter>();
    std::string err;
    if (!w->open(opt.out_dir / th_file_name(model.run_name, g), g, u, err)) {
      res.exit_code = 1;
      res.message = err;
      return res;
    }
    th.push_back(std::move(w));
  }
  VtkWriter vtk(opt.out_dir, model.run_name);

  std::size_t n_elements = 0, n_inactive = 0;
  for (const auto& g : model.groups) {
    n_elements += g->n_elements;
    n_inactive += g->n_deactivated;
  }
  listing.line("hbm-solver explicit engine: run " + model.run_name);
  listing.line("  nodes " + std::to_string(model.nodes.n_nodes) + ", elements " + std::to_string(n_elements) +
               (n_inactive > 0 ? " (" + std::to_string(n_inactive) + " deactivated inside rigid bodies)" : std::string()) +
               ", groups " + std::to_string(model.groups.size()) + ", interactions " +
               std::to_string(model.interactions.size()) + ", constraints " + std::to_string(model.constraints.size()));
  for (const auto& g : model.groups) {
    const Part& p = model.parts[static_cast<std::size_t>(g->part)];
    listing.line("  group " + g->keyword + " part " + std::to_string(p.id) + " '" + p.title + "': " +
                 std::to_string(g->n_elements) + " elements, " + std::string(g->formulation()) +
                 (g->n_deactivated > 0 ? ", " + std::to_string(g->n_deactivated) +
                                             " deactivated (inside a rigid body)"
                                       : std::string()));
  }
  const std::string mu = unit_text(hbm::deck::Dimension::Mass, u), eu = unit_text(hbm::deck::Dimension::Energy, u),
                    tu = unit_text(hbm::deck::Dimension::Time, u);
  listing.line(rc.nodal_cst ? "  time step: /DT/NODA/CST fixed " + fmt("%.4e", rc.dt_min) + " " + tu +
                                  " with nodal mass scaling (Tsca " + fmt("%.3f", rc.dt_scale) + ")"
                            : "  time step: element, factor " + fmt("%.3f", rc.dt_scale));
  char head[256];
  std::snprintf(head, sizeof head, "%9s %12s %11s %9s %12s %12s %12s %11s %11s %9s", "CYCLE", ("TIME[" + tu + "]").c_str(),
                "TIME-STEP", "ERROR[%]", ("I-ENERGY[" + eu + "]").c_str(), ("K-ENERGY[" + eu + "]").c_str(),
                ("EXT-WORK[" + eu + "]").c_str(), "MAS.ERR", ("ADDED[" + mu + "]").c_str(), "ETA[s]");
  listing.line(head);

  CycleState c;
  const double M0 = model.total_mass0();
  c.energies.mass0 = M0;
  {
    const auto [ke, ker] = half_step_kinetic(model.nodes, c.chunk_scratch);
    c.kinetic_half_prev = ke;
    c.rotational_half_prev = ker;
    c.energies.initial_total = ke + ker;  // E_0: initial velocities v^{-1/2} = v_0
  }
  double next_th = 0.0, next_anim = rc.anim_start;
  const double tol = 1e-9 * rc.t_stop;
  // The next output time after `t`: the schedule steps by `interval`; a step that jumps
  // over a million intervals at once (a damaged deck's huge stable step, where the interval
  // may not even change a time that large) goes straight past t. Ordinary runs only add.
  auto advance_past = [](double& next, double t, double interval) {
    if (next > t) return;
    if ((t - next) / interval > 1e6) {
      next = std::max(t + interval, std::nextafter(t, std::numeric_limits<double>::infinity()));
      return;
    }
    while (next <= t) next += interval;
  };
  // A run whose stable time step has fallen below this fraction of its first one would need
  // that many times its planned cycles: it is stopped (a damaged deck, a collapsing element).
  // So is a run whose first step would need more cycles than any explicit crash run takes
  // (a units slip: E in Pa in a GPa deck, a density in kg/mm^3 written in t/mm^3).
  constexpr double kTimeStepCollapse = 1e-6, kMaxCycles = 1e9;
  double dt_first = 0.0;
  const auto wall0 = Clock::now();
  const double cpu0 = process_cpu_seconds();
  double output_seconds = 0.0;
  Vec3Soa vel_out;
  // When each group's elements switched to small strain (first and last sampling time at
  // which its count grew; sampled with the time histories, or every listing line).
  struct SwitchTimes {
    std::size_t count = 0;
    double first = -1.0, last = -1.0;
  };
  std::vector<SwitchTimes> switched(model.groups.size());
  auto sample_switches = [&](double t) {
    for (std::size_t g = 0; g < model.groups.size(); ++g) {
      const std::size_t n = model.groups[g]->n_small_strain();
      if (n == switched[g].count) continue;
      if (switched[g].count == 0) switched[g].first = t;
      switched[g].last = t;
      switched[g].count = n;
    }
  };
  for (;;) {
    const auto cycle0 = Clock::now();
#ifdef _OPENMP
    if (fixed_threads == 0) omp_set_num_threads(chooser.next_threads());
#endif
    compute_element_forces(model, c);
    assemble_nodal_forces(model, c);
    add_interaction_forces(model, c);
    gather_constraint_forces(model, c);
    choose_time_step(model, c);
    update_velocities(model, c);
    impose_constraints(model, c);
    account_energies(model, c);
    chooser.cycle_done(std::chrono::duration<double>(Clock::now() - cycle0).count());
    model.dt_output = c.step.dt_next;
    const double t = c.step.time;
    for (const auto& e : c.events) listing.line("  " + e);
    c.events.clear();
    // Stop criteria at t^n.
    for (std::size_t g = 0; g < model.groups.size() && c.stop == StopReason::None; ++g) {
      const Index e = c.group_results[g].inverted_element;
      if (e == kNoIndex) continue;
      const ElementGroup& grp = *model.groups[g];
      const Part& p = model.parts[static_cast<std::size_t>(grp.part)];
      c.stop = StopReason::InvertedElement;
      c.stop_message = "element " + std::to_string(grp.element_id[static_cast<std::size_t>(e)]) + " of part " +
                       std::to_string(p.id) + " '" + p.title + "' inverted (negative volume) at time " +
                       fmt("%.6e", t) + " " + tu + ", cycle " + std::to_string(c.step.cycle);
    }
    if (c.stop == StopReason::None && c.energies.mass_ratio() > rc.stop_mass_ratio) {
      c.stop = StopReason::AddedMass;
      c.stop_message = "added mass ratio (M-M0)/M0 = " + fmt("%.4e", c.energies.mass_ratio()) + " exceeds DMmax = " +
                       fmt("%.4e", rc.stop_mass_ratio) + " at time " + fmt("%.6e", t) + " " + tu +
                       "; mass went to:" + where_mass_went(model, c, u);
    }
    if (c.stop == StopReason::None && std::abs(c.energies.energy_error()) > rc.stop_energy_error) {
      c.stop = StopReason::EnergyError;
      c.stop_message = "energy error " + fmt("%.4e", c.energies.energy_error()) + " exceeds Emax = " +
                       fmt("%.4e", rc.stop_energy_error) + " at time " + fmt("%.6e", t) + " " + tu;
    }
    if (c.stop == StopReason::None && t >= rc.t_stop - tol) c.stop = StopReason::EndTime;
    if (c.stop == StopReason::None && !(c.step.dt_next > 0.0 && std::isfinite(c.step.dt_next))) {
      c.stop = StopReason::InvertedElement;
      c.stop_message = "time step " + fmt("%.4e", c.step.dt_next) + " is not positive and finite at time " + fmt("%.6e", t);
    }
    // " (element E of part P 'title')" for the element that set the step, if one did.
    auto step_element = [&]() -> std::string {
      if (c.dt_group == kNoIndex || c.dt_element == kNoIndex) return "";
      const ElementGroup& grp = *model.groups[static_cast<std::size_t>(c.dt_group)];
      const Part& p = model.parts[static_cast<std::size_t>(grp.part)];
      return " (element " + std::to_string(grp.element_id[static_cast<std::size_t>(c.dt_element)]) + " of part " +
             std::to_string(p.id) + " '" + p.title + "')";
    };
    if (c.step.cycle == 0) {
      dt_first = c.step.dt_next;
      const double cycles = (rc.t_stop - t) / dt_first;
      if (cycles < 1.0)
        listing.line("  warning: the first time step " + fmt("%.4e", dt_first) + " " + tu + step_element() +
                         " is longer than the whole run (end time " + fmt("%.6e", rc.t_stop) + " " + tu +
                         "): one cycle; check the units of its material",
                     true);
      if (c.stop == StopReason::None && cycles > kMaxCycles) {
        c.stop = StopReason::TimeStepTooSmall;
        c.stop_message = "the first time step " + fmt("%.4e", dt_first) + " " + tu + step_element() + " would take " +
                         fmt("%.3e", cycles) + " cycles to the end time " + fmt("%.6e", rc.t_stop) + " " + tu +
                         " (more than " + fmt("%.0e", kMaxCycles) + "): check the units of its material";
      }
    }
    if (c.stop == StopReason::None && c.step.dt_next < kTimeStepCollapse * dt_first) {
      c.stop = StopReason::TimeStepTooSmall;
      c.stop_message = "time step " + fmt("%.4e", c.step.dt_next) + " " + tu + step_element() + " fell below " +
                       fmt("%.0e", kTimeStepCollapse) + " of the first one (" + fmt("%.4e", dt_first) + " " + tu +
                       ") at time " + fmt("%.6e", t) + " " + tu + ", cycle " + std::to_string(c.step.cycle);
    }
    const bool stopping = c.stop != StopReason::None;
    // Outputs at t^n.
    const auto o0 = Clock::now();
    if (rc.th_interval > 0 && (t >= next_th - tol || stopping)) {
      sample_switches(t);
      for (auto& w : th) w->write_row(t, c.energies);
      advance_past(next_th, t + tol, rc.th_interval);
    }
    if (rc.anim_interval > 0 && (t >= next_anim - tol || stopping)) {
      const NodalState& n = model.nodes;
      vel_out.resize(n.n_nodes);
      for (std::size_t i = 0; i < n.n_nodes; ++i) {
        vel_out.x[i] = n.v.x[i] - 0.5 * c.step.dt_next * n.a.x[i];
        vel_out.y[i] = n.v.y[i] - 0.5 * c.step.dt_next * n.a.y[i];
        vel_out.z[i] = n.v.z[i] - 0.5 * c.step.dt_next * n.a.z[i];
      }
      std::string err;
      if (!vtk.write_frame(model, t, vel_out, err)) listing.line("  warning: animation: " + err);
      advance_past(next_anim, t + tol, rc.anim_interval);
    }
    if (c.step.cycle % rc.print_every == 0 || stopping) {
      if (rc.th_interval <= 0) sample_switches(t);
      const double wall = std::chrono::duration<double>(Clock::now() - wall0).count();
      const double eta = t > 0 ? wall * (rc.t_stop - t) / t : 0.0;
      char b[256];
      std::snprintf(b, sizeof b, "%9lld %12.5e %11.4e %9.3f %12.5e %12.5e %12.5e %11.4e %11.4e %9.1f",
                    static_cast<long long>(c.step.cycle), t, c.step.dt_next, 100.0 * c.energies.energy_error(),
                    c.energies.internal + c.energies.hourglass, c.energies.kinetic + c.energies.rotational,
                    c.energies.external_work, c.energies.mass_ratio(), c.energies.added_mass, std::max(eta, 0.0));
      listing.line(b, rc.print_stdout || stopping);
    }
    output_seconds += std::chrono::duration<double>(Clock::now() - o0).count();
    if (stopping) break;
    update_positions(model, c);
  }
  c.times.output += output_seconds;
  const double wall = std::chrono::duration<double>(Clock::now() - wall0).count();

  // Final report.
  listing.line("");
  listing.line("PART SUMMARY (mass " + mu + ")");
  for (const Part& p : model.parts) {
    std::int64_t eroded = 0;
    std::size_t inactive = 0;
    for (const auto& g : model.groups)
      if (static_cast<std::size_t>(g->part) == static_cast<std::size_t>(&p - model.parts.data())) {
        eroded += g->n_eroded;
        inactive += g->n_deactivated;
      }
    char b[320];
    std::snprintf(b, sizeof b,
                  "  part %10lld  mass %12.5e  added %12.5e  (%8.4f %%)  deleted elements %lld  deactivated %zu  %s",
                  static_cast<long long>(p.id), p.mass0, p.added_mass, 100.0 * p.added_mass / std::max(p.mass0, 1e-300),
                  static_cast<long long>(eroded), inactive, p.title.c_str());
    listing.line(b);
  }
  listing.line("  total mass M0 " + fmt("%.6e", M0) + ", added " + fmt("%.6e", c.energies.added_mass) +
               ", (M-M0)/M0 " + fmt("%.4e", c.energies.mass_ratio()));
  listing.line("");
  const double cycles = static_cast<double>(std::max<std::int64_t>(c.step.cycle + 1, 1));
  // Per element-cycle figures count the computed elements (those inside rigid bodies are
  // deactivated and cost nothing).
  const double ne = static_cast<double>(std::max<std::size_t>(n_elements - n_inactive, 1));
  const double nn = static_cast<double>(std::max<std::size_t>(model.nodes.n_nodes, 1));
  // validation_report.py reads this heading: keep its form.
  listing.line("TIMING (wall " + fmt("%.3f", wall) + " s, " + std::to_string(c.step.cycle + 1) + " cycles)");
  const std::string threads_text =
      fixed_threads > 0 || chooser.max_threads() == 1
          ? std::to_string(fixed_threads > 0 ? fixed_threads : 1)
          : "chosen per stretch: " + std::to_string(chooser.cycles_one()) + " cycles on 1, " +
                std::to_string(chooser.cycles_max()) + " on " + std::to_string(chooser.max_threads()) +
                " (last probe: " + chooser.last_choice() + ")";
  listing.line("  threads " + threads_text + ", process CPU time " + fmt("%.3f", process_cpu_seconds() - cpu0) +
               " s");
  if (c.partition.threads > 1) {
    // Who did what on several threads (ThreadPartition, docs/cycle.md).
    const ThreadPartition& tp = c.partition;
    std::string ranges, shares;
    for (std::size_t k = 0; k + 1 < tp.node_begin.size(); ++k) {
      ranges += (k ? ", " : "") + std::to_string(tp.node_begin[k]) + "-" + std::to_string(tp.node_begin[k + 1]);
      shares += (k ? " / " : "") + fmt("%.1f", 100.0 * tp.work_share[k]);
    }
    listing.line("  thread partition: node index ranges " + ranges + ", element work " + shares + " %" +
                 (tp.measured ? " (from measured group times)" : " (from relative costs)") +
                 (tp.shared ? "" : "; model too small to share: one thread ran every phase"));
  }
  // Per phase: wall seconds, share of the wall time, ns per element- or node-cycle from
  // the wall time and from the main thread's CPU time (the robust figure on a loaded
  // machine with 1 thread).
  auto row = [&](const char* name, double s, double cpu, double per, const char* what) {
    char b[240];
    std::snprintf(b, sizeof b, "  %-16s %10.4f s  %6.1f %%  %10.1f ns per %s-cycle  (CPU %8.1f)", name, s,
                  100.0 * s / std::max(wall, 1e-12), 1e9 * s / (per * cycles), what, 1e9 * cpu / (per * cycles));
    listing.line(b);
  };
  const PhaseTimes& pc = c.cpu_times;
  row("element forces", c.times.element_forces, pc.element_forces, ne, "element");
  row("contact/loads", c.times.interactions, pc.interactions, nn, "node");
  row("assembly", c.times.assembly, pc.assembly, nn, "node");
  row("constraints", c.times.constraints, pc.constraints, nn, "node");
  row("time step", c.times.time_step, pc.time_step, nn, "node");
  row("nodal update", c.times.nodal_update, pc.nodal_update, nn, "node");
  row("energies", c.times.energies, pc.energies, nn, "node");
  row("output", c.times.output, 0.0, nn, "node");
  {
    const PhaseTimes& p = c.times;
    const double rest = wall - (p.element_forces + p.interactions + p.assembly + p.constraints + p.time_step +
                                p.nodal_update + p.energies + p.output);
    row("rest of loop", std::max(rest, 0.0), 0.0, nn, "node");
  }
  // Element forces by kind (keyword, material law, formulation): wall time of the
  // groups' compute_forces (with several threads the small groups run side by side, so
  // the rows add up to more than the phase) and CPU time sampled on 1 cycle in 16.
  listing.line("ELEMENT FORCES BY KIND");
  {
    struct Kind {
      std::string label;
      double seconds = 0, cpu = 0;
      std::size_t elements = 0, groups = 0, deactivated = 0;  // elements: computed ones
    };
    std::vector<Kind> kinds;
    for (std::size_t g = 0; g < model.groups.size() && g < c.group_seconds.size(); ++g) {
      const ElementGroup& grp = *model.groups[g];
      const Part& p = model.parts[static_cast<std::size_t>(grp.part)];
      std::string law = p.mat_keyword.rfind("/MAT/", 0) == 0 ? p.mat_keyword.substr(5) : p.mat_keyword;
      const std::string label = grp.keyword + " " + (law.empty() ? "-" : law) + " " + std::string(grp.formulation());
      auto it = std::find_if(kinds.begin(), kinds.end(), [&](const Kind& k) { return k.label == label; });
      if (it == kinds.end()) {
        kinds.push_back({label});
        it = kinds.end() - 1;
      }
      it->seconds += c.group_seconds[g];
      it->cpu += c.group_cpu_seconds[g];
      it->elements += grp.n_elements - grp.n_deactivated;
      it->deactivated += grp.n_deactivated;
      ++it->groups;
    }
    for (const Kind& k : kinds) {
      char b[360];
      const double per = static_cast<double>(std::max<std::size_t>(k.elements, 1)) * cycles;
      std::snprintf(b, sizeof b, "  %-64s %6zu el %3zu gr %9.4f s  %8.1f ns per element-cycle  (CPU %8.1f)",
                    k.label.c_str(), k.elements, k.groups, k.seconds, 1e9 * k.seconds / per, 1e9 * k.cpu / per);
      listing.line(k.deactivated > 0 ? b + ("  +" + std::to_string(k.deactivated) + " deactivated")
                                     : std::string(b));
    }
  }
  // Elements switched to small strain (/DT/BRICK/CST, /DT/SHELL/CST): their geometry is
  // frozen from the switch on, so the user needs to know where.
  {
    bool header = false;
    for (std::size_t g = 0; g < model.groups.size(); ++g) {
      const ElementGroup& gp = *model.groups[g];
      const std::size_t n = gp.n_small_strain();
      if (n == 0) continue;
      if (!header) listing.line("ELEMENTS SWITCHED TO SMALL STRAIN (first and last switch, " + tu + ")");
      header = true;
      const Part& p = model.parts[static_cast<std::size_t>(gp.part)];
      std::string when;
      if (switched[g].first >= 0)
        when = switched[g].first == switched[g].last ? ", at " + fmt("%.3f", switched[g].first)
                                                     : ", from " + fmt("%.3f", switched[g].first) + " to " + fmt("%.3f", switched[g].last);
      listing.line("  " + gp.keyword + " part " + std::to_string(p.id) + " '" + p.title + "': " + std::to_string(n) +
                   " of " + std::to_string(gp.n_elements) + when);
    }
  }
  listing.line("");
  res.reason = c.stop;
  res.energies = c.energies;
  res.time = c.step.time;
  res.cycles = c.step.cycle;
  res.times = c.times;
  if (c.stop == StopReason::EndTime) {
    listing.line("NORMAL TERMINATION");
    res.exit_code = 0;
  } else {
    res.message = c.stop_message;
    listing.line("ERROR TERMINATION: " + c.stop_message);
    res.exit_code = 3;
  }
  return res;
}

}  // namespace hbm::solver
