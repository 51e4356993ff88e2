#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Isolated pelvic ring of the model loaded laterally through the left acetabulum, against
Guillemot 1998.

What it does: cuts the pelvic ring out of the body model include (parts pelvis_cortex,
pelvic_joints and sacrum with their property and material cards, and the rigid bodies
acetabulum_r and acetabulum_l with their node groups, all copied verbatim), writes a
standalone deck reproducing Guillemot's quasi-static isolated-pelvis test, runs hbm-solver
on it and compares the force against the acetabulum displacement with Guillemot's 10 static
specimens (mean and range at 1, 2, 3 and 5 mm, and the initial stiffness: least-squares
slope over 0.5-2.5 mm) and with the dynamic test without fracture. --check-plate runs an
analytic case instead of (or besides) the pelvis through the same deck writer, pot and
driven rigid body: a shell cantilever (k = 3 E I / L^3, driven body free) and a shell strip
in tension (k = E A / L, driven body guided).

Test set-up (Guillemot 1998 as described by the SAFER catalogue): sacrum potted, pubic rami
free, load through a rigid ball seated in the acetabulum. In the deck (model frame, Y to the
left):
  - pot: every node of part sacrum fixed in all 6 dof (/BCS 111 111);
  - ball: the model's rigid body acetabulum_l, its main node driven medially (-Y) by
    /IMPVEL, the velocity ramped up over the first 0.5 mm of stroke; rotations free;
    --guided (default) also fixes its X and Z translations (a ball on a stiff ram),
    --free leaves them free; acetabulum_r is a free rigid body;
  - force = Y force of the driven rigid body (positive resisting the medial push),
    d = medial displacement of its main node; stroke 10 mm at 0.05 mm/ms by default
    (quasi-static: about 3 s of solver time); fixed 1.5 us step with nodal mass scaling,
    as the whole model is run.

Source: Guillemot H, Got C, Besnault B, Lavaste F, Robin S, Le Coz JY, Lassau JP, Pelvic
behavior in side collisions: static and dynamic tests on isolated pelvic bones, 16th ESV
Conference, Windsor, 1998, paper 98-S6-W-37; curves from the SAFER HBM validation
catalogue (saferhbm/validation, Guillemot-1998-Pelvis), files static.csv (forces in daN,
converted to N here) and dynamic.csv (N) in --guillemot.

Run (from the repository root):
  ctest/validation/tools/isolated_pelvis_lateral.py --solver build/bin/hbm-solver \\
      --model decks/hbm50/hbm50.inc --work /tmp/pelvis [--guillemot DIR] \\
      [--speed MM_PER_MS] [--stroke MM] [--guided | --free] [--report FILE.md] [--check-plate]
