#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Generator of the engine verification decks in decks/examples/<case>/ (starter
<case>_0000.rad + engine <case>_0001.rad). Each deck's header comment says what it shows,
the analytic value and how to run it; the CTest ctest/solver/run_engine_verification.cpp
runs them. Regenerate with:  python3 decks/examples/engine_tools/engine_decks.py
Units: kg, mm, ms (force kN, stress GPa, energy J)."""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "deck_tools"))
from radioss_deck import Deck, run_line  # noqa: E402


def face(grid, axis, index):
    return sorted({n for (i, j, k), n in grid.items() if (i, j, k)[axis] == index})


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
        f"stress rho c v0 = {rho * c * v0:.6e} GPa. Tolerance 2% on both.", run_line("wave_bar"), CHECK])
    grid, el = d.block(n, 1, 1, (L, 1.0, 1.0))
    d.law1(1, "steel nu 0", rho, E, 0.0)
    d.prop_solid(1, "solid")
    d.part(1, "bar", 1, 1)
    d.bricks(1, el)
    d.grnod_node(1, "pushed end", face(grid, 0, 0))
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
        run_line("patch_distorted"), CHECK])
    def warp(i, j, k, x, y, z):
        if (i, j, k) == (1, 1, 1):
            return x + 0.15, y - 0.1, z + 0.12
        if i == 1 and j == 1 and k in (0, 2):
            return x + 0.1, y + 0.05, z
        if i == 1 and k == 1 and j in (0, 2):
            return x - 0.08, y, z + 0.07
        return x, y, z
    grid, el = d.block(2, 2, 2, (2.0, 2.0, 2.0), warp=warp)
    d.law1(1, "elastic", rho, E, nu)
    d.prop_solid(1, "solid", qa=1e-30, qb=1e-30)  # no bulk viscosity (0 reads as the default)
    d.part(1, "patch", 1, 1)
    d.bricks(1, el)
    d.funct(1, "constant", [(0, 1), (1, 1)])
    # A zero velocity takes a zero function: a scale of 0 reads as 1 (OpenRadioss's default).
    d.funct(2, "zero", [(0, 0), (1, 0)])
    A = [[rate[0], rate[3], rate[5]], [rate[3], rate[1], rate[4]], [rate[5], rate[4], rate[2]]]
    gid = 1
    for key, n in sorted(grid.items()):
        if key == (1, 1, 1):
            continue
        x = d.nodes[n]
        d.grnod_node(gid, f"node {n}", [n])
        for a, name in enumerate("XYZ"):
            v = sum(A[a][b] * x[b] for b in range(3))
            d.impvel(100 * gid + a, f"node {n} {name}", 1 if v != 0 else 2, name, gid, v if v != 0 else 1.0)
        d.inivel(100 + gid, f"node {n}", [sum(A[a][b] * x[b] for b in range(3)) for a in range(3)], gid)
        gid += 1
    xi = d.nodes[grid[(1, 1, 1)]]
    d.grnod_node(gid, "interior", [grid[(1, 1, 1)]])
    d.inivel(1, "interior on the field", [sum(A[a][b] * xi[b] for b in range(3)) for a in range(3)], gid)
    d.th_nodes(1, "interior", ["DX", "DY", "DZ"], [(grid[(1, 1, 1)], "interior node")])
    d.engine(0.05, 0.01, print_every=100)
    d.write()


def single_element(name, header, mat_writer, law_tstop, strain, node_vars=("DX", "DY"), part_vars=("IE", "HE")):
    """One 1 mm cube, uniaxial stress: x=0 face fixed in X, y=0 in Y, z=0 in Z, face x=1 pulled
    to `strain` at law_tstop; time histories of the pulled corner and of the part."""
    d = Deck(name, header)
    grid, el = d.block(1, 1, 1, (1.0, 1.0, 1.0))
    mat_writer(d)
    d.prop_solid(1, "solid", qa=1e-30, qb=1e-30)  # no bulk viscosity (0 reads as the default)
    d.part(1, "cube", 1, 1)
    d.bricks(1, el)
    d.grnod_node(1, "x0", face(grid, 0, 0))
    d.grnod_node(2, "y0", face(grid, 1, 0))
    d.grnod_node(3, "z0", face(grid, 2, 0))
    d.grnod_node(4, "x1", face(grid, 0, 1))
    d.bcs(1, "x0", "100", 1)
    d.bcs(2, "y0", "010", 2)
    d.bcs(3, "z0", "001", 3)
    d.funct(1, "ramp", [(0, 0), (0.1 * law_tstop, 1), (law_tstop, 1)])
    # displacement = strain * 1 mm reached at t_stop with the smooth ramp: area = 0.95 t_stop
    d.impvel(1, "pull", 1, "X", 4, strain / (0.95 * law_tstop))
    d.th_nodes(1, "pulled corner", list(node_vars), [(grid[(1, 1, 1)], "corner")])
    d.th("PART", 2, "part", list(part_vars), [1])
    return d


def uniaxial_law1():
    E, nu, rho = 0.01, 0.3, 1e-6
    d = single_element("uniaxial_law1", [
        "uniaxial_law1: one LAW1 brick (1 mm cube, E = 0.01 GPa, nu = 0.3) pulled to 10% strain",
        "in 5 ms (quasi-static: wave transit 0.01 ms), symmetry conditions on three faces.",
        "What it shows: hypoelastic Jaumann rate under uniaxial stress gives the log-strain law",
        "sigma_xx = E ln(L/L0) and sigma_yy = sigma_zz = 0; lateral strain",
        "ln(W/W0) = -nu ln(L/L0). Tolerance 1%.", run_line("uniaxial_law1"), CHECK],
        lambda d: d.law1(1, "elastic", rho, E, nu), 5.0, 0.10)
    d.engine(5.0, 0.05, print_every=500)
    d.write()


def uniaxial_law2():
    E, nu, rho, a, b, n = 0.2, 0.3, 7.85e-6, 3.0e-4, 5.0e-4, 0.5
    d = single_element("uniaxial_law2", [
        "uniaxial_law2: one LAW2 (Johnson-Cook, no rate) brick pulled to 5% strain in 5 ms.",
        f"E = {E} GPa, a = {a} GPa, b = {b} GPa, n = {n}. What it shows: yield at sigma = a,",
        "then sigma = a + b eps_p^n with eps_p = eps - sigma/E (log strain). Tolerance 1%.",
        run_line("uniaxial_law2"), CHECK],
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
        run_line("relax_law34"), CHECK])
    grid, el = d.block(1, 1, 1, (1.0, 1.0, 1.0))
    d.law34(1, "tissue", rho, K, G0, Ginf, beta)
    d.prop_solid(1, "solid", qa=1e-30, qb=1e-30)  # no bulk viscosity (0 reads as the default)
    d.part(1, "cube", 1, 1)
    d.bricks(1, el)
    d.grnod_node(1, "bottom", face(grid, 1, 0))
    d.grnod_node(2, "top", face(grid, 1, 1))
    d.bcs(1, "bottom", "111", 1)
    d.bcs(2, "top yz", "011", 2)
    d.funct(1, "pulse", [(0, 1), (tr, 1), (tr * 1.0000001, 0), (10, 0)])
    d.impvel(1, "shear", 1, "X", 2, gamma / tr)
    d.th("PART", 1, "energies", ["IE", "HE"], [1])
    d.engine(0.5, 0.005, print_every=200)
    d.write()


def free_fall():
    d = Deck("free_fall", [
        "free_fall: an elastic brick (LAW1) falls from rest under /GRAV g = 9.81e-3 mm/ms^2.",
        "What it shows: z(t) = z0 - g t^2 / 2 exactly (central differences are exact for a",
        "constant acceleration; no deformation). Checked to 1e-9 relative at t = 10 ms.",
        run_line("free_fall"), CHECK])
    grid, el = d.block(1, 1, 1, (10.0, 10.0, 10.0))
    d.law1(1, "elastic", 1e-6, 0.01, 0.3)
    d.prop_solid(1, "solid")
    d.part(1, "cube", 1, 1)
    d.bricks(1, el)
    d.grnod_node(1, "all", sorted(grid.values()))
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
    d = Deck(name, head + [run_line(name), CHECK])
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
    d.prop_solid(1, "solid")
    d.part(1, "big", 1, 1)
    d.part(2, "thin", 1, 1)
    d.bricks(1, [els[0], els[2]])
    d.bricks(2, [els[1]])
    d.th("PART", 1, "mass", ["AM", "M"], [1, 2])
    d.engine(0.02, 0.002, print_every=10, nodal_dt=(0.9, tmin), stop=(0.0, 0.01) if stop else None)
    d.write()


def energy_impact():
    E, nu, rho, v0 = 0.2, 0.3, 7.85e-6, 5.0
    d = Deck("energy_impact", [
        "energy_impact: an elastic block (4 x 4 x 8 bricks, 10 x 10 x 20 mm, LAW1) moving at",
        f"{v0} mm/ms hits a fixed wall (its bottom face stops: /BCS) and bounces in the elastic",
        "waves. What it shows: kinetic + internal + hourglass stays equal to the initial kinetic",
        "energy 0.5 m v0^2 (no external work from fixed nodes) within 0.1%.",
        run_line("energy_impact"), CHECK])
    grid, el = d.block(4, 4, 8, (10.0, 10.0, 20.0))
    d.law1(1, "steel", rho, E, nu)
    d.prop_solid(1, "solid")
    d.part(1, "block", 1, 1)
    d.bricks(1, el)
    bottom = face(grid, 2, 0)
    d.grnod_node(1, "bottom", bottom)
    d.grnod_node(2, "others", sorted(set(grid.values()) - set(bottom)))
    d.bcs(1, "bottom", "111", 1)
    d.inivel(1, "impact", (0.0, 0.0, -v0), 2)
    d.th("PART", 1, "energies", ["IE", "KE", "HE"], [1])
    d.engine(0.5, 0.005, print_every=100)
    d.write()


def law34_impact(name, header, tstop, nodal):
    rho, K, G0, Ginf, beta = 1.0e-6, 2.0e-2, 2.0e-4, 1.0e-4, 0.1
    d = Deck(name, header)
    n, L = 8, 40.0
    grid, el = d.block(n, n, n // 2, (L, L, L / 2))
    d.law34(1, "soft tissue", rho, K, G0, Ginf, beta)
    d.prop_solid(1, "solid: Isolid 24, physical hourglass", isolid=24)
    d.part(1, "tissue block", 1, 1)
    d.bricks(1, el)
    bottom = face(grid, 2, 0)
    top = [grid[(i, j, n // 2)] for i in range(2, 7) for j in range(2, 7)]
    d.grnod_node(1, "bottom", bottom)
    d.grnod_node(2, "punch", top)
    d.bcs(1, "bottom", "111", 1)
    d.funct(1, "constant", [(0, 1), (100, 1)])
    d.impvel(1, "punch", 1, "Z", 2, -6.7)
    d.bcs(2, "punch xy", "110", 2)
    d.th_nodes(1, "punch", ["DZ", "VZ"], [(grid[(4, 4, n // 2)], "punch centre")])
    d.th("PART", 2, "energies", ["IE", "HE", "KE"], [1])
    d.engine(tstop, tstop / 50, anim=tstop / 5, print_every=100, nodal_dt=nodal)
    d.write()


def inverted():
    d = Deck("inverted_element", [
        "inverted_element: planted failure. One soft brick whose top face is driven down at",
        "100 mm/ms through its bottom face (fixed): the element turns inside out at about",
        "t = 0.01 ms. What it shows: the run stops cleanly with 'element 1 of part 1 ...",
        "inverted (negative volume) at time ...', exit code 3, the time history and the",
        "animation written up to that time are valid.", run_line("inverted_element"), CHECK])
    grid, el = d.block(1, 1, 1, (1.0, 1.0, 1.0))
    d.law1(1, "soft", 1e-6, 1e-3, 0.3)
    d.prop_solid(1, "solid")
    d.part(1, "cube", 1, 1)
    d.bricks(1, el)
    d.grnod_node(1, "bottom", face(grid, 2, 0))
    d.grnod_node(2, "top", face(grid, 2, 1))
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
        run_line("tetra_prism_uniaxial"), CHECK])
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
    d.prop_solid(1, "solid", qa=1e-30, qb=1e-30)  # no bulk viscosity (0 reads as the default)
    d.part(1, "tetra cube", 1, 1)
    d.part(2, "prism cube", 1, 1)
    d.tetras(1, tets)
    d.bricks(2, prisms)
    allg = {**{("a",) + k: v for k, v in g.items()}, **{("b",) + k: v for k, v in h.items()}}
    d.grnod_node(1, "x0", [v for k, v in allg.items() if k[1] == 0])
    d.grnod_node(2, "ylow", [v for k, v in allg.items() if k[2] == 0])
    d.grnod_node(3, "z0", [v for k, v in allg.items() if k[3] == 0])
    d.grnod_node(4, "x1", [v for k, v in allg.items() if k[1] == 1])
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

    def material(d):
        d.funct(2, "yield curve", [(0.0, 3.0e-4), (0.1, 5.0e-4), (1.0, 5.0e-4)])
        d.law36(1, "tabulated", rho, E, nu, 0.03, 2)

    d = single_element("law36_erosion", [
        "law36_erosion: one LAW36 brick (tabulated yield curve: 3e-4 GPa at eps_p = 0 rising",
        "linearly to 5e-4 GPa at eps_p = 0.1), EPS_p_max = 0.03, pulled to 6% strain in 5 ms.",
        "What it shows: before failure sigma_xx = f(eps_p), eps_p = ln(L) - sigma/E (1%);",
        "the element is deleted when eps_p reaches 0.03 (counted for part 1, its internal",
        "energy kept in the balance), the run ends normally.", run_line("law36_erosion"), CHECK],
        material, 5.0, 0.06, node_vars=["DX"], part_vars=["IE", "ER"])
    d.engine(5.0, 0.05, print_every=1000)
    d.write()


def law36_rate_filter():
    E, nu, rho = 0.2, 0.3, 7.85e-6

    def material(d):
        d.funct(2, "yield curve", [(0.0, 3.0e-4), (0.1, 5.0e-4), (1.0, 5.0e-4)])
        d.law36_rates(1, "tabulated, two strain rates", rho, E, nu, 0.0, [(2, 1.0, 0.0), (2, 2.0, 0.05)], 0.2)

    d = single_element("law36_rate_filter", [
        "law36_rate_filter: one LAW36 brick with yield curves at two strain rates, f(eps_p) at",
        "rate 0 and 2 f at 0.05 /ms (f: 3e-4 GPa at eps_p = 0 rising to 5e-4 GPa at 0.1),",
        "F_cut = 0.2 /ms, pulled at 0.0126 mm/ms after a 0.5 ms ramp, to 1 ms.",
        "What it shows: the yield stress is f(eps_p) (1 + r / 0.05) at the element's strain rate",
        "r filtered as OpenRadioss does (r_n = a r + (1 - a) r_(n-1), a = 2 pi F_cut dt):",
        "sigma_xx matches it (0.5%) while the rate of the pull would give 5% more or above.",
        run_line("law36_rate_filter"), "Checked by ctest/solver/run_strain_rate_filter_verification.cpp "
        "(label verification)."], material, 5.0, 0.06, node_vars=["DX"], part_vars=["IE"])
    d.engine(1.0, 0.05, print_every=1000)
    d.write()


if __name__ == "__main__":
    tetra_prism_uniaxial()
    law36_erosion()
    law36_rate_filter()
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
        "Hourglass: physical stabilisation in the corotational frame (Isolid 24).",
        "What it shows: no inverted element, normal termination, hourglass energy below 10%",
        "of the internal energy at the end (5 mm indentation).",
        run_line("law34_impact"), CHECK], 0.75, None)
    law34_impact("impact", [
        "impact: the example run by scripts/main-job.sh. A flat punch hits a LAW34 soft-tissue",
        "block at 6.7 m/s (8 mm indentation), bottom face fixed, fixed time step 1.5e-3 ms",
        "with nodal mass scaling (/DT/NODA/CST 0.9 1.5e-3) as the body model runs.",
        "Outputs: listing impact_0001.out, CSV time histories, VTK frames + impact.pvd.",
        run_line("impact")], 1.2, (0.9, 1.5e-3))
    inverted()
