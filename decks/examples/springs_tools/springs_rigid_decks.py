#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Generator of the spring and rigid-body verification decks in decks/examples/springs_*/
and decks/examples/rigid_*/ (starter <case>_0000.rad + engine <case>_0001.rad). Each
deck's header says what it shows, the analytic value with its tolerance, and how to run
it; ctest/solver/springs_decks_verification.cpp runs them through hbm-solver and checks
the time histories. Regenerate with:
    python3 decks/examples/springs_tools/springs_rigid_decks.py
Units: kg, mm, ms (force kN, moment kN mm, energy J)."""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "deck_tools"))
from radioss_deck import Deck, run_line  # noqa: E402

DT = 1.5e-3  # ms, the body model's fixed step


class Case(Deck):
    """A spring or rigid-body case: object ids given in order of creation, per kind; the
    engine file runs at the fixed step (nodal time step control Tsca 0.9, Tmin = DT)."""

    def __init__(self, name, header, t_stop, th_dt):
        super().__init__(name, header)
        self.engine_card(f"/RUN/{name}/1", t_stop)
        self.engine_card("/TFILE/4", th_dt)
        self.engine_card("/DT/NODA/CST/0", 0.9, DT)
        self.engine_card("/PRINT/-20000")

    def group(self, title, nodes):
        gid = self.next_id("grnod")
        self.grnod_node(gid, title, nodes)
        return gid

    def function(self, title, pts):
        fid = self.next_id("funct")
        self.funct(fid, title, pts)
        return fid

    def spring_part(self, title, kind, mass, dofs, inertia=0.0):
        """Spring property (/PROP/TYPE4 with one DOF block, TYPE8 or TYPE13 with six) and
        its part. mat_id 0: a spring's law is its property (Radioss spring parts need no
        material)."""
        pid = self.next_id("part")
        if kind == 4:
            self.prop_spring4(pid, title + " property", mass, dofs[0])
        else:
            self.prop_spring6(kind, pid, title + " property", mass, inertia, dofs)
        self.part(pid, title, pid, 0)
        return pid

    def fix(self, title, trans, rot, nodes):
        self.bcs(self.next_id("bcs"), title, trans, self.group(title + " nodes", nodes), rot=rot)

    def launch(self, title, v, nodes):
        self.inivel(self.next_id("inivel"), title, v, self.group(title + " nodes", nodes))

    def drive(self, title, fct, direction, nodes, scale=1.0, t_stop=0.0):
        self.impvel(self.next_id("impvel"), title, fct, direction, self.group(title + " nodes", nodes),
                    scale, tstop=t_stop)

    def history(self, kind, title, variables, objects):
        tid = self.next_id("th" + kind)
        if kind == "NODE":
            self.th_nodes(tid, title, variables, objects)
        else:
            self.th(kind, tid, title, variables, objects)

    def brick_rbody(self, title, a, b, c, rho, centre, omega, v0=(0.0, 0.0, 0.0)):
        """One brick a x b x c (mm) of density rho centred at `centre`, made a rigid body
        (its 8 corner nodes, lumped mass M/8 each, are the secondaries; the brick is
        deactivated inside the body); initial rigid velocity v0 + omega x r per node."""
        corners = []
        for k in (0, 1):
            for j in (0, 1):
                for i in (0, 1):
                    corners.append((centre[0] + (i - 0.5) * a, centre[1] + (j - 0.5) * b, centre[2] + (k - 0.5) * c))
        order = [0, 1, 3, 2, 4, 5, 7, 6]  # brick numbering: bottom face, then top face
        ids = [self.node(*p) for p in corners]
        main = self.node(centre[0] + 0.1 * a, centre[1], centre[2])  # moved to the centre
        pid = self.next_id("part")
        self.law1(100 + pid, title + " material", rho, 1.0, 0.3)
        self.prop_solid(pid, title + " solid")
        self.part(pid, title, pid, 100 + pid)
        self.bricks(pid, [(self.next_id("brick"), [ids[o] for o in order])])
        g = self.group(title + " secondary nodes", ids)
        rid = self.next_id("rbody")
        self.rbody(rid, title, main, g)
        for n, p in zip(ids, corners):
            r = [p[q] - centre[q] for q in range(3)]
            v = [v0[0] + omega[1] * r[2] - omega[2] * r[1],
                 v0[1] + omega[2] * r[0] - omega[0] * r[2],
                 v0[2] + omega[0] * r[1] - omega[1] * r[0]]
            self.launch(f"{title} node {n}", v, [n])
        return rid, main


def springs_mass_period():
    name = "springs_mass_period"
    K, m = 10.0, 1.0
    T = 2 * math.pi * math.sqrt(m / K)
    d = Case(name, [f"{name}: a 1 kg mass on a /PROP/TYPE4 linear spring K = {K} kN/mm (spring Mass 2 kg,",
                    "half on each node; node 1 fixed by /BCS), launched at 1 mm/ms, step 1.5e-3 ms.",
                    f"What it shows: period T = 2 pi sqrt(m/K) = {T:.6f} ms (checked to 0.5 %), spring",
                    "force FX = K LX at every output (1e-9), amplitude v0/omega (0.5 %).",
                    run_line(name),
                    "Checked by ctest/solver/springs_decks_verification.cpp (label verification)."], 10.0, 0.005)
    n1, n2 = d.node(0, 0, 0), d.node(100, 0, 0)
    p = d.spring_part("linear spring", 4, 2.0 * m, [d.spring_dof(k=K)])
    d.springs(p, [(n1, n2)])
    d.fix("fixed end", "111", "111", [n1])
    d.fix("guided mass", "011", "000", [n2])
    d.launch("launch", (1.0, 0, 0), [n2])
    d.history("NODE", "mass", ["DX", "VX"], [(n2, "mass")])
    d.history("SPRING", "spring", ["FX", "LX", "IE"], [1])
    d.write()


def springs_damping():
    name = "springs_damping"
    K, m, zeta = 10.0, 1.0, 0.05
    C = 2 * zeta * math.sqrt(K * m)
    d = Case(name, [f"{name}: a 1 kg mass on a /PROP/TYPE4 spring K = {K} kN/mm with damping",
                    f"C = {C:.8f} kN ms/mm (zeta = {zeta}), launched at 1 mm/ms; node 1 fixed.",
                    f"What it shows: logarithmic decrement 2 pi zeta / sqrt(1 - zeta^2) = "
                    f"{2 * math.pi * zeta / math.sqrt(1 - zeta * zeta):.6f} (1 %) and damped",
                    f"period {2 * math.pi * math.sqrt(m / K) / math.sqrt(1 - zeta * zeta):.6f} ms (0.5 %).",
                    run_line(name),
                    "Checked by ctest/solver/springs_decks_verification.cpp (label verification)."], 12.0, 0.002)
    n1, n2 = d.node(0, 0, 0), d.node(50, 0, 0)
    p = d.spring_part("damped spring", 4, 2.0 * m, [d.spring_dof(k=K, c=C)])
    d.springs(p, [(n1, n2)])
    d.fix("fixed end", "111", "111", [n1])
    d.fix("guided mass", "011", "000", [n2])
    d.launch("launch", (1.0, 0, 0), [n2])
    d.history("NODE", "mass", ["DX"], [(n2, "mass")])
    d.write()


def springs_torsion():
    name = "springs_torsion"
    K, J = 50.0, 2.0
    T = 2 * math.pi * math.sqrt(J / K)
    d = Case(name, [f"{name}: torsion springs K4 = {K} kN mm/rad on a node of inertia J = {J} kg mm^2",
                    "(spring Inertia 4, half per node), one /PROP/TYPE8 (part 1) and one /PROP/TYPE13",
                    "(part 2); node 1 of each fixed; node 2 spun about X by /IMPVEL (0.5 rad/ms until",
                    "0.1 ms), then free.",
                    f"What it shows: torsion period 2 pi sqrt(J/K) = {T:.6f} ms for both (0.5 %), and the",
                    "torsion moment MX = K4 RX (1e-9).",
                    run_line(name),
                    "Checked by ctest/solver/springs_decks_verification.cpp (label verification)."], 6.0, 0.002)
    one = d.function("constant", [(0.0, 1.0), (100.0, 1.0)])
    dofs = [d.spring_dof(k=K if dof == 3 else 0.0) for dof in range(6)]  # DOF 4: torsion about X
    for kind in (8, 13):
        kw = f"/PROP/TYPE{kind}"
        a = d.node(0, 0, 10 * len(d.nodes))
        b = d.node(10, 0, 10 * (len(d.nodes) - 1))
        p = d.spring_part("torsion spring " + kw[6:], kind, 2.0, dofs, inertia=2.0 * J)
        d.springs(p, [(a, b)])
        d.fix(f"fixed end {kw[6:]}", "111", "111", [a])
        d.fix(f"torsion only {kw[6:]}", "111", "011", [b])
        d.drive(f"spin {kw[6:]}", one, "XX", [b], scale=0.5, t_stop=0.1)
    d.history("SPRING", "torsion springs", ["MX", "RX"], [1, 2])
    d.write()


def springs_nonlinear():
    name = "springs_nonlinear"
    d = Case(name, ["springs_nonlinear: /PROP/TYPE4 springs driven at 2 mm/ms by /IMPVEL for 2 ms, then",
                    "back at -2 mm/ms for 2 ms. Part 1: nonlinear elastic (H=0) stiffening curve;",
                    "part 2: elastoplastic with isotropic hardening (H=1, K = 5 kN/mm, yield curve",
                    "1 + 0.5 x kN).",
                    "What it shows: H=0 force FX = f(LX) at every output (1e-9 kN); H=1 loads on the",
                    "yield curve, unloads with slope K and keeps the permanent set",
                    "d_pk - f(d_pk)/K at zero force (1e-6 mm; d_pk ~ 4 mm is the peak elongation,",
                    "read from the time history written every cycle: 4 - 2.9/5 = 3.42 mm for d_pk = 4).",
                    run_line(name),
                    "Checked by ctest/solver/springs_decks_verification.cpp (label verification)."], 4.0, DT)
    f = d.function("stiffening force vs elongation [kN, mm]",
                [(-4, -12), (-2, -3), (-1, -0.8), (0, 0), (1, 0.8), (2, 3), (4, 12)])
    y = d.function("yield force vs equivalent elongation [kN, mm]", [(-100.2, -51), (-0.2, -1.0), (0.2, 1.0), (100.2, 51)])
    v = d.function("drive velocity [mm/ms]", [(0, 2), (2, 2), (2.0000001, -2), (100, -2)])
    for title, fct, h, K in (("nonlinear elastic", f, 0, 1.0), ("elastoplastic", y, 1, 5.0)):
        a, b = d.node(0, 10 * len(d.nodes), 0), d.node(20, 10 * (len(d.nodes) - 1), 0)
        p = d.spring_part(title, 4, 0.002, [d.spring_dof(k=K, fct1=fct, h=h)])
        d.springs(p, [(a, b)])
        d.fix(f"{title} fixed end", "111", "111", [a])
        d.fix(f"{title} guided end", "011", "000", [b])
        d.drive(f"{title} drive", v, "X", [b])
    d.history("SPRING", "springs", ["FX", "LX"], [1, 2])
    d.write()


def rigid_tumbling():
    name = "rigid_tumbling"
    a, b, c, rho = 10.0, 20.0, 30.0, 1e-5
    M = rho * a * b * c
    w = (0.03, -0.02, 0.05)
    d = Case(name, [f"{name}: a rigid body (/RBODY on the 8 corner nodes of one {a} x {b} x {c} mm brick,",
                    f"rho = {rho} kg/mm^3, M = {M} kg, corner masses M/8) tumbling freely at",
                    f"omega = {w} rad/ms for 1e5 cycles of 1.5e-3 ms (150 ms).",
                    "What it shows: the free rigid body invariants are conserved by the symplectic",
                    "splitting rotation update: angular momentum AMX AMY AMZ and kinetic energy KE",
                    "within 1e-6 relative of their initial values; engine energy error below 1e-6.",
                    run_line(name),
                    "Checked by ctest/solver/springs_decks_verification.cpp (label verification)."], 150.0, 0.5)
    d.brick_rbody("tumbling body", a, b, c, rho, (0.0, 0.0, 0.0), w)
    d.history("RBODY", "body", ["AMX", "AMY", "AMZ", "WX", "WY", "WZ", "KE"], [1])
    d.write()


def rigid_intermediate_axis():
    name = "rigid_intermediate_axis"
    a, b, c, rho = 10.0, 20.0, 30.0, 1e-5
    M = rho * a * b * c
    W, eps, v0 = 0.2, 1e-6, 2.0
    Jxx, Jyy, Jzz = M * (b * b + c * c) / 4, M * (a * a + c * c) / 4, M * (a * a + b * b) / 4
    lam = W * math.sqrt((Jxx - Jyy) * (Jyy - Jzz) / (Jxx * Jzz))
    d = Case(name, [f"{name}: three identical rigid boxes {a} x {b} x {c} mm (one brick each, corner",
                    f"masses M/8, M = {M} kg), spun at {W} rad/ms about X (major axis, body 1, also",
                    f"translating at {v0} mm/ms), Y (intermediate, body 2) and Z (minor, body 3), each",
                    f"with a {eps} relative perturbation on the two other axes; 180 ms.",
                    "What it shows: body 2 flips (its spin leaves the Y axis: deviation > 0.3) with the",
                    f"perturbation growing at lambda = Omega sqrt((Jxx-Jyy)(Jyy-Jzz)/(Jxx Jzz)) = {lam:.6f}",
                    "/ms (3 %); bodies 1 and 3 stay within 1e-4 of their axis. Body 1's KE equals",
                    f"0.5 M v0^2 + 0.5 Jxx Omega^2 with the closed-form M and Jxx = M (b^2 + c^2)/4 of",
                    "the corner masses (1e-9): mass and inertia computed from the secondary nodes.",
                    run_line(name),
                    "Checked by ctest/solver/springs_decks_verification.cpp (label verification)."], 180.0, 0.05)
    for k, axis in enumerate(range(3)):
        w = [eps * W] * 3
        w[axis] = W
        d.brick_rbody(f"spin about {'XYZ'[axis]}", a, b, c, rho, (0.0, 100.0 * k, 0.0), w,
                      (v0, 0.0, 0.0) if axis == 0 else (0.0, 0.0, 0.0))
    d.history("RBODY", "bodies", ["WX", "WY", "WZ", "VX", "KE"], [1, 2, 3])
    d.write()


def rigid_spring_impact():
    name = "rigid_spring_impact"
    a, b, c, rho = 40.0, 40.0, 40.0, 1e-5
    d = Case(name, [f"{name}: a 0.2 kg mass (spring Mass 0.4 kg) moving at (-5, 1, 0) mm/ms hits, through",
                    "a /PROP/TYPE4 linear spring K = 2 kN/mm attached off-centre to a corner of a free",
                    f"rigid box ({a} mm cube, brick mass {rho * a * b * c} kg; the spring's other half mass",
                    "0.2 kg sits on the corner, so M = 0.84 kg, centre (24.762, 24.762, 15.238) mm), which",
                    "starts to translate and spin.",
                    "What it shows: total linear momentum m v + M v_c and angular momentum about the",
                    "origin m x x v + M x_c x v_c + AM are conserved (1e-8 relative; exact invariants of",
                    "the scheme, written with 10 digits), energy error below 1e-4.",
                    run_line(name),
                    "Checked by ctest/solver/springs_decks_verification.cpp (label verification)."], 60.0, 0.05)
    rid, main = d.brick_rbody("box", a, b, c, rho, (20.0, 20.0, 20.0), (0.0, 0.0, 0.0))
    corner = 4  # node (40, 40, 0): fourth corner of the brick
    free = d.node(100.0, 40.0, 0.0)
    p = d.spring_part("impact spring", 4, 0.4, [d.spring_dof(k=2.0)])
    d.springs(p, [(corner, free)])
    d.launch("projectile", (-5.0, 1.0, 0.0), [free])
    d.history("NODE", "projectile", ["DX", "DY", "DZ", "VX", "VY", "VZ"], [(free, "projectile"), (main, "box centre")])
    d.history("RBODY", "box", ["VX", "VY", "VZ", "AMX", "AMY", "AMZ", "KE"], [rid])
    d.write()


if __name__ == "__main__":
    springs_mass_period()
    springs_damping()
    springs_torsion()
    springs_nonlinear()
    rigid_tumbling()
    rigid_intermediate_axis()
    rigid_spring_impact()