--check-plate alone runs only the analytic plates (no --model needed); add --model to run
both. A model far off Guillemot is reported, not failed. Exit 1 with a message naming the
file (and line) on bad input, a solver failure or a failed plate check; 0 otherwise.
"""
import os
import shlex
import sys
from dataclasses import dataclass

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from isolated_rib_bending import (Card, InputError, centroid, channel,  # noqa: E402
                                  file_digest, fitted_slope, fmt, ids_in_rows_of_10, in_repo,
                                  interpolate, mean, node_line, ratio, read_model, read_time_history,
                                  run_hbm_solver, DriveSchedule, starter_head, write_deck_pair,
                                  positive_number, run_analytic_check, tool_argument_parser, tool_main,
                                  write_report_lines,
                                  FIXED_STEP_MS, RAMP_STROKE_MM)

TOOL = "ctest/validation/tools/isolated_pelvis_lateral.py"
REPO_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
DEFAULT_GUILLEMOT = os.path.join(os.path.dirname(REPO_ROOT), "shared", "reference", "corridors", "catalogue",
                                 "Guillemot-1998-Pelvis")

PELVIS_PARTS = ("pelvis_cortex", "pelvic_joints", "sacrum")
POTTED_PART = "sacrum"
ACETABULA = ("acetabulum_r", "acetabulum_l")  # /RBODY titles in the model
DRIVEN_BODY = "acetabulum_l"
# ids of the cards the tool adds (pot and driven groups, BCS, function, velocity)
POT_ID, DRIVEN_ID = 90001, 90002
COMPARE_AT_MM = (1.0, 2.0, 3.0, 5.0)
STIFFNESS_FIT_MM = (0.5, 2.5)
PLATE_STROKE_MM = 3.0                # past the end of the stiffness fit
PLATE_TOLERANCE = 0.03


# ---------------------------------------------------------------- specimens
@dataclass
class RigidBody:
    title: str
    card: Card     # /RBODY/id
    group: Card    # /GRNOD/NODE/id of its secondary nodes
    main: int
    members: list  # secondary node ids


@dataclass
class Specimen:
    name: str           # deck and run name
    header: list        # comment lines for the deck
    contents: str       # its elements, e.g. 'sacrum 12 bricks'
    nodes: dict         # id -> (x, y, z)
    cards: list         # /MAT, /PROP, /PART and element blocks (Card: key + lines), in deck order
    rigid_bodies: list  # RigidBody, the driven one included
    driven: RigidBody   # its main node is pushed along -Y
    potted_nodes: list  # fixed in all 6 dof
    guided: bool        # driven main node's X and Z fixed as well
    stroke_mm: float


def read_rigid_bodies(model):
    """The model's /RBODY cards by title, each with its /GRNOD/NODE group of secondaries."""
    path = model.path
    bodies = {}
    for (kind, _), card in model.cards.items():
        if kind != "RBODY":
            continue
        key = card.key
        try:
            title, first = card.lines[0].strip(), card.lines[1]
            main, group_id = int(first[0:10]), int(first[60:70])
        except (IndexError, ValueError):
            raise InputError(f"{path}:{card.line_no}: {key}: expected a title line, then main node id "
                             f"(columns 1-10) and grnod_id (columns 61-70)") from None
        group = model.cards.get(("GRNOD", group_id))
        if group is None:
            raise InputError(f"{path}:{card.line_no}: {key} refers to /GRNOD/NODE/{group_id}, "
                             "which is not in the file")
        try:
            members = [int(n) for line in group.lines[1:] for n in line.split()]
        except ValueError:
            raise InputError(f"{path}:{group.line_no}: {group.key}: node ids expected after the title") from None
        bodies[title] = RigidBody(title, card, group, main, members)
    return bodies


def cut_pelvis(model, bodies, guided, stroke_mm):
    """The pelvic ring of the model with its acetabulum rigid bodies (module docstring)."""
    cards, nodes_of_part, mat_keys, contents = [], {}, set(), []
    for title in PELVIS_PARTS:
        pid = model.part_id(title)
        part, prop, mat = model.part_cards(pid)
        if mat.key not in mat_keys:  # a material shared by two parts is written once
            mat_keys.add(mat.key)
            cards.append(mat)
        cards += [prop, part]
        nodes_of_part[title] = set()
        for kind, count in (("SHELL", 4), ("SH3N", 3), ("BRICK", 8)):
            rows = model.elements.get((kind, pid), [])
            if rows:
                cards.append(Card(f"/{kind}/{pid}", [text for _, text in rows], rows[0][0] - 1))
                contents.append(f"{title} {len(rows)} {kind.lower()}s")
                nodes_of_part[title] |= {n for row in model.element_nodes(kind, pid, 10, count) for n in row}
        if not nodes_of_part[title]:
            raise InputError(f"{model.path}:{part.line_no}: part {pid} {title} has no /SHELL, /SH3N or /BRICK "
                             "elements")

    ring_nodes = set().union(*nodes_of_part.values())
    acetabula = []
    for title in ACETABULA:
        if title not in bodies:
            raise InputError(f"{model.path}: no /RBODY titled '{title}'; rigid bodies: {' '.join(sorted(bodies))}")
        body = bodies[title]
        if not ring_nodes & set(body.members):
            raise InputError(f"{model.path}:{body.card.line_no}: {body.card.key} {title} has no node on the parts "
                             f"{', '.join(PELVIS_PARTS)}: it would not load the ring")
        group_id = int(body.group.key.split("/")[-1])
        if group_id in (POT_ID, DRIVEN_ID):
            raise InputError(f"{model.path}:{body.group.line_no}: {body.group.key} clashes with the node groups "
                             f"{POT_ID}, {DRIVEN_ID} that the tool adds")
        acetabula.append(body)
    used = ring_nodes | {n for b in acetabula for n in b.members + [b.main]}
    nodes = {n: model.node(n, "the pelvic ring") for n in sorted(used)}
    driven = acetabula[ACETABULA.index(DRIVEN_BODY)]
    mode = "guided (X Z fixed)" if guided else "free"
    header = [f"Isolated pelvic ring, lateral acetabulum loading (Guillemot 1998 set-up), written by {TOOL}",
              f"parts {', '.join(PELVIS_PARTS)} and rigid bodies {', '.join(ACETABULA)} of {in_repo(model.path)}",
              f"{POTTED_PART} potted (all nodes fixed), {DRIVEN_BODY} main node {driven.main} driven -Y, {mode}"]
    return Specimen("pelvis", header, ", ".join(contents), nodes, cards, acetabula, driven,
                    sorted(nodes_of_part[POTTED_PART]), guided, stroke_mm)


