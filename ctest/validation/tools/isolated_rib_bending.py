#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Isolated-rib anterior-posterior bending of the model's ribs against Kindig 2009.

What it does: cuts the right rib of each requested level out of the body model include
(the triangles of part rib_NN on the right side, with their property and material cards),
writes a standalone deck reproducing Kindig's isolated-rib test, runs hbm-solver on it and
compares the reaction force against end-to-end displacement with Kindig's average curve
and corridor polygon at 5, 10 and 15 mm, and the initial stiffness (least-squares slope
over 0.5-5 mm) of both. --check-ring runs an analytic case instead of (or besides) the
ribs: a pinned-pinned half ring, whose end-to-end stiffness is 2 E I / (pi R^3).

Test set-up (Kindig 2009 as described by the SAFER catalogue): the rib ends are potted,
the pots rotate about the normal of the rib's plane, the posterior pot is fixed and the
anterior pot is driven towards it along the line joining the ends; force = posterior pot
reaction. In the deck:
  - frame: origin at the posterior pot, X from the anterior to the posterior pot (the
    loading line), Z the normal of the rib's least-squares plane (Y = Z x X);
  - posterior pot: /RBODY on the rib nodes shared with part thoracic_vertebrae, main node
    /BCS 111 110 (translations fixed, rotations about X and Y fixed, free about Z);
  - anterior pot: /RBODY on the rib nodes shared with part costal_cartilage, /IMPVEL +X
    towards the posterior pot (velocity ramped up over the first 0.5 mm of stroke),
    /BCS 011 110 (Y and Z fixed, free rotation about Z);
  - stroke 1.2 x the end of Kindig's average curve; fixed 1.5 us step with nodal mass
    scaling, as the whole model is run; default speed 0.1 mm/ms (0.1 m/s, quasi-static:
    3-4 s of solver time per rib).

Source: Kindig MW, Tolerance to failure and geometric influences on the stiffness of human
ribs under anterior-posterior loading, MSc thesis, University of Virginia, 2009; averages
and corridors from the SAFER HBM validation catalogue (saferhbm/validation,
Kindig-2009-isolated-rib), files RibN_Kindig_avg.csv and RibN_Kindig_cor.csv in --kindig.

Run (from the repository root):
  ctest/validation/tools/isolated_rib_bending.py --solver build/bin/hbm-solver \\
      --model decks/hbm50/hbm50.inc --work /tmp/ribs [--ribs 2 3 ... 10] \\
      [--speed MM_PER_MS] [--kindig DIR] [--report FILE.md] [--check-ring]
