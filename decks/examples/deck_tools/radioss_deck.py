# SPDX-License-Identifier: GPL-3.0-or-later
"""The one writer of the example decks in decks/examples/<case>/ (starter <case>_0000.rad
and engine <case>_0001.rad), used by every generator there (engine_tools, shell_tools,
springs_tools, contact_*/make_deck.py,
rigid_rwall_impact/make_deck.py).

Starter cards are in Radioss block format as docs/deck-format.md lists them and as the C++
deck writer (deck/src/deck_writer.cpp) writes them: integers right-aligned in 10 columns,
reals right-aligned in 20 columns (here with 13 significant digits), /BEGIN with the kg
mm ms units, /NODE right after /BEGIN; optional fields at the end of a line that a
generator does not set are left blank (the reader's default). Engine cards are free
format, numbers in their shortest exact text. A card whose title or field cannot be
written raises ValueError naming the deck and the card; files are written to a temporary
name and renamed when complete.
Units of the examples: kg, mm, ms (force kN, stress GPa, energy J)."""

import os

EXAMPLES = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

# /ANIM outputs of the solid cases (velocity, von Mises, plastic strain, added mass) and of
# the contact cases (velocity, contact force).
ANIM_SOLID = ("VECT/VEL", "ELEM/VONM", "ELEM/EPSP", "NODA/DMAS")
ANIM_CONTACT = ("VECT/VEL", "VECT/CONT")


def i10(v):
    text = f"{int(v):>10d}"
    if len(text) > 10:
        raise ValueError(f"integer {v} does not fit in 10 columns")
    return text


def f20(v):
    return f"{float(v):>20.12E}"


def t10(s):
    return f"{s:>10}"


def blank(n):
    return " " * n


def number(v):
    """Engine (free-format) number: integers as they are, reals in the shortest text that
    reads back exactly (Python's repr, the digits of C++ std::to_chars)."""
    return str(v) if isinstance(v, int) else repr(float(v))


def rows_of_ten(values, fmt=i10):
    """Id lists (/GRNOD, /SURF/PART, /TH objects) and TH variable names: 10 per line."""
    values = list(values)
    return ["".join(fmt(v) for v in values[k:k + 10]) for k in range(0, len(values), 10)]


def run_line(name):
    """Header line saying how to run example `name`."""
    return f"Run: hbm-solver decks/examples/{name}/{name}_0000.rad --out out/{name}"