@dataclass
class Plate:
    """Flat strip of 4-node shells (LAW1, cortex-like E), potted at one end, the other end a
    rigid body driven along -Y. 'bending': the strip lies in the XZ plane along +X, driven
    out of plane with the body free (cantilever, k = 3 E I / L^3, I = b t^3 / 12); 'tension':
    it lies along -Y, driven along its axis with the body guided (k = E A / L, A = b t).
    Poisson's ratio 0 makes the strip a beam whatever its deflection and end restraints: with
    0.3 the cantilever comes out 2 % below 3 E I / L^3 over the fit (0.0 % over 0.1-0.5 mm),
    a plate effect that the beam formula does not hold."""
    load: str
    length_mm: float
    width_mm: float = 20.0
    thickness_mm: float = 3.0
    cells_along: int = 20
    cells_across: int = 2
    modulus_gpa: float = 10.84
    density: float = 2e-6  # kg/mm^3
    poisson: float = 0.0

    def analytic_stiffness(self):
        """[N/mm] (the model's units are kg mm ms: force kN, stress GPa)."""
        e = 1e3 * self.modulus_gpa  # N/mm^2
        if self.load == "bending":
            return 3.0 * e * self.width_mm * self.thickness_mm ** 3 / 12.0 / self.length_mm ** 3
        return e * self.width_mm * self.thickness_mm / self.length_mm

    def formula(self):
        return "3 E I / L^3" if self.load == "bending" else "E A / L"

    def position(self, i, j):
        along = self.length_mm * i / self.cells_along
        across = self.width_mm * (j / self.cells_across - 0.5)
        return (along, 0.0, across) if self.load == "bending" else (across, -along, 0.0)

    def specimen(self):
        """The strip, potted at its first row of nodes, its last row the driven body."""
        grid, nodes = {}, {}
        for i in range(self.cells_along + 1):
            for j in range(self.cells_across + 1):
                grid[(i, j)] = len(nodes) + 1
                nodes[grid[(i, j)]] = self.position(i, j)
        shells = []
        for i in range(self.cells_along):
            for j in range(self.cells_across):
                corners = (grid[(i, j)], grid[(i + 1, j)], grid[(i + 1, j + 1)], grid[(i, j + 1)])
                shells.append(f"{len(shells) + 1:10d}" + "".join(f"{n:10d}" for n in corners))
        cards = [Card("/MAT/LAW1/1", ["plate", f"{self.density:20.10E}",
                                      f"{self.modulus_gpa:20.10E}{self.poisson:20.10E}"], 0),
                 # the fields of hbm50's pelvis_cortex property card, thickness set here
                 Card("/PROP/TYPE1/1", ["plate shell", "         4                   2", "",
                                        f"{3:10d}{'':10}{self.thickness_mm:20.10E}"], 0),
                 Card("/PART/1", [f"plate_{self.load}", f"{1:10d}{1:10d}{0:10d}"], 0),
                 Card("/SHELL/1", shells, 0)]
        end = [grid[(self.cells_along, j)] for j in range(self.cells_across + 1)]
        main = len(nodes) + 1
        nodes[main] = centroid([nodes[n] for n in end])
        # main node moved to the centre (ICoG 1); unit inertia added: the end nodes are
        # collinear, their own inertia about that line is nil
        rbody = Card("/RBODY/1", ["plate_end", f"{main:10d}{0:10d}{0:10d}{0:10d}{0.0:20.6E}{1:10d}{0:10d}{1:10d}{0:10d}",
                                  f"{1.0:20.6E}" * 3], 0)
        group = Card("/GRNOD/NODE/1", ["plate end nodes"] + ids_in_rows_of_10(end), 0)
        body = RigidBody("plate_end", rbody, group, main, end)
        header = [f"analytic check written by {TOOL}: plate {self.load}, L {self.length_mm:g} b {self.width_mm:g} "
                  f"t {self.thickness_mm:g} mm, E {self.modulus_gpa:g} GPa, nu {self.poisson:g}, "
                  f"{self.cells_along} x {self.cells_across} quads"]
        potted = [grid[(0, j)] for j in range(self.cells_across + 1)]
        return Specimen(f"plate_{self.load}", header, f"{len(shells)} shells", nodes, cards, [body], body, potted,
                        self.load == "tension", PLATE_STROKE_MM)