--check-ring alone runs only the half ring (no --model needed); add --ribs to run both.
Exit 1 with a message naming the file (and line) on bad input, a solver failure or a
failed ring check; 0 otherwise.
"""
import argparse
import bisect
import hashlib
import math
import os
import shlex
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass

TOOL = "ctest/validation/tools/isolated_rib_bending.py"
REPO_ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
DEFAULT_KINDIG = os.path.join(os.path.dirname(REPO_ROOT), "shared", "reference", "corridors", "catalogue",
                              "Kindig-2009-isolated-rib")

SIDE = "right"                       # Kindig's ribs are compared with the model's right ribs
VERTEBRA_PART = "thoracic_vertebrae"  # rib nodes shared with it form the posterior pot
CARTILAGE_PART = "costal_cartilage"   # rib nodes shared with it form the anterior pot
POSTERIOR_MAIN, ANTERIOR_MAIN = 900001, 900002  # pot main nodes added to the deck
COMPARE_AT_MM = (5.0, 10.0, 15.0)
STIFFNESS_FIT_MM = (0.5, 5.0)
STROKE_FACTOR = 1.2                  # stroke = 1.2 x the end of Kindig's average curve
RAMP_STROKE_MM = 0.5                 # the velocity ramps up linearly over this stroke
SAMPLE_STROKE_MM = 0.01              # time-history output every 0.01 mm of stroke
FIXED_STEP_MS = 1.5e-3
RING_TOLERANCE = 0.03


class InputError(Exception):
    """Bad input or a failed run; the message names the file (and line)."""


# ---------------------------------------------------------------- vectors (3-tuples)
def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    return scale(a, 1.0 / math.sqrt(dot(a, a)))


def centroid(points):
    n = len(points)
    return tuple(sum(p[k] for p in points) / n for k in range(3))


def smallest_eigenvector(matrix):
    """Eigenvector of the smallest eigenvalue of a symmetric 3x3 matrix, by cyclic Jacobi
    rotations (each rotation zeroes one off-diagonal term; a few sweeps converge)."""
    a = [row[:] for row in matrix]
    v = [[1.0 if i == j else 0.0 for j in range(3)] for i in range(3)]
    for _ in range(50):
        off = a[0][1] ** 2 + a[0][2] ** 2 + a[1][2] ** 2
        if off <= 1e-30 * sum(a[i][i] ** 2 for i in range(3)):
            break
        for p, q in ((0, 1), (0, 2), (1, 2)):
            if a[p][q] == 0.0:
                continue
            theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q])
            t = math.copysign(1.0, theta) / (abs(theta) + math.sqrt(theta * theta + 1.0))
            c = 1.0 / math.sqrt(t * t + 1.0)
            s = t * c
            for k in range(3):  # a <- a J, v <- v J
                a[k][p], a[k][q] = c * a[k][p] - s * a[k][q], s * a[k][p] + c * a[k][q]
                v[k][p], v[k][q] = c * v[k][p] - s * v[k][q], s * v[k][p] + c * v[k][q]
            for k in range(3):  # a <- J^T a
                a[p][k], a[q][k] = c * a[p][k] - s * a[q][k], s * a[p][k] + c * a[q][k]
    i = min(range(3), key=lambda j: a[j][j])
    return (v[0][i], v[1][i], v[2][i])


def best_fit_plane_normal(points):
    """Unit normal of the least-squares plane through the points (the direction of least
    scatter: smallest eigenvector of their covariance), pointing to +Z."""
    c = centroid(points)
    d = [sub(p, c) for p in points]
    cov = [[sum(x[i] * x[j] for x in d) for j in range(3)] for i in range(3)]
    n = unit(smallest_eigenvector(cov))
    return scale(n, -1.0) if n[2] < 0 else n


# ---------------------------------------------------------------- model deck
@dataclass
class Card:
    key: str      # e.g. /MAT/LAW1/29
    lines: list   # the card's lines after the key, verbatim
    line_no: int  # line of the key in the file


@dataclass
class Model:
    path: str
    nodes: dict     # id -> (x, y, z)
    cards: dict     # (kind, id) -> Card for /MAT, /PROP, /PART, /RBODY and /GRNOD/NODE (kind "GRNOD")
    elements: dict  # (kind, part id) -> list of (line number, text) for /SH3N, /SHELL, /BRICK

    def part_id(self, title):
        parts = {cid: card.lines[0].strip() for (kind, cid), card in self.cards.items() if kind == "PART" and card.lines}
        ids = [cid for cid, name in parts.items() if name == title]
        if len(ids) != 1:
            titles = sorted(parts.values())
            raise InputError(f"{self.path}: {len(ids)} /PART cards titled '{title}' (expected 1); "
                             f"parts: {' '.join(titles)}")
        return ids[0]

    def card(self, kind, cid, referrer):
        if (kind, cid) not in self.cards:
            raise InputError(f"{self.path}:{referrer.line_no}: {referrer.key} refers to /{kind} {cid}, "
                             f"which is not in the file")
        return self.cards[(kind, cid)]

    def part_cards(self, pid):
        """The /PART card of part pid and the /PROP and /MAT cards it refers to."""
        part = self.cards[("PART", pid)]
        try:
            prop_id, mat_id = int(part.lines[1][0:10]), int(part.lines[1][10:20])
        except (IndexError, ValueError):
            raise InputError(f"{self.path}:{part.line_no}: {part.key}: second line is not property id + "
                             f"material id in 10 columns") from None
        return part, self.card("PROP", prop_id, part), self.card("MAT", mat_id, part)

    def element_nodes(self, kind, pid, first, count):
        """Node ids of each element of /kind/pid (count 10-column fields from column first)."""
        rows = []
        for line_no, text in self.elements.get((kind, pid), []):
            try:
                rows.append([int(text[c:c + 10]) for c in range(first, first + 10 * count, 10)])
            except ValueError:
                raise InputError(f"{self.path}:{line_no}: /{kind}/{pid}: expected {count} node ids "
                                 f"in 10-column fields: '{text}'") from None
        return rows

    def node(self, nid, where):
        if nid not in self.nodes:
            raise InputError(f"{self.path}: {where} uses node {nid}, which is not in /NODE")
        return self.nodes[nid]


def read_model(path):
    """The model include: nodes, /MAT /PROP /PART /RBODY /GRNOD/NODE cards and the element
    lines per part."""
    try:
        with open(path) as f:
            text = f.read().splitlines()
    except OSError as e:
        raise InputError(f"{path}: cannot read the model deck ({e.strerror})") from None
    model = Model(path, {}, {}, {})
    block, card, elements = None, None, None
    for line_no, line in enumerate(text, 1):
        if line.startswith("#"):
            continue
        if line.startswith("/"):
            key = line.strip()
            fields = key.split("/")
            block, card, elements = fields[1], None, None
            if block == "GRNOD" and fields[2:3] != ["NODE"]:
                block = None  # other group kinds: not needed here
            if block in ("MAT", "PROP", "PART", "RBODY", "GRNOD", "SH3N", "SHELL", "BRICK"):
                try:
                    cid = int(fields[-1])
                except ValueError:
                    raise InputError(f"{path}:{line_no}: '{key}' does not end in an id") from None
                if block in ("MAT", "PROP", "PART", "RBODY", "GRNOD"):
                    card = model.cards[(block, cid)] = Card(key, [], line_no)
                else:
                    elements = model.elements.setdefault((block, cid), [])
            continue
        if card is not None:
            card.lines.append(line)
        elif elements is not None and line.strip():
            elements.append((line_no, line))
        elif block == "NODE" and line.strip():
            try:
                model.nodes[int(line[0:10])] = (float(line[10:30]), float(line[30:50]), float(line[50:70]))
            except ValueError:
                raise InputError(f"{path}:{line_no}: /NODE line is not id + 3 coordinates "
                                 f"in 10/20/20/20 columns: '{line}'") from None
    if not model.nodes:
        raise InputError(f"{path}: no /NODE block")
    return model


# ---------------------------------------------------------------- specimens
@dataclass
class Specimen:
    name: str             # deck and run name
    header: list          # comment lines for the deck
    part_title: str
    nodes: dict           # id -> (x, y, z) in the test frame
    triangles: list       # (element id, n1, n2, n3, thickness)
    prop_card: Card
    mat_card: Card
    posterior_nodes: list
    anterior_nodes: list
    stroke_mm: float
    chord_mm: float


def cut_rib(model, level, stroke_mm):
    """Rib `level` of the model's right side in the test frame (module docstring)."""
    pid = model.part_id(f"rib_{level:02d}")
    part, prop_card, mat_card = model.part_cards(pid)

    triangles = []
    y_sign = -1.0  # the model's right side is y < 0
    for line_no, text in model.elements.get(("SH3N", pid), []):
        try:
            eid, a, b, c = (int(text[k:k + 10]) for k in range(0, 40, 10))
            thickness = float(text[80:100]) if text[80:100].strip() else 0.0
        except ValueError:
            raise InputError(f"{model.path}:{line_no}: /SH3N/{pid}: expected id, 3 nodes (10 columns each) "
                             f"and a thickness in columns 81-100: '{text}'") from None
        if all(y_sign * model.node(n, f"/SH3N/{pid} line {line_no}")[1] > 0 for n in (a, b, c)):
            triangles.append((eid, a, b, c, thickness))
    if not triangles:
        raise InputError(f"{model.path}: part {pid} rib_{level:02d} has no /SH3N triangles on the {SIDE} side")
    rib_nodes = sorted({n for t in triangles for n in t[1:4]})

    vertebra = {n for row in model.element_nodes("BRICK", model.part_id(VERTEBRA_PART), 10, 8) for n in row}
    cartilage_id = model.part_id(CARTILAGE_PART)
    cartilage = ({n for row in model.element_nodes("SH3N", cartilage_id, 10, 3) for n in row}
                 | {n for row in model.element_nodes("SHELL", cartilage_id, 10, 4) for n in row})
    posterior = [n for n in rib_nodes if n in vertebra]
    anterior = [n for n in rib_nodes if n in cartilage]
    if not posterior or not anterior:
        raise InputError(f"{model.path}: rib_{level:02d} ({SIDE}): {len(posterior)} nodes shared with "
                         f"{VERTEBRA_PART}, {len(anterior)} with {CARTILAGE_PART}; both pots need nodes")
    if max(model.nodes) >= POSTERIOR_MAIN:
        raise InputError(f"{model.path}: node ids reach {max(model.nodes)}; the pot main nodes "
                         f"{POSTERIOR_MAIN}, {ANTERIOR_MAIN} would clash")

    p = centroid([model.nodes[n] for n in posterior])
    a = centroid([model.nodes[n] for n in anterior])
    ez = best_fit_plane_normal([model.nodes[n] for n in rib_nodes])
    loading_line = sub(p, a)
    ex = unit(sub(loading_line, scale(ez, dot(loading_line, ez))))
    ey = cross(ez, ex)
    local = {n: tuple(dot(e, sub(model.nodes[n], p)) for e in (ex, ey, ez)) for n in rib_nodes}
    chord = math.sqrt(dot(loading_line, loading_line))
    name = f"rib{level:02d}_{SIDE}"
    header = [f"Isolated rib AP bending, Kindig 2009 set-up, written by {TOOL}",
              f"rib {level} {SIDE} side (part {pid}) of {in_repo(model.path)}",
              "frame: X anterior->posterior pot, Z = rib-plane normal",
              f"chord {chord:.1f} mm, {len(triangles)} triangles"]
    return Specimen(name, header, f"rib_{level:02d}_{SIDE}", local, triangles, prop_card, mat_card,
                    posterior, anterior, stroke_mm, chord)


