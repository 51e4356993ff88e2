#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Generator of the shell verification decks decks/examples/shell_<case>/ (starter
<case>_0000.rad + engine <case>_0001.rad). Each deck's header comment says what it shows,
the analytic value, the tolerance and how to run it; ctest/solver/shelldecks_run_verification.cpp
runs them through hbm-solver. Regenerate with:
    python3 decks/examples/shell_tools/shell_decks.py
Units: kg, mm, ms (force kN, stress GPa, energy J). Cards are written by
decks/examples/deck_tools/radioss_deck.py."""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "deck_tools"))
from radioss_deck import Deck, run_line  # noqa: E402

CHECK = "Checked by ctest/solver/shelldecks_run_verification.cpp (label verification)."


def strip(d, nx, ny, L, b, tria, z=0.0):
    """Flat strip [0, L] x [0, b] of nx x ny quads (or pairs of triangles, diagonals
    alternating); returns node grid {(i, j): id} and elements."""
    grid = {}
    for i in range(nx + 1):
        for j in range(ny + 1):
            grid[(i, j)] = d.node(L * i / nx, b * j / ny, z)
    elems = []
    for i in range(nx):
        for j in range(ny):
            a, bb, c, e = grid[(i, j)], grid[(i + 1, j)], grid[(i + 1, j + 1)], grid[(i, j + 1)]
            if not tria:
                cells = [[a, bb, c, e]]
            elif (i + j) % 2 == 0:
                cells = [[a, bb, c], [a, c, e]]
            else:
                cells = [[a, bb, e], [bb, c, e]]
            for ns in cells:
                elems.append((d.next_elem, ns))
                d.next_elem += 1
    return grid, elems


def cantilever_grav(tria):
    name = "shell_cantilever_grav_" + ("tria" if tria else "quad")
    L, b, t, E, nu, rho = 50.0, 5.0, 1.0, 210.0, 0.3, 7.85e-6
    nx, ny = 20, 2
    I, A = b * t ** 3 / 12, b * t
    delta = 0.3
    g = 8 * E * I * delta / (rho * A * L ** 4)
    f1 = 1.87510407 ** 2 / (2 * math.pi * L ** 2) * math.sqrt(E * I / (rho * A))
    elem = "SH3N triangles (CST + DKT)" if tria else "SHELL quads (Belytschko-Tsay)"
    d = Deck(name, [
        f"{name}: cantilever plate strip L = {L} mm, b = {b} mm, t = {t} mm, {nx} x {ny} {elem},",
        f"steel LAW1 (E = {E} GPa, nu = {nu}), clamped at x = 0, gravity g = {g:.6f} mm/ms^2 applied",
        "suddenly at t = 0 (/GRAV, -Z). What it shows: the tip oscillates about the static",
        f"deflection q L^4 / (8 E I) = {delta:.6f} mm (q = rho g b t, I = b t^3 / 12; its mean over whole",
        f"periods) at the first bending frequency f1 = 1.8751^2/(2 pi L^2) sqrt(E I/(rho b t)) = {f1:.6f} kHz.",
        "Tolerance 3% on both.", run_line(name), CHECK])
    grid, el = strip(d, nx, ny, L, b, tria)
    d.law1(1, "steel", rho, E, nu)
    d.prop_shell(1, "plate 1 mm", t, 3)
    d.part(1, "strip", 1, 1)
    d.shells(1, el)
    d.grnod_node(1, "clamped end", [grid[(0, j)] for j in range(ny + 1)])
    d.grnod_node(2, "all nodes", sorted(grid.values()))
    d.bcs(1, "clamp", "111", 1, rot="111")
    d.funct(1, "constant", [(0, 1), (1000, 1)])
    d.grav(1, "gravity", 1, "Z", 2, -g)
    d.th_nodes(1, "tip", ["DZ"], [(grid[(nx, ny // 2)], "tip middle")])
    d.th("PART", 2, "energies", ["IE", "KE", "HE"], [1])
    d.engine(round(4.2 / f1, 3), 2.0e-3, anim=round(1.0 / f1, 3), print_every=5000)
    d.write()


def pulled_strip_part(d, grid, el, nx, ny, rot="000"):
    """Part 1 of the strip's shells; node groups 1 held end (x = 0), 2 pulled end (x = L),
    3 the corner (0, 0), 4 all nodes; the held end fixed in X, the corner in Y, every node in
    Z (and in the rotations `rot`)."""
    d.part(1, "strip", 1, 1)
    d.shells(1, el)
    d.grnod_node(1, "held end", [grid[(0, j)] for j in range(ny + 1)])
    d.grnod_node(2, "pulled end", [grid[(nx, j)] for j in range(ny + 1)])
    d.grnod_node(3, "corner", [grid[(0, 0)]])
    d.grnod_node(4, "all nodes", sorted(grid.values()))
    d.bcs(1, "held X", "100", 1)
    d.bcs(2, "corner Y", "010", 3)
    d.bcs(3, "in plane", "001", 4, rot=rot)


def pull_failure(tria):
    name = "shell_pull_failure_" + ("tria" if tria else "quad")
    L, b, t, E, nu, rho = 50.0, 10.0, 1.0, 210.0, 0.3, 7.85e-6
    a, bh, n, epsmax = 0.3, 0.2, 0.5, 0.1
    nx, ny = 10, 2
    v = 1.0
    eps_f = epsmax + (a + bh * epsmax ** n) / E
    u_f = L * (math.exp(eps_f) - 1)
    elem = "SH3N triangles (CST + DKT)" if tria else "SHELL quads (Belytschko-Tsay)"
    d = Deck(name, [
        f"{name}: strip {L} x {b} x {t} mm, {nx} x {ny} {elem}, LAW2 a = {a}, b = {bh}, n = {n},",
        f"EPS_p_max = {epsmax}; end x = 0 held in X, end x = L pulled at {v} mm/ms (ramped over 0.2 ms).",
        "What it shows: shells are deleted when their points reach EPS_p_max, i.e. at the log strain",
        f"eps_p_max + sigma_y(eps_p_max)/E = {eps_f:.6f}, end displacement {u_f:.4f} mm (tolerance 1%);",
        "the part's eroded count (TH/PART ER) rises, the animation frames flag the deleted cells",
        "(cell field 'eroded'), and the energy balance still closes within 1% afterwards.",
        run_line(name), CHECK])
    grid, el = strip(d, nx, ny, L, b, tria)
    d.law2(1, "steel JC", rho, E, nu, a, bh, n, epsmax)
    d.prop_shell(1, "plate 1 mm", t, 3)
    pulled_strip_part(d, grid, el, nx, ny)
    d.funct(1, "ramp", [(0, 0), (0.2, 1), (1000, 1)])
    d.impvel(1, "pull", 1, "X", 2, v)
    d.th_nodes(1, "pulled end", ["DX"], [(grid[(nx, 0)], "pulled corner")])
    d.th("PART", 2, "strip", ["IE", "KE", "ER"], [1])
    d.engine(round(u_f / v + 0.6, 3), 5.0e-3, anim=0.25, print_every=5000)
    d.write()


def pull_ogden(tria):
    name = "shell_pull_ogden_" + ("tria" if tria else "quad")
    L, b, t, rho = 50.0, 10.0, 1.0, 1.0e-6
    mu, alpha = (3.0e-4, 1.0e-6), (2.0, 24.0)
    nx, ny = 10, 2
    lam, T = 1.35, 40.0
    v = (lam - 1.0) * L / T
    w = sum(m / a * (lam ** a + 2 * lam ** (-a / 2) - 3) for m, a in zip(mu, alpha))
    elem = "SH3N triangles (CST + DKT)" if tria else "SHELL quads (Belytschko-Tsay)"
    d = Deck(name, [
        f"{name}: strip {L} x {b} x {t} mm, {nx} x {ny} {elem}, LAW42 Ogden mu = {mu[0]}, {mu[1]} GPa,",
        f"alpha = {alpha[0]}, {alpha[1]} (incompressible, Ithick 1); end x = 0 held in X, its sides free, end x = L",
        f"pulled at up to {v:.4f} mm/ms (ramps of 10 ms) to a uniaxial stretch of {lam}, then held.",
        "What it shows: the strain energy of the strip, L b t sum mu_p / alpha_p (l^a_p + 2 l^(-a_p/2) - 3)",
        f"= {w * L * b * t:.6e} J at l = {lam} (Ogden 1972), equals the part's internal energy less its kinetic",
        "energy averaged over the hold (the strip rings; tolerance 2%); the energy error stays within 1%.",
        run_line(name), CHECK])
    grid, el = strip(d, nx, ny, L, b, tria)
    d.law42(1, "skin-like Ogden", rho, mu, alpha)
    d.prop_shell(1, "membrane 1 mm", t, 3, ithick=1)
    pulled_strip_part(d, grid, el, nx, ny, rot="111")
    # Ramps of 10 ms, twenty periods of the strip's first stretching mode: it hardly rings.
    d.funct(1, "ramp, pull, hold", [(0, 0), (10.0, 1), (T, 1), (T + 10.0, 0), (1000, 0)])
    d.impvel(1, "pull", 1, "X", 2, v)
    d.th_nodes(1, "pulled end", ["DX"], [(grid[(nx, 0)], "pulled corner")])
    d.th("PART", 2, "strip", ["IE", "KE", "HE"], [1])
    d.engine(T + 15.0, 5.0e-3, anim=5.0, print_every=5000)
    d.write()


if __name__ == "__main__":
    for tria in (True, False):
        cantilever_grav(tria)
        pull_failure(tria)
        pull_ogden(tria)