PLATES = (Plate("bending", length_mm=60.0), Plate("tension", length_mm=300.0, cells_along=30))


# ---------------------------------------------------------------- deck writer
def write_deck(folder, spec, speed):
    """Starter and engine files of the test (module docstring); returns the starter path."""
    schedule = DriveSchedule(spec.stroke_mm, speed)
    lines = starter_head(spec.name, spec.header)
    lines += [node_line(n, spec.nodes[n]) for n in sorted(spec.nodes)]
    for card in spec.cards:
        lines += [card.key] + card.lines
    for body in spec.rigid_bodies:
        lines += [body.group.key] + body.group.lines + [body.card.key] + body.card.lines
    driven_body_id = int(spec.driven.card.key.split("/")[-1])
    lines += [f"/GRNOD/NODE/{POT_ID}", "potted nodes"] + ids_in_rows_of_10(spec.potted_nodes)
    lines += [f"/GRNOD/NODE/{DRIVEN_ID}", "driven main node"] + ids_in_rows_of_10([spec.driven.main])
    lines += [f"/BCS/{POT_ID}", "pot: all dof fixed", f"   111 111{0:10d}{POT_ID:10d}"]
    if spec.guided:
        lines += [f"/BCS/{DRIVEN_ID}", "driven body guided along Y: X Z fixed, rotations free",
                  f"   101 000{0:10d}{DRIVEN_ID:10d}"]
    lines += schedule.funct_lines(POT_ID)
    lines += [f"/IMPVEL/{POT_ID}", "driven body along -Y", f"{POT_ID:10d}{'Y':>10}{0:10d}{0:10d}{DRIVEN_ID:10d}",
              f"{1.0:20.10E}{-speed:20.10E}{0.0:20.10E}{0.0:20.10E}"]
    lines += ["/TH/RBODY/1", "driven body", "".join(f"{c:>10}" for c in ("FX", "FY", "FZ")), f"{driven_body_id:10d}",
              "/TH/NODE/2", "driven main node", "".join(f"{c:>10}" for c in ("DX", "DY", "DZ")),
              f"{spec.driven.main:10d}{0:10d}driven", "/END"]
    return write_deck_pair(folder, spec.name, lines, schedule, speed, 5000)


# ---------------------------------------------------------------- solver run
@dataclass
class RunResult:
    displacement: list   # driven main node along -Y [mm]
    force: list          # Y force of the driven body, positive resisting the push [N]
    termination: str
    max_energy_error: float  # largest |energy error| over the run, fraction
    wall_s: float