def write_atomic(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


class Deck:
    """One example case: its starter cards (nodes kept apart and written first) and its
    engine cards. `header` lines become the comment block of the starter; its first line
    heads the engine file."""

    def __init__(self, name, header):
        self.name = name
        self.header = list(header)
        self.nodes = {}        # id -> (x, y, z), written sorted by id
        self.last_node = 0     # largest node id so far
        self.cards = []        # starter lines after /NODE
        self.engine_lines = []
        self.next_elem = 1     # automatic element ids (block, strips)
        self.ids = {}          # automatic ids by kind (next_id)

    # ---- ids and nodes
    def next_id(self, kind):
        self.ids[kind] = self.ids.get(kind, 0) + 1
        return self.ids[kind]

    def node(self, x, y, z, nid=None):
        """Adds a node; without `nid` it takes the id after the largest so far."""
        if nid is None:
            nid = self.last_node + 1
        if nid in self.nodes:
            raise ValueError(f"{self.name}: node {nid} defined twice")
        self.nodes[nid] = (x, y, z)
        self.last_node = max(self.last_node, nid)
        return nid

    def block(self, nx, ny, nz, size, origin=(0.0, 0.0, 0.0), first_node=None, first_elem=None, warp=None):
        """Structured brick block of nx x ny x nz elements over the box `size` = (lx, ly,
        lz) from `origin`; node ids i fastest, then j, then k, from `first_node` (or the
        next free id); element ids from `first_elem` (or self.next_elem). `warp(i, j, k,
        x, y, z)` may move the nodes. Returns (grid {(i, j, k): node id}, [(element id,
        8 nodes)]), the grid in node id order."""
        lx, ly, lz = size
        if first_elem is not None:
            self.next_elem = first_elem
        grid = {}
        for k in range(nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    x, y, z = origin[0] + lx * i / nx, origin[1] + ly * j / ny, origin[2] + lz * k / nz
                    if warp:
                        x, y, z = warp(i, j, k, x, y, z)
                    nid = None if first_node is None else first_node + len(grid)
                    grid[(i, j, k)] = self.node(x, y, z, nid)
        elems = []
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    ns = [grid[(i, j, k)], grid[(i + 1, j, k)], grid[(i + 1, j + 1, k)], grid[(i, j + 1, k)],
                          grid[(i, j, k + 1)], grid[(i + 1, j, k + 1)], grid[(i + 1, j + 1, k + 1)],
                          grid[(i, j + 1, k + 1)]]
                    elems.append((self.next_elem, ns))
                    self.next_elem += 1
        return grid, elems

    def card(self, keyword, title=None, lines=()):
        if title is not None and (len(title) > 100 or title[:1] in ("/", "#") or "\n" in title):
            raise ValueError(f"{self.name}: {keyword} title '{title}' is longer than 100 columns, "
                             "starts with / or # or holds a line break")
        for line in lines:
            if line[:1] in ("/", "#"):
                raise ValueError(f"{self.name}: {keyword} data line '{line}' would read as a keyword or comment")
        self.cards.append(keyword)
        if title is not None:
            self.cards.append(title)
        self.cards.extend(lines)

    # ---- elements
    def bricks(self, part, elems):  # elems: (id, [8 nodes])
        self.card(f"/BRICK/{part}", None, [i10(e) + "".join(i10(n) for n in ns) for e, ns in elems])

    def tetras(self, part, elems):  # elems: (id, [4 nodes])
        self.card(f"/TETRA4/{part}", None, [i10(e) + "".join(i10(n) for n in ns) for e, ns in elems])

    def shells(self, part, elems):
        """4-node elements as /SHELL, 3-node ones as /SH3N (one kind per call)."""
        kw = "/SH3N" if elems and len(elems[0][1]) == 3 else "/SHELL"
        self.card(f"{kw}/{part}", None, [i10(e) + "".join(i10(n) for n in ns) for e, ns in elems])

    def springs(self, part, pairs):
        """/SPRING elements n1-n2 with automatic ids; returns the ids."""
        ids = [self.next_id("spring") for _ in pairs]
        self.card(f"/SPRING/{part}", None, [i10(s) + i10(a) + i10(b) for s, (a, b) in zip(ids, pairs)])
        return ids

    # ---- parts, properties, materials
    def part(self, pid, title, prop, mat):
        self.card(f"/PART/{pid}", title, [i10(prop) + i10(mat) + i10(0)])

    def prop_solid(self, pid, title, isolid=0, qa=1.1, qb=0.05, h=0.1):
        self.card(f"/PROP/TYPE14/{pid}", title, [i10(isolid), f20(qa) + f20(qb) + f20(h)])

    def prop_shell(self, pid, title, thick, n_points, ishell=0, hm=0.01, hf=0.01, hr=0.01, p_thick_fail=0.0,
                   ithick=0):
        """/PROP/TYPE1: Ishell, hourglass coefficients, N points, thickness, Ashear 5/6, Ithick, Iplas 1."""
        self.card(f"/PROP/TYPE1/{pid}", title, [
            i10(ishell) + i10(0) + i10(0) + i10(0) + i10(0) + blank(10) + f20(p_thick_fail),
            f20(hm) + f20(hf) + f20(hr) + f20(0) + f20(0),
            i10(n_points) + i10(0) + f20(thick) + f20(5.0 / 6.0) + blank(10) + i10(ithick) + i10(1)])

    @staticmethod
    def spring_dof(k=0.0, c=0.0, fct1=0, h=0, fct3=0):
        """The three lines of one spring DOF (/PROP/TYPE4, 8, 13): K C A B D, fct_id1 H
        fct_id2 fct_id3 fct_id4, F E Ascale Hscale (A = D = F = Ascale = Hscale = 1)."""
        return [f20(k) + f20(c) + f20(1.0) + f20(0.0) + f20(1.0),
                i10(fct1) + i10(h) + i10(0) + i10(fct3) + i10(0),
                f20(1.0) + f20(0.0) + f20(1.0) + f20(1.0)]

    def prop_spring4(self, pid, title, mass, dof):
        """/PROP/TYPE4: one translational DOF along n1-n2; `dof` from spring_dof."""
        self.card(f"/PROP/TYPE4/{pid}", title, [f20(mass) + i10(0) + i10(0) + i10(0)] + dof)

    def prop_spring6(self, kind, pid, title, mass, inertia, dofs):
        """/PROP/TYPE8 (general) or /PROP/TYPE13 (beam-type) spring: six DOF blocks."""
        if kind not in (8, 13) or len(dofs) != 6:
            raise ValueError(f"{self.name}: /PROP/TYPE{kind}/{pid}: a 6-DOF spring is TYPE8 or TYPE13 with 6 DOF blocks")
        line1 = f20(mass) + f20(inertia) + "".join(i10(0) for _ in range(6))
        self.card(f"/PROP/TYPE{kind}/{pid}", title, [line1] + [line for dof in dofs for line in dof])

    def law1(self, mid, title, rho, e, nu):
        self.card(f"/MAT/LAW1/{mid}", title, [f20(rho), f20(e) + f20(nu)])

    def law2(self, mid, title, rho, e, nu, a, b, n, epsmax=0.0):
        self.card(f"/MAT/LAW2/{mid}", title,
                  [f20(rho), f20(e) + f20(nu) + i10(0), f20(a) + f20(b) + f20(n) + f20(epsmax) + f20(0)])

    def law42(self, mid, title, rho, mu, alpha, sigma_cut=0.0):
        """/MAT/LAW42 (Ogden): nu and sigma_cut (0 = defaults 0.495, 1e30), no bulk function,
        no Prony terms; up to five (mu_p, alpha_p) pairs."""
        mu = list(mu) + [0.0] * (5 - len(mu))
        alpha = list(alpha) + [0.0] * (5 - len(alpha))
        self.card(f"/MAT/LAW42/{mid}", title, [
            f20(rho), f20(0.0) + f20(sigma_cut) + blank(10) + i10(0) + f20(0.0) + i10(0) + i10(0),
            "".join(f20(m) for m in mu), "".join(f20(a) for a in alpha)])

    def law34(self, mid, title, rho, bulk, g0, ginf, beta):
        self.card(f"/MAT/LAW34/{mid}", title, [f20(rho), f20(bulk), f20(g0) + f20(ginf) + f20(beta)])

    def law36(self, mid, title, rho, e, nu, eps_p_max, yield_fct, yield_scale=1.0):
        """/MAT/LAW36 with one yield curve (function of eps_p), no rate effect."""
        self.card(f"/MAT/LAW36/{mid}", title, [
            f20(rho), f20(e) + f20(nu) + f20(eps_p_max) + f20(0) + f20(0),
            i10(1) + i10(0) + f20(0) + f20(0) + f20(0), "",
            i10(yield_fct), f20(yield_scale), f20(0.0)])

    def law36_rates(self, mid, title, rho, e, nu, eps_p_max, curves, fcut):
        """/MAT/LAW36 with yield curves at increasing strain rates: curves = [(fct, scale,
        rate), ...] (up to 5), strain-rate filter cutoff fcut (0: 10 kHz in OpenRadioss)."""
        self.card(f"/MAT/LAW36/{mid}", title, [
            f20(rho), f20(e) + f20(nu) + f20(eps_p_max) + f20(0) + f20(0),
            i10(len(curves)) + i10(0) + f20(0) + f20(fcut) + f20(0), "",
            "".join(i10(c[0]) for c in curves), "".join(f20(c[1]) for c in curves),
            "".join(f20(c[2]) for c in curves)])

    # ---- groups and surfaces
    def grnod_node(self, gid, title, ids):
        self.card(f"/GRNOD/NODE/{gid}", title, rows_of_ten(ids))

    def grnod_part(self, gid, title, parts):
        self.card(f"/GRNOD/PART/{gid}", title, ["".join(i10(p) for p in parts)])

    def surf_part(self, sid, title, parts):
        self.card(f"/SURF/PART/{sid}", title, ["".join(i10(p) for p in parts)])

    # ---- boundary conditions, loads, functions
    def bcs(self, bid, title, tra, grnod, rot="000"):
        self.card(f"/BCS/{bid}", title, [f"   {tra:3s} {rot:3s}" + i10(0) + i10(grnod)])

    def funct(self, fid, title, pts):
        self.card(f"/FUNCT/{fid}", title, [f20(x) + f20(y) for x, y in pts])

    def inivel(self, vid, title, v, grnod):
        self.card(f"/INIVEL/TRA/{vid}", title, ["".join(f20(c) for c in v) + i10(grnod)])

    def impvel(self, iid, title, fct, direction, grnod, scale, tstart=0.0, tstop=0.0):
        self.card(f"/IMPVEL/{iid}", title, [i10(fct) + t10(direction) + i10(0) + i10(0) + i10(grnod),
                                            f20(1.0) + f20(scale) + f20(tstart) + f20(tstop)])

    def grav(self, gid, title, fct, direction, grnod, scale):
        self.card(f"/GRAV/{gid}", title, [i10(fct) + t10(direction) + i10(0) + i10(0) + i10(grnod),
                                          f20(1.0) + f20(scale)])

    def rbody(self, rid, title, main, grnod):
        """/RBODY: main node, secondaries /GRNOD, mass and inertia from the secondaries (Ikrem 1)."""
        self.card(f"/RBODY/{rid}", title,
                  [i10(main) + i10(0) + i10(0) + i10(0) + f20(0.0) + i10(grnod) + i10(0) + i10(1) + i10(0)])

    # ---- contact
    def inter7(self, iid, title, grnod, surf, stfac=1.0, fric=0.0, gapmin=0.0, vis_s=0.0,
               istf=0, igap=0, tstart=0.0, tstop=0.0):
        self.card(f"/INTER/TYPE7/{iid}", title, [
            i10(grnod) + i10(surf) + i10(istf) + i10(0) + i10(igap),
            f20(0) + f20(0) + f20(0),
            f20(0) + f20(0),
            f20(stfac) + f20(fric) + f20(gapmin) + f20(tstart) + f20(tstop),
            blank(30) + i10(0) + f20(vis_s) + f20(1.0),
            i10(0),
        ])

    def inter2(self, iid, title, grnod, surf, dsearch=0.0):
        self.card(f"/INTER/TYPE2/{iid}", title, [i10(grnod) + i10(surf) + blank(60) + f20(dsearch)])

    def rwall_plane(self, wid, title, point, normal_point, slide=0, fric=0.0, grnod1=0, dsearch=0.0,
                    node=0, mass=0.0, v0=(0.0, 0.0, 0.0)):
        # Fixed wall (node = 0): line 3 is the point M. Moving wall: line 3 is Mass VX0 VY0 VZ0
        # and the wall passes through the node (point is then unused).
        line3 = "".join(f20(c) for c in point) if node == 0 else f20(mass) + "".join(f20(c) for c in v0)
        self.card(f"/RWALL/PLANE/{wid}", title, [
            i10(node) + i10(slide) + i10(grnod1) + i10(0),
            f20(dsearch) + f20(fric),
            line3,
            "".join(f20(c) for c in normal_point),
        ])

    # ---- time histories
    def th(self, kind, tid, title, variables, ids):
        """/TH/<kind> (PART, INTER, RWALL, SPRING, RBODY, ...): variables, then object ids."""
        self.card(f"/TH/{kind}/{tid}", title, rows_of_ten(variables, t10) + rows_of_ten(ids))

    def th_nodes(self, tid, title, variables, nodes):  # nodes: (id, name)
        self.card(f"/TH/NODE/{tid}", title,
                  rows_of_ten(variables, t10) + [i10(n) + i10(0) + f"{name:<80}" for n, name in nodes])

    # ---- engine cards, in the order they are called
    def engine_card(self, keyword, *values):
        self.engine_lines.append(keyword)
        if values:
            self.engine_lines.append(" ".join(number(v) for v in values))

    def engine(self, tstop, dt_his, print_every=100, anim=0.0, anim_outputs=ANIM_SOLID, nodal_dt=None, stop=None):
        """The usual engine file: /RUN, /TFILE, /PRINT, /ANIM, /DT/NODA/CST (Tsca, Tmin),
        /STOP (Emax, DMmax)."""
        self.engine_card(f"/RUN/{self.name}/1", tstop)
        self.engine_card("/TFILE/4", dt_his)
        self.engine_card(f"/PRINT/-{print_every}")
        if anim > 0:
            self.engine_card("/ANIM/DT", 0, anim)
            for kind in anim_outputs:
                self.engine_card("/ANIM/" + kind)
        if nodal_dt:
            self.engine_card("/DT/NODA/CST/0", *nodal_dt)
        if stop:
            self.engine_card("/STOP", stop[0], stop[1], 0, 1, 1)

    # ---- files
    def starter_text(self):
        out = ["#RADIOSS STARTER"] + ["# " + h if h else "#" for h in self.header]
        out += ["/BEGIN", self.name, i10(2024) + i10(0),
                f"{'kg':>20}{'mm':>20}{'ms':>20}", f"{'kg':>20}{'mm':>20}{'ms':>20}"]
        if self.nodes:
            out += ["/NODE"] + [i10(n) + f20(x) + f20(y) + f20(z) for n, (x, y, z) in sorted(self.nodes.items())]
        return "\n".join(out + self.cards + ["/END"]) + "\n"

    def engine_text(self):
        if not self.engine_lines:
            raise ValueError(f"{self.name}: no engine cards (call engine() or engine_card())")
        head = ["#RADIOSS ENGINE"] + ["# " + h if h else "#" for h in self.header[:1]]
        return "\n".join(head + self.engine_lines) + "\n"

    def write(self, folder=None):
        """Writes <folder>/<name>_0000.rad and _0001.rad (folder: decks/examples/<name>)."""
        folder = folder or os.path.join(EXAMPLES, self.name)
        starter, engine = self.starter_text(), self.engine_text()  # both complete before any file
        os.makedirs(folder, exist_ok=True)
        write_atomic(os.path.join(folder, self.name + "_0000.rad"), starter)
        write_atomic(os.path.join(folder, self.name + "_0001.rad"), engine)