@dataclass
class Ring:
    """Pinned-pinned half ring with a rib-like section (band height 13 mm, shell thickness 7 mm,
    E 3.6 GPa: about those of hbm50's rib 5), 12 x 1 cells like a model rib strip."""
    radius_mm: float = 83.0
    height_mm: float = 13.0
    thickness_mm: float = 7.0
    modulus_gpa: float = 3.6
    density: float = 4.9e-7  # kg/mm^3
    poisson: float = 0.3
    cells_along: int = 12
    stroke_mm: float = 6.0  # past the end of the stiffness fit

    def analytic_stiffness(self):
        """End-to-end stiffness [N/mm]: delta = pi F R^3 / (2 E I), I = h t^3 / 12 (in-plane bending)."""
        inertia = self.height_mm * self.thickness_mm ** 3 / 12.0
        return 2.0 * self.modulus_gpa * 1e3 * inertia / (math.pi * self.radius_mm ** 3)

    def specimen(self):
        """The ring in the XY plane, ends on the X axis: anterior end at x = -R, posterior at +R."""
        grid, nodes = {}, {}
        for i in range(self.cells_along + 1):
            angle = math.pi * (1.0 - i / self.cells_along)
            for j in (0, 1):
                nid = len(nodes) + 1
                grid[(i, j)] = nid
                nodes[nid] = (self.radius_mm * math.cos(angle), self.radius_mm * math.sin(angle),
                              self.height_mm * (j - 0.5))
        triangles = []
        for i in range(self.cells_along):
            a, b, c, d = grid[(i, 0)], grid[(i + 1, 0)], grid[(i + 1, 1)], grid[(i, 1)]
            triangles += [(2 * i + 1, a, b, c, self.thickness_mm), (2 * i + 2, a, c, d, self.thickness_mm)]
        posterior = [grid[(self.cells_along, j)] for j in (0, 1)]
        anterior = [grid[(0, j)] for j in (0, 1)]
        p = centroid([nodes[n] for n in posterior])
        local = {n: sub(x, p) for n, x in nodes.items()}
        mat = Card("/MAT/LAW1/1", ["ring", f"{self.density:20.10E}",
                                   f"{self.modulus_gpa:20.10E}{self.poisson:20.10E}"], 0)
        # the fields of hbm50's rib property cards
        prop = Card("/PROP/TYPE1/1", ["ring shell (as rib props)", "         4                   2", "",
                                      "         3                             1"], 0)
        header = [f"analytic check written by {TOOL}: half ring R {self.radius_mm:g} h {self.height_mm:g} "
                  f"t {self.thickness_mm:g} E {self.modulus_gpa:g}, {self.cells_along} x 1 cells"]
        return Specimen("ring", header, "ring", local, triangles, prop, mat, posterior, anterior,
                        self.stroke_mm, 2.0 * self.radius_mm)


# ---------------------------------------------------------------- deck writer
def ids_in_rows_of_10(ids):
    ids = list(ids)
    return ["".join(f"{i:10d}" for i in ids[k:k + 10]) for k in range(0, len(ids), 10)]


def node_line(nid, x):
    return f"{nid:10d}{x[0]:20.10E}{x[1]:20.10E}{x[2]:20.10E}"