def run_solver(solver, starter, spec):
    """Runs hbm-solver on the deck and reads the driven body's force and displacement from
    its /TH/RBODY and /TH/NODE files."""
    out, termination, wall = run_hbm_solver(solver, starter)
    rbody_csv = os.path.join(out, f"{spec.name}_TH_RBODY_1.csv")
    node_csv = os.path.join(out, f"{spec.name}_TH_NODE_2.csv")
    rbody, nodes = read_time_history(rbody_csv), read_time_history(node_csv)
    t_force = channel(rbody, rbody_csv, "time", "ms")
    body_id = spec.driven.card.key.split("/")[-1]
    # the body's force from its elements: +Y while it is pushed along -Y
    force = channel(rbody, rbody_csv, f"rbody {body_id} {spec.driven.title} FY", "N")
    error = channel(rbody, rbody_csv, "energy error", "-")
    if channel(nodes, node_csv, "time", "ms") != t_force:  # the solver writes all histories on the same cycles
        raise InputError(f"{node_csv}: its times differ from those of {rbody_csv}")
    displacement = [-dy for dy in channel(nodes, node_csv, f"node {spec.driven.main} driven DY", "mm")]
    return RunResult(displacement, force, termination, max(abs(e) for e in error), wall)


# ---------------------------------------------------------------- Guillemot data
@dataclass
class Curve:
    label: str
    points: list  # (displacement mm, force N), displacement non-decreasing

    def at(self, x):
        return interpolate(x, [p[0] for p in self.points], [p[1] for p in self.points])

    def stiffness(self):
        return fitted_slope([p[0] for p in self.points], [p[1] for p in self.points], *STIFFNESS_FIT_MM)

    @property
    def end_mm(self):
        return self.points[-1][0]


@dataclass
class Guillemot:
    static: list     # Curve per specimen
    dynamic: Curve   # test without fracture, loading branch
    source_lines: list  # '# KEY: value' header lines of static.csv


def read_columns(path, unit_word):
    """Header comments and {column name: [(line number, cell)]} of a catalogue CSV ('#' lines,
    a column-name row, then rows of cells, empty where a column has ended). The '# COLUMNS /
    UNITS' comment must name the force unit unit_word."""
    try:
        with open(path) as f:
            text = f.read().splitlines()
    except OSError as e:
        raise InputError(f"{path}: cannot read the Guillemot file ({e.strerror})") from None
    comments = [line for line in text if line.startswith("#")]
    units = [line for line in comments if line.startswith("# COLUMNS / UNITS")]
    if not units or unit_word not in units[0]:
        raise InputError(f"{path}: expected a '# COLUMNS / UNITS' line giving the forces in {unit_word}")
    rows = [(line_no, line) for line_no, line in enumerate(text, 1) if line.strip() and not line.startswith("#")]
    if not rows:
        raise InputError(f"{path}: no column-name row")
    names = [c.strip() for c in rows[0][1].split(",")]
    columns = {name: [] for name in names}
    for line_no, line in rows[1:]:
        for name, cell in zip(names, line.split(",")):
            if cell.strip():
                columns[name].append((line_no, cell.strip()))
    return comments, columns, rows[0][0]


def curve_from(path, columns, header_line, d_name, f_name, force_factor, label):
    """The curve of columns d_name, f_name (forces x force_factor to N), up to its largest
    displacement (the loading branch)."""
    for name in (d_name, f_name):
        if name not in columns:
            raise InputError(f"{path}:{header_line}: no column '{name}'; columns: {', '.join(columns)}")
    if len(columns[d_name]) != len(columns[f_name]):
        raise InputError(f"{path}: columns {d_name} and {f_name} have {len(columns[d_name])} and "
                         f"{len(columns[f_name])} values")
    points = []
    for (line_no, d), (_, f) in zip(columns[d_name], columns[f_name]):
        try:
            points.append((float(d), force_factor * float(f)))
        except ValueError:
            raise InputError(f"{path}:{line_no}: '{d}', '{f}' in {d_name}, {f_name} are not numbers") from None
    if len(points) < 3:
        raise InputError(f"{path}: {len(points)} values in {d_name}, {f_name}; expected a curve")
    peak = max(range(len(points)), key=lambda i: points[i][0])
    points = points[:peak + 1]
    if any(b[0] < a[0] for a, b in zip(points, points[1:])):
        raise InputError(f"{path}: {d_name} decreases before its largest value; expected a loading curve")
    return Curve(label, points)


