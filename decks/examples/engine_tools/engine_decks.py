#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Generator of the engine verification decks in decks/examples/<case>/ (starter
<case>_0000.rad + engine <case>_0001.rad). Each deck's header comment says what it shows,
the analytic value and how to run it; the CTest ctest/solver/run_engine_verification.cpp
runs them. Regenerate with:  python3 decks/examples/engine_tools/engine_decks.py
Units: kg, mm, ms (force kN, stress GPa, energy J)."""

import math
import os

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def i10(v):
    return f"{int(v):>10d}"


def f20(v):
    return f"{float(v):>20.12E}"


class Deck:
    def __init__(self, name, header):
        self.name = name
        self.s = ["#RADIOSS STARTER"] + ["# " + h if h else "#" for h in header]
        self.s += ["/BEGIN", name, i10(2024) + i10(0),
                   f"{'kg':>20}{'mm':>20}{'ms':>20}", f"{'kg':>20}{'mm':>20}{'ms':>20}"]
        self.e = ["#RADIOSS ENGINE"] + ["# " + h if h else "#" for h in header[:1]]
        self.nodes = {}
        self.next_node = 1
        self.next_elem = 1

    def card(self, kw, title=None, lines=()):
        self.s.append(kw)
        if title is not None:
            self.s.append(title)
        self.s.extend(lines)

    def node(self, x, y, z):
        n = self.next_node
        self.next_node += 1
        self.nodes[n] = (x, y, z)
        return n

    def write_nodes(self):
        self.card("/NODE", None, [i10(n) + f20(x) + f20(y) + f20(z) for n, (x, y, z) in sorted(self.nodes.items())])

    def block(self, nx, ny, nz, lx, ly, lz, origin=(0, 0, 0), warp=None):
        """Structured block; returns (node index grid dict (i,j,k)->id, list of (eid, 8 nodes))."""
        grid = {}
        for k in range(nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    x, y, z = origin[0] + lx * i / nx, origin[1] + ly * j / ny, origin[2] + lz * k / nz
                    if warp:
                        x, y, z = warp(i, j, k, x, y, z)
                    grid[(i, j, k)] = self.node(x, y, z)
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

    def bricks(self, part, elems):
        self.card(f"/BRICK/{part}", None, [i10(e) + "".join(i10(n) for n in ns) for e, ns in elems])

    def part(self, pid, title, prop, mat):
        self.card(f"/PART/{pid}", title, [i10(prop) + i10(mat) + i10(0)])

    def prop14(self, pid, title, isolid=0, qa=1.1, qb=0.05, h=0.1):
        self.card(f"/PROP/TYPE14/{pid}", title, [i10(isolid), f20(qa) + f20(qb) + f20(h)])

    def law1(self, mid, title, rho, E, nu):
        self.card(f"/MAT/LAW1/{mid}", title, [f20(rho), f20(E) + f20(nu)])

    def law2(self, mid, title, rho, E, nu, a, b, n, epsmax=0.0):
        self.card(f"/MAT/LAW2/{mid}", title, [f20(rho), f20(E) + f20(nu) + i10(0), f20(a) + f20(b) + f20(n) + f20(epsmax) + f20(0)])

    def law34(self, mid, title, rho, K, G0, Ginf, beta):
        self.card(f"/MAT/LAW34/{mid}", title, [f20(rho), f20(K), f20(G0) + f20(Ginf) + f20(beta)])

    def grnod(self, gid, title, ids):
        ids = list(ids)
        self.card(f"/GRNOD/NODE/{gid}", title, ["".join(i10(n) for n in ids[k:k + 10]) for k in range(0, len(ids), 10)])

    def funct(self, fid, title, pts):
        self.card(f"/FUNCT/{fid}", title, [f20(x) + f20(y) for x, y in pts])

    def bcs(self, bid, title, tra, grnod):
        self.card(f"/BCS/{bid}", title, [f"   {tra:3s} 000" + i10(0) + i10(grnod)])

    def impvel(self, iid, title, fct, direction, grnod, scale, tstart=0.0, tstop=0.0):
        self.card(f"/IMPVEL/{iid}", title, [i10(fct) + f"{direction:>10}" + i10(0) + i10(0) + i10(grnod),
                                            f20(1.0) + f20(scale) + f20(tstart) + f20(tstop)])

    def inivel(self, iid, title, v, grnod):
        self.card(f"/INIVEL/TRA/{iid}", title, [f20(v[0]) + f20(v[1]) + f20(v[2]) + i10(grnod)])

    def grav(self, gid, title, fct, direction, grnod, scale):
        self.card(f"/GRAV/{gid}", title, [i10(fct) + f"{direction:>10}" + i10(0) + i10(0) + i10(grnod),
                                          f20(1.0) + f20(scale)])

    def th_nodes(self, tid, title, variables, nodes):
        self.card(f"/TH/NODE/{tid}", title,
                  ["".join(f"{v:>10}" for v in variables)] + [i10(n) + i10(0) + f"{name:<80}" for n, name in nodes])

    def th_parts(self, tid, title, variables, parts):
        self.card(f"/TH/PART/{tid}", title, ["".join(f"{v:>10}" for v in variables), "".join(i10(p) for p in parts)])

    def engine(self, tstop, dt_his, anim=0.0, print_every=100, nodal=None, stop=None):
        e = self.e
        e += [f"/RUN/{self.name}/1", f"{tstop}", "/TFILE/4", f"{dt_his}", f"/PRINT/-{print_every}"]
        if anim > 0:
            e += ["/ANIM/DT", f"0 {anim}", "/ANIM/VECT/VEL", "/ANIM/ELEM/VONM", "/ANIM/ELEM/EPSP", "/ANIM/NODA/DMAS"]
        if nodal:
            e += ["/DT/NODA/CST/0", f"{nodal[0]} {nodal[1]}"]
        if stop:
            e += ["/STOP", f"{stop[0]} {stop[1]} 0 1 1"]
        pass

    def write(self):
        d = os.path.join(ROOT, self.name)
        os.makedirs(d, exist_ok=True)
        self.write_nodes_first()
        for suffix, lines in (("_0000.rad", self.s + ["/END"]), ("_0001.rad", self.e)):
            path = os.path.join(d, self.name + suffix)
            tmp = path + ".tmp"
            with open(tmp, "w") as f:
                f.write("\n".join(lines) + "\n")
            os.replace(tmp, path)

    def write_nodes_first(self):
        # /NODE goes right after /BEGIN (5 lines after the header comments).
        i = self.s.index("/BEGIN") + 5
        nodes = ["/NODE"] + [i10(n) + f20(x) + f20(y) + f20(z) for n, (x, y, z) in sorted(self.nodes.items())]
        self.s = self.s[:i] + nodes + self.s[i:]


def face(grid, axis, index):
    return sorted({n for (i, j, k), n in grid.items() if (i, j, k)[axis] == index})


RUN = "Run: hbm-solver decks/examples/{0}/{0}_0000.rad --out out/{0}"
CHECK = "Checked by ctest/solver/run_engine_verification.cpp (label verification)."


def wave_bar():
    # Steel-like bar, nu = 0 (1D), 100 elements of 1 mm; end x = 0 pushed at v0.
    E, rho, v0, L, n = 200.0, 7.85e-6, 1.0, 100.0, 100
    c = math.sqrt(E / rho)
    d = Deck("wave_bar", [
        "wave_bar: elastic wave in a brick bar (100 x 1 x 1 bricks of 1 mm, LAW1, nu = 0).",
        f"The end x = 0 moves at v0 = {v0} mm/ms from t = 0 (/IMPVEL); lateral faces free.",
        f"What it shows: the wave front reaches x = 50 mm at t = 50/c = {50 / c:.6e} ms",
        f"(c = sqrt(E/rho) = {c:.3f} mm/ms) and the particle velocity behind it is v0, the",
        f"stress rho c v0 = {rho * c * v0:.6e} GPa. Tolerance 2% on both.", RUN.format("wave_bar"), CHECK])
    grid, el = d.block(n, 1, 1, L, 1.0, 1.0)
    d.law1(1, "steel nu 0", rho, E, 0.0)
    d.prop14(1, "solid")
    d.part(1, "bar", 1, 1)
    d.bricks(1, el)
    d.grnod(1, "pushed end", face(grid, 0, 0))
    d.funct(1, "constant", [(0, 1), (1, 1)])
    d.impvel(1, "push", 1, "X", 1, v0)
    mid = grid[(50, 0, 0)]
    d.th_nodes(1, "probes", ["DX", "VX"], [(mid, "mid bar"), (grid[(25, 0, 0)], "quarter bar")])
    d.engine(0.03, 2.0e-4, anim=0.01, print_every=50)
    d.write()


def patch_distorted():
    E, rho, nu = 0.2, 1e-6, 0.3
    rate = [1e-3, -0.5e-3, 0.3e-3, 0.4e-3, 0.2e-3, -0.1e-3]  # velocity gradient terms (1/ms)
    d = Deck("patch_distorted", [
        "patch_distorted: patch test on a distorted 2 x 2 x 2 brick mesh (interior node moved).",
        "Every boundary node has the velocity of the linear field v = A x (/IMPVEL per node",
        "and direction, and /INIVEL from t = 0), the interior node is free with the field's",
        "initial velocity (/INIVEL).",
        "What it shows: the stress is the same in",
        "every element (uniform to 1e-10 relative) and the interior node follows the linear",
        "field: the one-point uniform-gradient brick passes the patch test on distorted meshes.",
        RUN.format("patch_distorted"), CHECK])
    def warp(i, j, k, x, y, z):
        if (i, j, k) == (1, 1, 1):
            return x + 0.15, y - 0.1, z + 0.12
        if i == 1 and j == 1 and k in (0, 2):
            return x + 0.1, y + 0.05, z
        if i == 1 and k == 1 and j in (0, 2):
            return x - 0.08, y, z + 0.07
        return x, y, z
    grid, el = d.block(2, 2, 2, 2.0, 2.0, 2.0, warp=warp)
    d.law1(1, "elastic", rho, E, nu)
    d.prop14(1, "solid", qa=0.0, qb=0.0)
    d.part(1, "patch", 1, 1)
    d.bricks(1, el)
    d.funct(1, "constant", [(0, 1), (1, 1)])
    A = [[rate[0], rate[3], rate[5]], [rate[3], rate[1], rate[4]], [rate[5], rate[4], rate[2]]]
    gid = 1
    for key, n in sorted(grid.items()):
        if key == (1, 1, 1):
            continue
        x = d.nodes[n]
        d.grnod(gid, f"node {n}", [n])
        for a, name in enumerate("XYZ"):
            v = sum(A[a][b] * x[b] for b in range(3))
            d.impvel(100 * gid + a, f"node {n} {name}", 1, name, gid, v)
        d.inivel(100 + gid, f"node {n}", [sum(A[a][b] * x[b] for b in range(3)) for a in range(3)], gid)
        gid += 1
    xi = d.nodes[grid[(1, 1, 1)]]
    d.grnod(gid, "interior", [grid[(1, 1, 1)]])
    d.inivel(1, "interior on the field", [sum(A[a][b] * xi[b] for b in range(3)) for a in range(3)], gid)
    d.th_nodes(1, "interior", ["DX", "DY", "DZ"], [(grid[(1, 1, 1)], "interior node")])
    d.engine(0.05, 0.01, print_every=100)
    d.write()


def single_element(name, header, mat_writer, law_tstop, strain, props=dict(isolid=0)):
    """One 1 mm cube, uniaxial stress: x=0 face fixed in X, y=0 in Y, z=0 in Z, face x=1 pulled."""
    d = Deck(name, header)
    grid, el = d.block(1, 1, 1, 1.0, 1.0, 1.0)
    mat_writer(d)
    d.prop14(1, "solid", qa=0.0, qb=0.0, **props)
    d.part(1, "cube", 1, 1)
    d.bricks(1, el)
    d.grnod(1, "x0", face(grid, 0, 0))
    d.grnod(2, "y0", face(grid, 1, 0))
    d.grnod(3, "z0", face(grid, 2, 0))
    d.grnod(4, "x1", face(grid, 0, 1))
    d.bcs(1, "x0", "100", 1)
    d.bcs(2, "y0", "010", 2)
    d.bcs(3, "z0", "001", 3)
    d.funct(1, "ramp", [(0, 0), (0.1 * law_tstop, 1), (law_tstop, 1)])
    # displacement = strain * 1 mm reached at t_stop with the smooth ramp: area = 0.95 t_stop
    d.impvel(1, "pull", 1, "X", 4, strain / (0.95 * law_tstop))
    d.th_nodes(1, "pulled corner", ["DX", "DY"], [(grid[(1, 1, 1)], "corner")])
    d.th_parts(2, "energies", ["IE", "HE"], [1])
    return d


def uniaxial_law1():
    E, nu, rho = 0.01, 0.3, 1e-6
    d = single_element("uniaxial_law1", [
        "uniaxial_law1: one LAW1 brick (1 mm cube, E = 0.01 GPa, nu = 0.3) pulled to 10% strain",
        "in 5 ms (quasi-static: wave transit 0.01 ms), symmetry conditions on three faces.",
        "What it shows: hypoelastic Jaumann rate under uniaxial stress gives the log-strain law",
        "sigma_xx = E ln(L/L0) and sigma_yy = sigma_zz = 0; lateral strain",
        "ln(W/W0) = -nu ln(L/L0). Tolerance 1%.", RUN.format("uniaxial_law1"), CHECK],
        lambda d: d.law1(1, "elastic", rho, E, nu), 5.0, 0.10)
    d.engine(5.0, 0.05, print_every=500)
    d.write()


def uniaxial_law2():
    E, nu, rho, a, b, n = 0.2, 0.3, 7.85e-6, 3.0e-4, 5.0e-4, 0.5
    d = single_element("uniaxial_law2", [
        "uniaxial_law2: one LAW2 (Johnson-Cook, no rate) brick pulled to 5% strain in 5 ms.",
        f"E = {E} GPa, a = {a} GPa, b = {b} GPa, n = {n}. What it shows: yield at sigma = a,",
        "then sigma = a + b eps_p^n with eps_p = eps - sigma/E (log strain). Tolerance 1%.",
        RUN.format("uniaxial_law2"), CHECK],
        lambda d: d.law2(1, "jc", rho, E, nu, a, b, n), 5.0, 0.05)
    d.engine(5.0, 0.05, print_every=500)
    d.write()


def relax_law34():
    rho, K, G0, Ginf, beta = 1e-6, 0.01, 1e-3, 2.5e-4, 10.0
    tr, gamma = 0.01, 0.01
    d = Deck("relax_law34", [
        "relax_law34: one LAW34 brick (1 mm cube) in simple shear: top face moved in X by",
        f"gamma = {gamma} (engineering shear) over a ramp of {tr} ms, then held; bottom fixed.",
        f"G(t) = Ginf + (G0 - Ginf) exp(-beta t), G0 = {G0}, Ginf = {Ginf} GPa, beta = {beta} /ms.",
        "What it shows: sigma_xy(t) = (gamma/tr) int_0^tr G(t - s) ds for t > tr",
        "= (gamma/tr) [Ginf tr + (G0 - Ginf)/beta (exp(-beta (t - tr)) - exp(-beta t))]",
        "(the recursive hereditary integral is exact for a piecewise constant rate). 1%.",
        RUN.format("relax_law34"), CHECK])
    grid, el = d.block(1, 1, 1, 1.0, 1.0, 1.0)
    d.law34(1, "tissue", rho, K, G0, Ginf, beta)
    d.prop14(1, "solid", qa=0.0, qb=0.0)
    d.part(1, "cube", 1, 1)
    d.bricks(1, el)
    d.grnod(1, "bottom", face(grid, 1, 0))
    d.grnod(2, "top", face(grid, 1, 1))
    d.bcs(1, "bottom", "111", 1)
    d.bcs(2, "top yz", "011", 2)
    d.funct(1, "pulse", [(0, 1), (tr, 1), (tr * 1.0000001, 0), (10, 0)])
    d.impvel(1, "shear", 1, "X", 2, gamma / tr)
    d.th_parts(1, "energies", ["IE", "HE"], [1])
    d.engine(0.5, 0.005, print_every=200)
    d.write()


def free_fall():
    d = Deck("free_fall", [
        "free_fall: an elastic brick (LAW1) falls from rest under /GRAV g = 9.81e-3 mm/ms^2.",
        "What it shows: z(t) = z0 - g t^2 / 2 exactly (central differences are exact for a",
        "constant acceleration; no deformation). Checked to 1e-9 relative at t = 10 ms.",
        RUN.format("free_fall"), CHECK])
    grid, el = d.block(1, 1, 1, 10.0, 10.0, 10.0)
    d.law1(1, "elastic", 1e-6, 0.01, 0.3)
    d.prop14(1, "solid")
    d.part(1, "cube", 1, 1)
    d.bricks(1, el)
    d.grnod(1, "all", sorted(grid.values()))
    d.funct(1, "one", [(0, 1), (100, 1)])
    d.grav(1, "gravity", 1, "Z", 1, -9.81e-3)
    d.th_nodes(1, "corner", ["DZ", "VZ", "AZ"], [(grid[(0, 0, 0)], "corner")])
    d.engine(10.0, 0.5, print_every=200)
    d.write()


def mass_scaling(stop):
    name = "mass_scaling_stop" if stop else "mass_scaling"
    E, nu, rho = 0.2, 0.3, 7.85e-6
    h_small = 0.05
    tmin = 2.0e-3
    head = [f"{name}: 3 bricks in a row, 1 mm cubes except the middle one, {h_small} mm thick;",
            f"/DT/NODA/CST Tsca = 0.9, Tmin = {tmin} ms: above the nodal step of the thin element's",
            "nodes (sqrt(h)/c Tsca) but below that of the others (1/c Tsca).",
            "What it shows: the nodes of the thin element get mass m = k_n/2 (Tmin/Tsca)^2 where",
            "k_n = sum of 2 m_slot / dt_e^2 over the element nodes (m_slot = m_e/8, dt_e = 2/w,",
            "w^2 = 8 (lambda tr(T)^2 + 2G T:T) / (rho tr T), T = diag(1/(2 L_i^2)) for a box of",
            "sides L_i); the other nodes get none."]
    if stop:
        head += ["/STOP DMmax = 0.01: the added mass exceeds 1% at the first cycle, so the run",
                 "stops cleanly naming part 2 and element 2, exit code 3, outputs valid."]
    d = Deck(name, head + [RUN.format(name), CHECK])
    xs = [0.0, 1.0, 1.0 + h_small, 2.0 + h_small]
    grid = {}
    for i, x in enumerate(xs):
        for k in range(2):
            for j in range(2):
                grid[(i, j, k)] = d.node(x, float(j), float(k))
    els = []
    for i in range(3):
        ns = [grid[(i, 0, 0)], grid[(i + 1, 0, 0)], grid[(i + 1, 1, 0)], grid[(i, 1, 0)],
              grid[(i, 0, 1)], grid[(i + 1, 0, 1)], grid[(i + 1, 1, 1)], grid[(i, 1, 1)]]
        els.append((i + 1, ns))
    d.law1(1, "steel", rho, E, nu)
    d.prop14(1, "solid")
    d.part(1, "big", 1, 1)
    d.part(2, "thin", 1, 1)
    d.bricks(1, [els[0], els[2]])
    d.bricks(2, [els[1]])
    d.th_parts(1, "mass", ["AM", "M"], [1, 2])
    d.engine(0.02, 0.002, print_every=10, nodal=(0.9, tmin), stop=(0.0, 0.01) if stop else None)
    d.write()


def energy_impact():
    E, nu, rho, v0 = 0.2, 0.3, 7.85e-6, 5.0
    d = Deck("energy_impact", [
        "energy_impact: an elastic block (4 x 4 x 8 bricks, 10 x 10 x 20 mm, LAW1) moving at",
        f"{v0} mm/ms hits a fixed wall (its bottom face stops: /BCS) and bounces in the elastic",
        "waves. What it shows: kinetic + internal + hourglass stays equal to the initial kinetic",
        "energy 0.5 m v0^2 (no external work from fixed nodes) within 0.1%.",
        RUN.format("energy_impact"), CHECK])
    grid, el = d.block(4, 4, 8, 10.0, 10.0, 20.0)
    d.law1(1, "steel", rho, E, nu)
    d.prop14(1, "solid")
    d.part(1, "block", 1, 1)
    d.bricks(1, el)
    bottom = face(grid, 2, 0)
    d.grnod(1, "bottom", bottom)
    d.grnod(2, "others", sorted(set(grid.values()) - set(bottom)))
    d.bcs(1, "bottom", "111", 1)
    d.inivel(1, "impact", (0.0, 0.0, -v0), 2)
    d.th_parts(1, "energies", ["IE", "KE", "HE"], [1])
    d.engine(0.5, 0.005, print_every=100)
    d.write()


def law34_impact(name, header, tstop, nodal):
    rho, K, G0, Ginf, beta = 1.0e-6, 2.0e-2, 2.0e-4, 1.0e-4, 0.1
    d = Deck(name, header)
    n, L = 8, 40.0
    grid, el = d.block(n, n, n // 2, L, L, L / 2)
    d.law34(1, "soft tissue", rho, K, G0, Ginf, beta)
    d.prop14(1, "solid (default: Isolid 24 for LAW34)")
    d.part(1, "tissue block", 1, 1)
    d.bricks(1, el)
    bottom = face(grid, 2, 0)
    top = [grid[(i, j, n // 2)] for i in range(2, 7) for j in range(2, 7)]
    d.grnod(1, "bottom", bottom)
    d.grnod(2, "punch", top)
    d.bcs(1, "bottom", "111", 1)
    d.funct(1, "constant", [(0, 1), (100, 1)])
    d.impvel(1, "punch", 1, "Z", 2, -6.7)
    d.bcs(2, "punch xy", "110", 2)
    d.th_nodes(1, "punch", ["DZ", "VZ"], [(grid[(4, 4, n // 2)], "punch centre")])
    d.th_parts(2, "energies", ["IE", "HE", "KE"], [1])
    d.engine(tstop, tstop / 50, anim=tstop / 5, print_every=100, nodal=nodal)
    d.write()


def inverted():
    d = Deck("inverted_element", [
        "inverted_element: planted failure. One soft brick whose top face is driven down at",
        "100 mm/ms through its bottom face (fixed): the element turns inside out at about",
        "t = 0.01 ms. What it shows: the run stops cleanly with 'element 1 of part 1 ...",
        "inverted (negative volume) at time ...', exit code 3, the time history and the",
        "animation written up to that time are valid.", RUN.format("inverted_element"), CHECK])
    grid, el = d.block(1, 1, 1, 1.0, 1.0, 1.0)
    d.law1(1, "soft", 1e-6, 1e-3, 0.3)
    d.prop14(1, "solid")
    d.part(1, "cube", 1, 1)
    d.bricks(1, el)
    d.grnod(1, "bottom", face(grid, 2, 0))
    d.grnod(2, "top", face(grid, 2, 1))
    d.bcs(1, "bottom", "111", 1)
    d.funct(1, "constant", [(0, 1), (1, 1)])
    d.impvel(1, "crush", 1, "Z", 2, -100.0)
    d.th_nodes(1, "top", ["DZ"], [(grid[(1, 1, 1)], "top corner")])
    d.engine(0.05, 0.001, anim=0.002, print_every=10)
    d.write()


def tetra_prism_uniaxial():
    E, nu, rho = 0.01, 0.3, 1e-6
    d = Deck("tetra_prism_uniaxial", [
        "tetra_prism_uniaxial: a unit cube of 6 /TETRA4 (part 1) and a unit cube of 2",
        "degenerate /BRICK prisms (n4 = n3, n8 = n7; part 2), LAW1, pulled to 5% strain in",
        "5 ms under uniaxial stress (symmetry faces x = 0, y = lower face, z = 0).",
        "What it shows: constant-strain tetra and degenerate brick give sigma_xx = E ln(L/L0)",
        "in every element (1%), other stresses ~0; the animation writes tetra and wedge cells.",
        RUN.format("tetra_prism_uniaxial"), CHECK])
    grids = []
    for y0 in (0.0, 2.0):
        g = {}
        for k in range(2):
            for j in range(2):
                for i in range(2):
                    g[(i, j, k)] = d.node(float(i), y0 + j, float(k))
        grids.append(g)
    g = grids[0]
    def vol(ns):
        p = [d.nodes[n] for n in ns]
        a = [p[1][t] - p[0][t] for t in range(3)]
        b = [p[2][t] - p[0][t] for t in range(3)]
        c = [p[3][t] - p[0][t] for t in range(3)]
        return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]))
    tets = []
    for path in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
        pass
    corners = [((0, 0, 0), (1, 0, 0), (1, 1, 0)), ((0, 0, 0), (1, 0, 0), (1, 0, 1)), ((0, 0, 0), (0, 1, 0), (1, 1, 0)),
               ((0, 0, 0), (0, 1, 0), (0, 1, 1)), ((0, 0, 0), (0, 0, 1), (1, 0, 1)), ((0, 0, 0), (0, 0, 1), (0, 1, 1))]
    for a, b, c in corners:
        ns = [g[a], g[b], g[c], g[(1, 1, 1)]]
        if vol(ns) < 0:
            ns[1], ns[2] = ns[2], ns[1]
        tets.append((d.next_elem, ns))
        d.next_elem += 1
    h = grids[1]
    prisms = [(d.next_elem, [h[(0, 0, 0)], h[(1, 0, 0)], h[(1, 1, 0)], h[(1, 1, 0)], h[(0, 0, 1)], h[(1, 0, 1)], h[(1, 1, 1)], h[(1, 1, 1)]]),
              (d.next_elem + 1, [h[(0, 0, 0)], h[(1, 1, 0)], h[(0, 1, 0)], h[(0, 1, 0)], h[(0, 0, 1)], h[(1, 1, 1)], h[(0, 1, 1)], h[(0, 1, 1)]])]
    d.law1(1, "elastic", rho, E, nu)
    d.prop14(1, "solid", qa=0.0, qb=0.0)
    d.part(1, "tetra cube", 1, 1)
    d.part(2, "prism cube", 1, 1)
    d.card("/TETRA4/1", None, [i10(e) + "".join(i10(n) for n in ns) for e, ns in tets])
    d.bricks(2, prisms)
    allg = {**{("a",) + k: v for k, v in g.items()}, **{("b",) + k: v for k, v in h.items()}}
    d.grnod(1, "x0", [v for k, v in allg.items() if k[1] == 0])
    d.grnod(2, "ylow", [v for k, v in allg.items() if k[2] == 0])
    d.grnod(3, "z0", [v for k, v in allg.items() if k[3] == 0])
    d.grnod(4, "x1", [v for k, v in allg.items() if k[1] == 1])
    d.bcs(1, "x0", "100", 1)
    d.bcs(2, "ylow", "010", 2)
    d.bcs(3, "z0", "001", 3)
    d.funct(1, "ramp", [(0, 0), (0.5, 1), (5.0, 1)])
    d.impvel(1, "pull", 1, "X", 4, 0.05 / (0.95 * 5.0))
    d.th_nodes(1, "corner", ["DX"], [(g[(1, 1, 1)], "tetra corner"), (h[(1, 1, 1)], "prism corner")])
    d.engine(5.0, 0.05, anim=1.0, print_every=1000)
    d.write()


def law36_erosion():
    E, nu, rho = 0.2, 0.3, 7.85e-6
    d = Deck("law36_erosion", [
        "law36_erosion: one LAW36 brick (tabulated yield curve: 3e-4 GPa at eps_p = 0 rising",
        "linearly to 5e-4 GPa at eps_p = 0.1), EPS_p_max = 0.03, pulled to 6% strain in 5 ms.",
        "What it shows: before failure sigma_xx = f(eps_p), eps_p = ln(L) - sigma/E (1%);",
        "the element is deleted when eps_p reaches 0.03 (counted for part 1, its internal",
        "energy kept in the balance), the run ends normally.", RUN.format("law36_erosion"), CHECK])
    grid, el = d.block(1, 1, 1, 1.0, 1.0, 1.0)
    d.funct(2, "yield curve", [(0.0, 3.0e-4), (0.1, 5.0e-4), (1.0, 5.0e-4)])
    d.card("/MAT/LAW36/1", "tabulated", [f20(rho), f20(E) + f20(nu) + f20(0.03) + f20(0) + f20(0),
                                         i10(1) + i10(0) + f20(0) + f20(0) + f20(0), "",
                                         i10(2), f20(1.0), f20(0.0)])
    d.prop14(1, "solid", qa=0.0, qb=0.0)
    d.part(1, "cube", 1, 1)
    d.bricks(1, el)
    d.grnod(1, "x0", face(grid, 0, 0))
    d.grnod(2, "y0", face(grid, 1, 0))
    d.grnod(3, "z0", face(grid, 2, 0))
    d.grnod(4, "x1", face(grid, 0, 1))
    d.bcs(1, "x0", "100", 1)
    d.bcs(2, "y0", "010", 2)
    d.bcs(3, "z0", "001", 3)
    d.funct(1, "ramp", [(0, 0), (0.5, 1), (5.0, 1)])
    d.impvel(1, "pull", 1, "X", 4, 0.06 / (0.95 * 5.0))
    d.th_nodes(1, "corner", ["DX"], [(grid[(1, 1, 1)], "corner")])
    d.th_parts(2, "part", ["IE", "ER"], [1])
    d.engine(5.0, 0.05, print_every=1000)
    d.write()


if __name__ == "__main__":
    tetra_prism_uniaxial()
    law36_erosion()
    wave_bar()
    patch_distorted()
    uniaxial_law1()
    uniaxial_law2()
    relax_law34()
    free_fall()
    mass_scaling(False)
    mass_scaling(True)
    energy_impact()
    law34_impact("law34_impact", [
        "law34_impact: a punch (5 x 5 top nodes, imposed velocity) hits a LAW34 tissue block",
        "(40 x 40 x 20 mm, 8 x 8 x 4 bricks, K = 0.02 GPa >> G0 = 2e-4 GPa) at 6.7 m/s.",
        "Hourglass: physical stabilisation in the corotational frame (default for LAW34).",
        "What it shows: no inverted element, normal termination, hourglass energy below 10%",
        "of the internal energy at the end (5 mm indentation).",
        RUN.format("law34_impact"), CHECK], 0.75, None)
    law34_impact("impact", [
        "impact: the example run by scripts/main-job.sh. A flat punch hits a LAW34 soft-tissue",
        "block at 6.7 m/s (8 mm indentation), bottom face fixed, fixed time step 1.5e-3 ms",
        "with nodal mass scaling (/DT/NODA/CST 0.9 1.5e-3) as the body model runs.",
        "Outputs: listing impact_0001.out, CSV time histories, VTK frames + impact.pvd.",
        RUN.format("impact")], 1.2, (0.9, 1.5e-3))
    inverted()