class DriveSchedule:
    """End time and velocity ramp of a test driven at `speed` over `stroke_mm`: the
    velocity ramps up linearly over the first RAMP_STROKE_MM of stroke."""

    def __init__(self, stroke_mm, speed):
        self.ramp_ms = 2.0 * RAMP_STROKE_MM / speed
        self.tstop = stroke_mm / speed + self.ramp_ms / 2.0  # the ramp covers half the stroke of full speed

    def funct_lines(self, funct_id):
        """/FUNCT card of the ramp (0 -> 1 over ramp_ms, then 1)."""
        return [f"/FUNCT/{funct_id}", "velocity ramp", f"{0.0:20.10E}{0.0:20.10E}", f"{self.ramp_ms:20.10E}{1.0:20.10E}",
                f"{max(10 * self.tstop, 1000.0):20.10E}{1.0:20.10E}"]


def starter_head(name, header):
    """First lines of a starter deck: comments, /BEGIN (units kg, mm, ms), /NODE."""
    lines = ["#RADIOSS STARTER"] + ["# " + h for h in header]
    return lines + ["/BEGIN", name, "      2024         0", f"{'kg':>20}{'mm':>20}{'ms':>20}",
                    f"{'kg':>20}{'mm':>20}{'ms':>20}", "/NODE"]


def write_deck_pair(folder, name, starter_lines, schedule, speed, print_every):
    """Writes NAME_0000.rad (the given lines) and NAME_0001.rad (end time, time histories
    every SAMPLE_STROKE_MM of stroke, the fixed step of the whole-model runs); returns the
    starter path."""
    os.makedirs(folder, exist_ok=True)
    starter = os.path.join(folder, name + "_0000.rad")
    with open(starter, "w") as f:
        f.write("\n".join(starter_lines) + "\n")
    engine = ["#RADIOSS ENGINE", f"/RUN/{name}/1", f"{schedule.tstop:g}", "/TFILE/4", f"{SAMPLE_STROKE_MM / speed:g}",
              f"/PRINT/-{print_every}", "# fixed step 1.5 us with nodal mass scaling, as the whole model is run",
              "/DT/NODA/CST/0", f"0.9 {FIXED_STEP_MS:g}", "/DT/SHELL/CST", f"0.9 {FIXED_STEP_MS:g}"]
    with open(os.path.join(folder, name + "_0001.rad"), "w") as f:
        f.write("\n".join(engine) + "\n")
    return starter


def write_deck(folder, spec, speed):
    """Starter and engine files of the test (module docstring); returns the starter path."""
    schedule = DriveSchedule(spec.stroke_mm, speed)
    lines = starter_head(spec.name, spec.header)
    lines += [node_line(n, spec.nodes[n]) for n in sorted(spec.nodes)]
    lines.append(node_line(POSTERIOR_MAIN, centroid([spec.nodes[n] for n in spec.posterior_nodes])))
    lines.append(node_line(ANTERIOR_MAIN, centroid([spec.nodes[n] for n in spec.anterior_nodes])))
    for card in (spec.mat_card, spec.prop_card):  # copied verbatim, ids kept
        lines += [card.key] + card.lines
    prop_id, mat_id = int(spec.prop_card.key.split("/")[-1]), int(spec.mat_card.key.split("/")[-1])
    lines += ["/PART/1", spec.part_title, f"{prop_id:10d}{mat_id:10d}{0:10d}", "/SH3N/1"]
    for eid, a, b, c, t in spec.triangles:
        lines.append(f"{eid:10d}{a:10d}{b:10d}{c:10d}{'':20}{'':20}{(f'{t:.6f}' if t > 0 else ''):>20}")
    for gid, title, ids in ((1, "posterior pot nodes", spec.posterior_nodes), (2, "anterior pot nodes", spec.anterior_nodes),
                            (3, "posterior pot main", [POSTERIOR_MAIN]), (4, "anterior pot main", [ANTERIOR_MAIN])):
        lines += [f"/GRNOD/NODE/{gid}", title] + ids_in_rows_of_10(ids)
    # pots: main node moved to the centre of gravity of the pot nodes (ICoG 1), unit inertia added
    for rid, main, group, title in ((1, POSTERIOR_MAIN, 1, "posterior pot"), (2, ANTERIOR_MAIN, 2, "anterior pot")):
        lines += [f"/RBODY/{rid}", title,
                  f"{main:10d}{0:10d}{0:10d}{0:10d}{0.0:20.6E}{group:10d}{0:10d}{1:10d}{0:10d}",
                  f"{1.0:20.6E}{1.0:20.6E}{1.0:20.6E}"]
    lines += ["/BCS/1", "posterior pot: translations fixed, free rotation about the rib-plane normal (Z)",
              f"   111 110{0:10d}{3:10d}",
              "/BCS/2", "anterior pot: Y Z fixed, free rotation about Z, X driven",
              f"   011 110{0:10d}{4:10d}"]
    lines += schedule.funct_lines(1)
    lines += ["/IMPVEL/1", "anterior pot towards the posterior pot", f"{1:10d}{'X':>10}{0:10d}{0:10d}{4:10d}",
              f"{1.0:20.10E}{speed:20.10E}{0.0:20.10E}{0.0:20.10E}"]
    lines += ["/TH/RBODY/1", "pots", "".join(f"{c:>10}" for c in ("FX", "FY", "FZ", "MX", "MY", "MZ", "KE")),
              f"{1:10d}{2:10d}",
              "/TH/NODE/2", "pot main nodes", "".join(f"{c:>10}" for c in ("DX", "DY", "DZ")),
              f"{POSTERIOR_MAIN:10d}{0:10d}posterior", f"{ANTERIOR_MAIN:10d}{0:10d}anterior",
              "/TH/PART/3", spec.part_title, "".join(f"{c:>10}" for c in ("IE", "KE", "HE", "ER")), f"{1:10d}",
              "/END"]
    return write_deck_pair(folder, spec.name, lines, schedule, speed, 2000)