def read_guillemot(folder):
    static_csv, dynamic_csv = os.path.join(folder, "static.csv"), os.path.join(folder, "dynamic.csv")
    comments, columns, header_line = read_columns(static_csv, "daN")
    count = len([name for name in columns if name.startswith("d_")])
    if count == 0:
        raise InputError(f"{static_csv}:{header_line}: no specimen columns d_1, f_1, ...")
    static = [curve_from(static_csv, columns, header_line, f"d_{k}", f"f_{k}", 10.0, f"specimen {k}")  # daN -> N
              for k in range(1, count + 1)]
    _, columns, header_line = read_columns(dynamic_csv, "[N]")
    dynamic = curve_from(dynamic_csv, columns, header_line, "nf_disp", "nf_force", 1.0, "dynamic, no fracture")
    return Guillemot(static, dynamic, comments)


# ---------------------------------------------------------------- comparison
@dataclass
class PelvisComparison:
    spec: Specimen
    run: RunResult
    guillemot: Guillemot

    def model_at(self, x):
        return interpolate(x, self.run.displacement, self.run.force)

    def static_at(self, x):
        """Guillemot static specimens at x: (forces of those that reach x, labels of those that do not)."""
        forces = [c.at(x) for c in self.guillemot.static]
        return [f for f in forces if f is not None], [c for c, f in zip(self.guillemot.static, forces) if f is None]

    def model_stiffness(self):
        return fitted_slope(self.run.displacement, self.run.force, *STIFFNESS_FIT_MM)

    def static_stiffnesses(self):
        return [c.stiffness() for c in self.guillemot.static]


def value_range(values):
    return f"{min(values):.0f}-{max(values):.0f}" if values else "-"


def ratio_text(model, reference):
    """Model / reference, and how many times too soft or stiff the model is."""
    r = ratio(model, reference)
    if r is None or r <= 0:
        return "-"
    return f"{r:.3g} (1/{1 / r:.0f})" if r < 1 else f"{r:.3g}"


def describe_setup(c, args):
    return (f"pelvic ring ({c.spec.contents}; {len(c.spec.potted_nodes)} {POTTED_PART} nodes potted), "
            f"{DRIVEN_BODY} driven -Y "
            f"at {args.speed:g} mm/ms, {'guided' if c.spec.guided else 'free'}")


def left_out_text(c, x):
    _, short = c.static_at(x)
    return ", ".join(f"{s.label} (ends at {s.end_mm:.1f} mm)" for s in short)


def print_pelvis_table(c, args):
    r = c.run
    print(f"{describe_setup(c, args)}: {r.termination}, max |energy error| {100 * r.max_energy_error:.2f} %, "
          f"solver {r.wall_s:.1f} s")
    print(f"  {'d [mm]':>6} {'model [N]':>10} {'static mean [N]':>15} {'n':>3} {'static range [N]':>16} "
          f"{'model/mean':>17} {'dynamic nf [N]':>14}")
    for x in COMPARE_AT_MM:
        model, (forces, _) = c.model_at(x), c.static_at(x)
        print(f"  {x:6g} {fmt(model, '10.1f'):>10} {fmt(mean(forces), '15.0f'):>15} {len(forces):>3} "
              f"{value_range(forces):>16} {ratio_text(model, mean(forces)):>17} "
              f"{fmt(c.guillemot.dynamic.at(x), '14.0f'):>14}")
    for x in COMPARE_AT_MM:
        if left_out_text(c, x):
            print(f"  left out of F{x:g}: {left_out_text(c, x)}")
    if c.guillemot.dynamic.end_mm < max(COMPARE_AT_MM):
        print(f"  dynamic no-fracture curve ends at {c.guillemot.dynamic.end_mm:.2f} mm")
    km, ks = c.model_stiffness(), c.static_stiffnesses()
    print(f"  stiffness (fit {STIFFNESS_FIT_MM[0]:g}-{STIFFNESS_FIT_MM[1]:g} mm): model {fmt(km, '.2f')} N/mm, "
          f"Guillemot static mean {mean(ks):.0f} N/mm (range {value_range(ks)}, {len(ks)} specimens), "
          f"model/mean {ratio_text(km, mean(ks))}; dynamic no fracture "
          f"{fmt(c.guillemot.dynamic.stiffness(), '.0f')} N/mm")


# ---------------------------------------------------------------- analytic plate check
def check_plates(solver, work, speed):
    def run_specimen(spec):
        return run_solver(solver, write_deck(os.path.join(work, spec.name), spec, speed), spec)
    return [run_analytic_check(run_specimen, work, plate, PLATE_TOLERANCE, STIFFNESS_FIT_MM) for plate in PLATES]