# ---------------------------------------------------------------- solver run and time histories
@dataclass
class RunResult:
    displacement: list   # end-to-end shortening [mm]
    force: list          # posterior pot reaction along X [N]
    termination: str
    max_energy_error: float  # largest |energy error| over the run, fraction
    wall_s: float
    deleted: list = None     # deleted rib elements at each sample (/TH/PART ER)

    def first_fracture(self):
        """(displacement mm, force N just before) at the first element deletion, or None: the
        rib fracture model (hbm-deckgen --rib-fracture) deletes a rib element where it breaks."""
        if not self.deleted:
            return None
        for i, n in enumerate(self.deleted):
            if n > 0:
                return self.displacement[i], max(self.force[:i + 1])
        return None


UNIT_FACTORS = {("kN", "N"): 1e3, ("N", "N"): 1.0, ("mm", "mm"): 1.0, ("m", "mm"): 1e3,
                ("ms", "ms"): 1.0, ("s", "ms"): 1e3, ("-", "-"): 1.0}


def read_time_history(path):
    """Columns of a solver /TH CSV file: {'name': (unit, values)} from headers 'name [unit]'."""
    try:
        with open(path) as f:
            rows = [line.rstrip("\n").split(",") for line in f if line.strip()]
    except OSError as e:
        raise InputError(f"{path}: cannot read the solver's time history ({e.strerror})") from None
    if len(rows) < 2:
        raise InputError(f"{path}: no data rows")
    columns = {}
    for k, head in enumerate(rows[0]):
        name, _, unit = head.strip().rpartition(" [")
        if not name or not unit.endswith("]"):
            raise InputError(f"{path}:1: column header '{head}' is not 'name [unit]'")
        try:
            columns[name] = (unit[:-1], [float(r[k]) for r in rows[1:]])
        except (ValueError, IndexError):
            bad = next(i for i, r in enumerate(rows[1:], 2) if len(r) <= k or not is_number(r[k]))
            raise InputError(f"{path}:{bad}: column '{head}' is not a number") from None
    return columns


def is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def channel(columns, path, name, unit):
    if name not in columns:
        raise InputError(f"{path}: no column '{name} [...]'; columns: {', '.join(columns)}")
    have, values = columns[name]
    if (have, unit) not in UNIT_FACTORS:
        raise InputError(f"{path}: column '{name}' is in [{have}], expected a unit convertible to [{unit}]")
    factor = UNIT_FACTORS[(have, unit)]
    return [v * factor for v in values]


def run_hbm_solver(solver, starter):
    """Runs hbm-solver on the deck (one thread) into the folder out/ beside it; its printed
    output is kept there in solver_output.txt. Returns (out folder, termination line, wall
    time in s); InputError when the solver cannot be run or does not end normally."""
    out = os.path.join(os.path.dirname(starter), "out")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    start = time.monotonic()
    try:
        r = subprocess.run([solver, starter, "--out", out, "--threads", "1"], capture_output=True, text=True)
    except OSError as e:
        raise InputError(f"{solver}: cannot run the solver ({e.strerror})") from None
    wall = time.monotonic() - start
    listing = os.path.join(out, "solver_output.txt")
    with open(listing, "w") as f:
        f.write(r.stdout + r.stderr)
    ends = [line.strip() for line in r.stdout.splitlines() if line.strip().endswith("TERMINATION")
            or "TERMINATION:" in line]
    termination = ends[-1] if ends else "no termination line"
    if r.returncode != 0 or termination != "NORMAL TERMINATION":
        tail = "\n  ".join((r.stdout + r.stderr).strip().splitlines()[-8:]) or "(no output)"
        raise InputError(f"{listing}: hbm-solver on {starter} exited {r.returncode} ({termination}):\n  {tail}")
    return out, termination, wall


def run_solver(solver, starter, spec):
    """Runs hbm-solver on the deck and reads the pot force and the end-to-end displacement
    from its /TH/RBODY and /TH/NODE files."""
    out, termination, wall = run_hbm_solver(solver, starter)
    rbody_csv = os.path.join(out, f"{spec.name}_TH_RBODY_1.csv")
    node_csv = os.path.join(out, f"{spec.name}_TH_NODE_2.csv")
    rbody, nodes = read_time_history(rbody_csv), read_time_history(node_csv)
    t_force = channel(rbody, rbody_csv, "time", "ms")
    force = channel(rbody, rbody_csv, "rbody 1 posterior pot FX", "N")
    error = channel(rbody, rbody_csv, "energy error", "-")
    if channel(nodes, node_csv, "time", "ms") != t_force:  # the solver writes all histories on the same cycles
        raise InputError(f"{node_csv}: its times differ from those of {rbody_csv}")
    anterior = channel(nodes, node_csv, f"node {ANTERIOR_MAIN} anterior DX", "mm")
    posterior = channel(nodes, node_csv, f"node {POSTERIOR_MAIN} posterior DX", "mm")
    shortening = [xa - xp for xa, xp in zip(anterior, posterior)]
    part_csv = os.path.join(out, f"{spec.name}_TH_PART_3.csv")
    parts = read_time_history(part_csv)
    if channel(parts, part_csv, "time", "ms") != t_force:
        raise InputError(f"{part_csv}: its times differ from those of {rbody_csv}")
    deleted = channel(parts, part_csv, f"part 1 {spec.part_title} ER", "-")
    return RunResult(shortening, force, termination, max(abs(e) for e in error), wall, deleted)


# ---------------------------------------------------------------- curve arithmetic
def interpolate(x, xs, ys):
    """y at x on the polyline through (xs, ys), xs non-decreasing; None beyond its ends."""
    if not xs or x < xs[0] or x > xs[-1]:
        return None
    i = bisect.bisect_left(xs, x)
    if i == 0 or xs[i] == x:
        return ys[i]
    return ys[i - 1] + (ys[i] - ys[i - 1]) * (x - xs[i - 1]) / (xs[i] - xs[i - 1])


def fitted_slope(xs, ys, lo, hi):
    """Least-squares slope of the points with lo <= x <= hi."""
    pts = [(x, y) for x, y in zip(xs, ys) if lo <= x <= hi]
    if len(pts) < 2:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx if sxx > 0 else None


def polygon_edges(polygon):
    return zip(polygon, polygon[1:] + polygon[:1])


def inside_polygon(x, y, polygon):
    """Even-odd ray casting: is (x, y) inside the closed polygon?"""
    inside = False
    for (x1, y1), (x2, y2) in polygon_edges(polygon):
        if (y1 > y) != (y2 > y) and x < x1 + (x2 - x1) * (y - y1) / (y2 - y1):
            inside = not inside
    return inside


def polygon_range_at(x, polygon):
    """Lowest and highest y where the vertical line through x cuts the polygon (None if it misses)."""
    ys = [y1 + (y2 - y1) * (x - x1) / (x2 - x1)
          for (x1, y1), (x2, y2) in polygon_edges(polygon) if (x1 - x) * (x2 - x) <= 0 and x1 != x2]
    return (min(ys), max(ys)) if ys else None


# ---------------------------------------------------------------- Kindig data
@dataclass
class KindigRib:
    average: list   # (displacement mm, force N)
    corridor: list  # closed polygon of (displacement mm, force N)
    source_lines: list  # '# KEY: value' header lines of the average file


def read_curve_csv(path):
    """Two-column CSV of displacement [mm], force [N] after '#' header lines and a column-name
    row; rows with an empty cell (columns of unequal length) are skipped."""
    try:
        with open(path) as f:
            text = f.read().splitlines()
    except OSError as e:
        raise InputError(f"{path}: cannot read the Kindig file ({e.strerror})") from None
    comments = [line for line in text if line.startswith("#")]
    points, header_seen = [], False
    for line_no, line in enumerate(text, 1):
        if line.startswith("#") or not line.strip():
            continue
        cells = [c.strip() for c in line.split(",")]
        if not header_seen:
            header_seen = True
            if not (cells[0].startswith("displacement") and len(cells) > 1 and cells[1].startswith("force")):
                raise InputError(f"{path}:{line_no}: expected the column names 'displacement_mm,force_N', "
                                 f"found '{line}'")
            continue
        if len(cells) < 2 or not cells[0] or not cells[1]:
            continue
        try:
            points.append((float(cells[0]), float(cells[1])))
        except ValueError:
            raise InputError(f"{path}:{line_no}: '{line}' is not displacement, force") from None
    if len(points) < 3:
        raise InputError(f"{path}: {len(points)} data rows, expected a curve")
    return points, comments


def read_kindig(folder, level):
    avg_path = os.path.join(folder, f"Rib{level}_Kindig_avg.csv")
    cor_path = os.path.join(folder, f"Rib{level}_Kindig_cor.csv")
    average, comments = read_curve_csv(avg_path)
    corridor, _ = read_curve_csv(cor_path)
    return KindigRib(average, corridor, comments)


# ---------------------------------------------------------------- comparison
@dataclass
class RibComparison:
    level: int
    spec: Specimen
    run: RunResult
    kindig: KindigRib

    def at(self, x):
        """(model force, Kindig average, corridor (lo, hi) or None, model inside corridor or None)."""
        model = interpolate(x, self.run.displacement, self.run.force)
        average = interpolate(x, [p[0] for p in self.kindig.average], [p[1] for p in self.kindig.average])
        band = polygon_range_at(x, self.kindig.corridor)
        inside = inside_polygon(x, model, self.kindig.corridor) if band and model is not None else None
        return model, average, band, inside

    def stiffness(self):
        model = fitted_slope(self.run.displacement, self.run.force, *STIFFNESS_FIT_MM)
        kindig = fitted_slope([p[0] for p in self.kindig.average], [p[1] for p in self.kindig.average],
                              *STIFFNESS_FIT_MM)
        return model, kindig


def fmt(value, spec, missing="-"):
    return missing if value is None else format(value, spec)


def ratio(a, b):
    return a / b if a is not None and b not in (None, 0.0) else None


def yes_no(flag):
    return "-" if flag is None else ("yes" if flag else "no")


def corridor_text(band):
    return f"{band[0]:.1f}-{band[1]:.1f}" if band else "-"


def print_rib_table(c):
    r = c.run
    print(f"rib {c.level} ({SIDE}, {c.spec.part_title}, chord {c.spec.chord_mm:.1f} mm, {len(c.spec.triangles)} "
          f"triangles): {r.termination}, max |energy error| {100 * r.max_energy_error:.2f} %, "
          f"solver {r.wall_s:.1f} s")
    print(f"  {'d [mm]':>6} {'model [N]':>10} {'Kindig [N]':>10} {'ratio':>6} {'corridor [N]':>14} {'in corridor':>11}")
    for x in COMPARE_AT_MM:
        model, average, band, inside = c.at(x)
        print(f"  {x:6.0f} {fmt(model, '10.1f'):>10} {fmt(average, '10.1f'):>10} "
              f"{fmt(ratio(model, average), '6.2f'):>6} {corridor_text(band):>14} {yes_no(inside):>11}")
    km, kk = c.stiffness()
    print(f"  initial stiffness (fit {STIFFNESS_FIT_MM[0]:g}-{STIFFNESS_FIT_MM[1]:g} mm): model {fmt(km, '.2f')} "
          f"N/mm, Kindig {fmt(kk, '.2f')} N/mm, ratio {fmt(ratio(km, kk), '.2f')}")
    print(f"  {fracture_text(c)}")