def describe_plate(check):
    p = check.shape
    return (f"Plate {p.load} ({'free' if p.load == 'bending' else 'guided'} end), L {p.length_mm:g} b {p.width_mm:g} "
            f"t {p.thickness_mm:g} mm, E {p.modulus_gpa:g} GPa, {p.cells_along} x {p.cells_across} quads: model k "
            f"{check.model_k:.3f} N/mm (fit {STIFFNESS_FIT_MM[0]:g}-{STIFFNESS_FIT_MM[1]:g} mm) vs {p.formula()} = "
            f"{check.analytic_k:.3f} N/mm: {100 * check.deviation:+.2f} % (limit +-{100 * PLATE_TOLERANCE:g} %); "
            f"{check.run.termination}, max |energy error| {100 * check.run.max_energy_error:.2f} %")


# ---------------------------------------------------------------- report
def write_report(path, args, comparison, plate_checks):
    lines = [f"<!-- Generated by {TOOL}; do not edit. Command: {shlex.join(sys.argv)} -->",
             "# Isolated pelvic ring, lateral acetabulum loading, against Guillemot 1998", ""]
    c = comparison
    if c:
        km, ks = c.model_stiffness(), c.static_stiffnesses()
        lines += [f"Model `{in_repo(args.model)}` (sha256 {file_digest(args.model)}): {describe_setup(c, args)}, "
                  f"stroke {args.stroke:g} mm; {c.run.termination}, max |energy error| "
                  f"{100 * c.run.max_energy_error:.2f} %. Force = Y force of the driven rigid body, d = its medial "
                  "displacement; static = Guillemot's quasi-static specimens (forces converted from daN), mean and "
                  "range over those that reach d; dynamic nf = the dynamic test without fracture.", "",
                  f"**Initial stiffness** (least-squares slope over d = {STIFFNESS_FIT_MM[0]:g}-"
                  f"{STIFFNESS_FIT_MM[1]:g} mm): model {fmt(km, '.2f')} N/mm, Guillemot static mean "
                  f"{mean(ks):.0f} N/mm (range "
                  f"{value_range(ks)}, {len(ks)} specimens): **ratio model/mean {ratio_text(km, mean(ks))}**; "
                  f"dynamic no fracture {fmt(c.guillemot.dynamic.stiffness(), '.0f')} N/mm.", "",
                  "| d [mm] | model [N] | static mean [N] | n | static range [N] | model/mean | dynamic nf [N] |",
                  "|---:|---:|---:|---:|---:|---:|---:|"]
        for x in COMPARE_AT_MM:
            model, (forces, _) = c.model_at(x), c.static_at(x)
            lines.append(f"| {x:g} | {fmt(model, '.1f')} | {fmt(mean(forces), '.0f')} | {len(forces)} | "
                         f"{value_range(forces)} | {ratio_text(model, mean(forces))} | "
                         f"{fmt(c.guillemot.dynamic.at(x), '.0f')} |")
        lines.append("")
        lines += [f"- left out of F{x:g}: {left_out_text(c, x)}" for x in COMPARE_AT_MM if left_out_text(c, x)]
        if c.guillemot.dynamic.end_mm < max(COMPARE_AT_MM):
            lines.append(f"- the dynamic no-fracture curve ends at {c.guillemot.dynamic.end_mm:.2f} mm")
        lines.append("")
    if plate_checks:
        lines += ["## Method check: plates", ""] + [f"- {describe_plate(p)}." for p in plate_checks] + [""]
    lines += ["## Method", "",
              f"`{TOOL}` cuts parts {', '.join(f'`{p}`' for p in PELVIS_PARTS)} (property and material cards "
              f"copied verbatim) and the rigid bodies {', '.join(f'`{b}`' for b in ACETABULA)} (with their node "
              "groups) out of the model into a standalone deck:", "",
              f"- pot: every `{POTTED_PART}` node fixed in all 6 dof;",
              f"- ball: rigid body `{DRIVEN_BODY}`, main node driven medially (-Y), rotations free; guided = its X "
              "and Z translations fixed as well (a ball on a stiff ram), free = not; the other acetabulum free;",
              f"- velocity ramped up over the first {RAMP_STROKE_MM:g} mm; fixed {FIXED_STEP_MS * 1e3:g} us step "
              "with nodal mass scaling (as the whole model runs); hbm-solver on one thread;",
              "- method check (`--check-plate`): shell strips through the same deck writer, pot and driven body: "
              "a cantilever driven out of plane with its end free (3 E I / L^3) and a strip in tension with its end "
              "guided (E A / L).", "",
              "## Sources", "",
              "- Guillemot H, Got C, Besnault B, Lavaste F, Robin S, Le Coz JY, Lassau JP. Pelvic behavior in side "
              "collisions: static and dynamic tests on isolated pelvic bones. 16th ESV Conference, Windsor, 1998, "
              "paper 98-S6-W-37."]
    if c:
        source = [s[2:] for s in c.guillemot.source_lines
                  if s.startswith(("# SOURCE CATALOGUE", "# LOAD CASE", "# TEST SETUP"))]
        lines += [f"- {s}" for s in source]
        lines.append(f"- Files: `{in_repo(args.guillemot)}/static.csv` (specimens, daN) and `dynamic.csv` (N).")
    write_report_lines(path, lines)