def fracture_text(c):
    """The model's first element deletion against the end of Kindig's average curve (the
    tests' mean displacement and force at fracture, where the average stops)."""
    end_d, end_f = c.kindig.average[-1]
    f = c.run.first_fracture()
    model = f"model breaks at d {f[0]:.1f} mm, peak {f[1]:.1f} N" if f else "model does not break (elastic ribs, or not within the stroke)"
    return f"fracture: {model}; Kindig average ends at d {end_d:.1f} mm, {end_f:.1f} N"


def mean(values):
    values = [v for v in values if v is not None]
    return sum(values) / len(values) if values else None


def print_summary(comparisons):
    parts = [f"F{x:g} {fmt(mean([ratio(*c.at(x)[:2]) for c in comparisons]), '.2f')}" for x in COMPARE_AT_MM]
    k = fmt(mean([ratio(*c.stiffness()) for c in comparisons]), ".2f")
    print(f"mean model/Kindig ratio over ribs {' '.join(str(c.level) for c in comparisons)}: "
          f"{' '.join(parts)} k0 {k}")


# ---------------------------------------------------------------- analytic checks
@dataclass
class AnalyticCheck:
    """A specimen with a closed-form stiffness (`shape`: .specimen(), .analytic_stiffness())
    run through the solver: the fitted model stiffness against the formula."""
    shape: object
    run: RunResult
    model_k: float
    analytic_k: float
    tolerance: float

    @property
    def deviation(self):
        return self.model_k / self.analytic_k - 1.0

    @property
    def passed(self):
        return abs(self.deviation) <= self.tolerance


def run_analytic_check(run_specimen, work, shape, tolerance, fit_mm):
    """run_specimen(spec) writes the specimen's decks under `work`, runs them and returns the
    tool's RunResult (displacement, force); the stiffness is fitted over fit_mm (lo, hi)."""
    spec = shape.specimen()
    run = run_specimen(spec)
    model_k = fitted_slope(run.displacement, run.force, *fit_mm)
    if model_k is None:
        raise InputError(f"{work}/{spec.name}: the run has no points between {fit_mm[0]:g} and {fit_mm[1]:g} mm")
    return AnalyticCheck(shape, run, model_k, shape.analytic_stiffness(), tolerance)


def check_ring(solver, work, speed):
    return run_analytic_check(
        lambda spec: run_solver(solver, write_deck(os.path.join(work, spec.name), spec, speed), spec), work, Ring(),
        RING_TOLERANCE, STIFFNESS_FIT_MM)


def describe_ring(check):
    g = check.shape
    return (f"Half ring R {g.radius_mm:g} mm, h {g.height_mm:g} mm, t {g.thickness_mm:g} mm, E {g.modulus_gpa:g} GPa, "
            f"{g.cells_along} x 1 cells: model k {check.model_k:.3f} N/mm (fit {STIFFNESS_FIT_MM[0]:g}-"
            f"{STIFFNESS_FIT_MM[1]:g} mm) vs 2 E I / (pi R^3) = {check.analytic_k:.3f} N/mm "
            f"(pi R^3 / (2 E I) = {1 / check.analytic_k:.4f} mm/N): {100 * check.deviation:+.2f} % "
            f"(limit +-{100 * RING_TOLERANCE:g} %); {check.run.termination}, max |energy error| "
            f"{100 * check.run.max_energy_error:.2f} %")


# ---------------------------------------------------------------- report
def file_digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()[:12]


def in_repo(path):
    """The path relative to the repository root (as the report should read on any checkout)."""
    return os.path.relpath(os.path.abspath(path), REPO_ROOT)


def write_report(path, args, comparisons, ring_check):
    lines = [f"<!-- Generated by {TOOL}; do not edit. Command: {shlex.join(sys.argv)} -->",
             "# Isolated-rib anterior-posterior bending against Kindig 2009", ""]
    if comparisons:
        lines += [f"Model `{in_repo(args.model)}` (sha256 {file_digest(args.model)}), {SIDE} ribs, driven at "
                  f"{args.speed:g} mm/ms. Force = posterior pot reaction, d = end-to-end shortening; "
                  f"ratio = model / Kindig average; corridor = where the line d = const cuts Kindig's "
                  f"corridor polygon; in corridor = the model point (d, F) lies inside that polygon.", "",
                  "| rib | d [mm] | model [N] | Kindig avg [N] | ratio | corridor [N] | in corridor |",
                  "|---:|---:|---:|---:|---:|---:|:---:|"]
        for c in comparisons:
            for x in COMPARE_AT_MM:
                model, average, band, inside = c.at(x)
                lines.append(f"| {c.level} | {x:g} | {fmt(model, '.1f')} | {fmt(average, '.1f')} | "
                             f"{fmt(ratio(model, average), '.2f')} | {corridor_text(band)} | {yes_no(inside)} |")
        lines += ["", f"Initial stiffness: least-squares slope over d = {STIFFNESS_FIT_MM[0]:g}-"
                  f"{STIFFNESS_FIT_MM[1]:g} mm.", "",
                  "| rib | chord [mm] | triangles | k model [N/mm] | k Kindig [N/mm] | ratio | termination | "
                  "max energy error |",
                  "|---:|---:|---:|---:|---:|---:|---|---:|"]
        for c in comparisons:
            km, kk = c.stiffness()
            lines.append(f"| {c.level} | {c.spec.chord_mm:.1f} | {len(c.spec.triangles)} | {fmt(km, '.2f')} | "
                         f"{fmt(kk, '.2f')} | {fmt(ratio(km, kk), '.2f')} | {c.run.termination} | "
                         f"{100 * c.run.max_energy_error:.2f} % |")
        lines += ["", "Fracture (the rib fracture model, `hbm-deckgen --rib-fracture AGE`, deletes a rib element where "
                  "it breaks; Kindig's average curve ends at the tests' mean fracture):", ""]
        lines += [f"- rib {c.level}: {fracture_text(c)}" for c in comparisons]
        lines.append("")
    if ring_check:
        lines += ["## Method check: half ring", "", describe_ring(ring_check) + ".", ""]
    lines += ["## Method", "",
              f"For each rib, `{TOOL}` cuts the triangles of part `rib_NN` on the {SIDE} side out of the "
              "model (thicknesses, property and material cards copied verbatim) into a standalone deck:",
              "",
              "- frame: origin at the posterior pot, X from the anterior to the posterior pot (the loading "
              "line), Z the normal of the rib's least-squares plane;",
              f"- posterior pot: rigid body on the rib nodes shared with `{VERTEBRA_PART}`, translations "
              "and rotations about X and Y fixed, free about Z; anterior pot: rigid body on the rib nodes "
              f"shared with `{CARTILAGE_PART}`, Y and Z fixed, free about Z, driven along +X;",
              f"- velocity ramped up over the first {RAMP_STROKE_MM:g} mm, stroke {STROKE_FACTOR:g} x the end of "
              f"Kindig's average; fixed {FIXED_STEP_MS * 1e3:g} us step with nodal mass scaling (as the whole "
              "model runs); hbm-solver on one thread;",
              "- method check (`--check-ring`): a pinned-pinned half ring of a rib-like section through the same "
              "pots and solver against delta = pi F R^3 / (2 E I).", "",
              "## Sources", "",
              "- Kindig MW. Tolerance to failure and geometric influences on the stiffness of human ribs under "
              "anterior-posterior loading. MSc thesis, University of Virginia, 2009."]
    if comparisons:
        source = [s[2:] for s in comparisons[0].kindig.source_lines if s.startswith(("# SOURCE", "# LOAD CASE", "# TEST SETUP"))]
        lines += [f"- {s}" for s in source]
        lines.append(f"- Files: `{in_repo(args.kindig)}/RibN_Kindig_avg.csv` (average) and `RibN_Kindig_cor.csv` "
                     "(corridor polygon).")
    write_report_lines(path, lines)


def write_report_lines(path, lines):
    """Writes the report's lines to path, creating its folder; whole or not at all (a
    temporary file beside it, renamed)."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, path)


# ---------------------------------------------------------------- main
class ArgumentParser(argparse.ArgumentParser):
    """argparse, but a bad command line exits 1 like every other input error."""

    def error(self, message):
        self.print_usage(sys.stderr)
        self.exit(1, f"{self.prog}: error: {message}\n")


def tool_argument_parser(doc):
    """The ArgumentParser of a component tool: its module docstring's first paragraph as the
    description, the rest kept as written."""
    return ArgumentParser(description=doc.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)


def positive_number(text):
    """argparse type: a finite number > 0 (a speed or a stroke that a deck can hold)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number") from None
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"'{text}' is not a finite number > 0")
    return value


def tool_main(parse_args, run, argv=None):
    """Command-line entry of a component tool: exit status of run(args), or 1 with the
    message of an InputError (bad input or a failed run)."""
    args = parse_args(argv)
    try:
        return run(args)
    except InputError as e:
        print(f"{os.path.basename(sys.argv[0])}: error: {e}", file=sys.stderr)
        return 1


def parse_args(argv):
    ap = tool_argument_parser(__doc__)
    ap.add_argument("--solver", required=True, help="hbm-solver executable")
    ap.add_argument("--model", help="body model include (decks/hbm50/hbm50.inc); needed to run ribs")
    ap.add_argument("--work", required=True, help="folder for the decks and runs")
    ap.add_argument("--ribs", nargs="+", type=int, help="rib levels (default 2-10; none with --check-ring alone)")
    ap.add_argument("--speed", type=positive_number, default=0.1, help="pot speed [mm/ms] (default 0.1, quasi-static)")
    ap.add_argument("--kindig", default=DEFAULT_KINDIG, help=f"Kindig 2009 files (default {DEFAULT_KINDIG})")
    ap.add_argument("--report", help="write a Markdown report here")
    ap.add_argument("--check-ring", action="store_true",
                    help=f"run the analytic half ring; fail if off by more than {100 * RING_TOLERANCE:g} %%")
    args = ap.parse_args(argv)
    if args.ribs is None and not args.check_ring:
        args.ribs = list(range(2, 11))
    if args.ribs and not args.model:
        ap.error("--model is needed to run ribs")
    return args


def run(args):
    specimens = []
    if args.ribs:
        model = read_model(args.model)
        for level in args.ribs:  # read every input before the first run
            kindig = read_kindig(args.kindig, level)
            stroke = STROKE_FACTOR * max(p[0] for p in kindig.average)
            specimens.append((level, cut_rib(model, level, stroke), kindig))
    ring_check = None
    if args.check_ring:
        ring_check = check_ring(args.solver, args.work, args.speed)
        print(f"{describe_ring(ring_check)}, solver {ring_check.run.wall_s:.1f} s")
    comparisons = []
    for level, spec, kindig in specimens:
        starter = write_deck(os.path.join(args.work, spec.name), spec, args.speed)
        comparisons.append(RibComparison(level, spec, run_solver(args.solver, starter, spec), kindig))
        print_rib_table(comparisons[-1])
    if len(comparisons) > 1:
        print_summary(comparisons)
    if args.report:
        write_report(args.report, args, comparisons, ring_check)
        print(f"report: {args.report}")
    if ring_check and not ring_check.passed:
        print(f"FAIL: half ring stiffness off by {100 * ring_check.deviation:+.2f} % "
              f"(limit +-{100 * RING_TOLERANCE:g} %)", file=sys.stderr)
        return 1
    return 0


def main(argv=None):
    return tool_main(parse_args, run, argv)


if __name__ == "__main__":
    sys.exit(main())