# ---------------------------------------------------------------- main
def parse_args(argv):
    ap = tool_argument_parser(__doc__)
    ap.add_argument("--solver", required=True, help="hbm-solver executable")
    ap.add_argument("--model", help="body model include (decks/hbm50/hbm50.inc); needed to run the pelvis")
    ap.add_argument("--work", required=True, help="folder for the decks and runs")
    ap.add_argument("--guillemot", default=DEFAULT_GUILLEMOT,
                    help=f"Guillemot 1998 files (default {DEFAULT_GUILLEMOT})")
    ap.add_argument("--speed", type=positive_number, default=0.05, help="acetabulum speed [mm/ms] (default 0.05, quasi-static)")
    ap.add_argument("--stroke", type=positive_number, default=10.0, help="acetabulum stroke [mm] (default 10)")
    guide = ap.add_mutually_exclusive_group()
    guide.add_argument("--guided", dest="guided", action="store_true", default=True,
                       help="fix the driven acetabulum's X and Z translations (default)")
    guide.add_argument("--free", dest="guided", action="store_false", help="leave them free")
    ap.add_argument("--report", help="write a Markdown report here")
    ap.add_argument("--check-plate", action="store_true",
                    help=f"run the analytic plates; fail if off by more than {100 * PLATE_TOLERANCE:g} %%")
    args = ap.parse_args(argv)
    if not args.model and not args.check_plate:
        ap.error("--model is needed to run the pelvis (or give --check-plate)")
    if args.stroke <= STIFFNESS_FIT_MM[1]:
        ap.error(f"--stroke must pass the end of the stiffness fit ({STIFFNESS_FIT_MM[1]:g} mm)")
    return args


def run(args):
    pelvis = None
    if args.model:  # read every input before the first run
        guillemot = read_guillemot(args.guillemot)
        model = read_model(args.model)
        pelvis = cut_pelvis(model, read_rigid_bodies(model), args.guided, args.stroke)
    plate_checks = []
    if args.check_plate:
        plate_checks = check_plates(args.solver, args.work, args.speed)
        for check in plate_checks:
            print(f"{describe_plate(check)}, solver {check.run.wall_s:.1f} s")
    comparison = None
    if pelvis:
        starter = write_deck(os.path.join(args.work, pelvis.name), pelvis, args.speed)
        comparison = PelvisComparison(pelvis, run_solver(args.solver, starter, pelvis), guillemot)
        print_pelvis_table(comparison, args)
    if args.report:
        write_report(args.report, args, comparison, plate_checks)
        print(f"report: {args.report}")
    failed = [check for check in plate_checks if not check.passed]
    for check in failed:
        print(f"FAIL: plate {check.shape.load} stiffness off by {100 * check.deviation:+.2f} % "
              f"(limit +-{100 * PLATE_TOLERANCE:g} %)", file=sys.stderr)
    return 1 if failed else 0


def main(argv=None):
    return tool_main(parse_args, run, argv)


if __name__ == "__main__":
    sys.exit(main())
