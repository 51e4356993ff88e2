#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Generates contact_sphere_rwall_0000.rad / _0001.rad (see HEADER):
#   python3 decks/examples/contact_sphere_rwall/make_deck.py
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "deck_tools"))
from radioss_deck import ANIM_CONTACT, Deck  # noqa: E402

NAME = "contact_sphere_rwall"
R, RHO, E, NU, V0 = 10.0, 1.0e-6, 0.01, 0.3, 1.0   # mm, kg/mm^3, GPa, -, mm/ms
N, M = 16, 8                                       # cube divisions, layers of the outer shell
# Hertz, elastic sphere on a rigid plane (Johnson, Contact Mechanics, 1985, §11.4):
#   E* = E / (1 - nu^2), m = rho 4/3 pi R^3,
#   delta_max = (15 m V0^2 / (16 E* sqrt(R)))^(2/5),  F_max = 4/3 E* sqrt(R) delta_max^(3/2),
#   contact duration t_c = 2.94 delta_max / V0.
ESTAR = E / (1 - NU * NU)
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
DMAX = (15 * MASS * V0 ** 2 / (16 * ESTAR * math.sqrt(R))) ** 0.4
FMAX = 4.0 / 3.0 * ESTAR * math.sqrt(R) * DMAX ** 1.5
TC = 2.94 * DMAX / V0
HEADER = [
    "contact_sphere_rwall: elastic brick sphere dropped on a fixed /RWALL/PLANE.",
    f"Sphere R = {R} mm (cube-sphere brick mesh, {N}^3 + 6x{N}x{N}x{M} bricks), LAW1 E = {E} GPa,",
    f"nu = {NU}, rho = {RHO} kg/mm^3, hits the wall z = 0 at {V0} mm/ms (no gravity).",
    "What it shows: the wall force peak (/TH/RWALL FNZ) matches Hertz within 10% and the",
    "sphere rebounds with (almost) its impact speed.",
    f"Hertz (Johnson 1985): m = {MASS:.6g} kg, delta_max = {DMAX:.4g} mm, F_max = {FMAX:.5g} kN,",
    f"contact duration {TC:.4g} ms. Rebound: elastic, e = 1 minus the energy left in vibrations.",
    "Run: hbm-solver decks/examples/contact_sphere_rwall/contact_sphere_rwall_0000.rad",
    "Checked by ctest/solver/contact_decks_verification.cpp (label verification).",
]


def sphere_mesh():
    """Cube-sphere: inner cube of half size c split N^3, six blocks of M layers mapping the
    cube faces to the sphere. Duplicate nodes merged by position."""
    c = 0.35 * R
    ids = {}
    nodes = []

    def node(p):
        key = tuple(round(x, 9) for x in p)
        if key not in ids:
            ids[key] = len(nodes) + 1
            nodes.append((ids[key],) + p)
        return ids[key]

    def cube_point(i, j, k):
        return tuple(-c + 2 * c * t / N for t in (i, j, k))

    def mapped(q, t):
        # From cube surface point q (t = 0) to the sphere (t = 1), blending towards a
        # sphere-like inner surface to keep elements regular.
        r = math.sqrt(sum(x * x for x in q))
        s = tuple(R * x / r for x in q)
        return tuple((1 - t) * a + t * b for a, b in zip(q, s))

    hexes = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                corners = [(i, j, k), (i + 1, j, k), (i + 1, j + 1, k), (i, j + 1, k),
                           (i, j, k + 1), (i + 1, j, k + 1), (i + 1, j + 1, k + 1), (i, j + 1, k + 1)]
                hexes.append([node(cube_point(*q)) for q in corners])
    # Six faces: axis a, side s (+1/-1); face grid (u, v) over the other two axes.
    for a in range(3):
        for s in (-1, 1):
            b, d = [x for x in range(3) if x != a]

            def face_point(u, v, layer):
                q = [0.0, 0.0, 0.0]
                q[a] = s * c
                q[b] = -c + 2 * c * u / N
                q[d] = -c + 2 * c * v / N
                return mapped(tuple(q), layer / M)

            for l in range(M):
                for v in range(N):
                    for u in range(N):
                        bottom = [face_point(u, v, l), face_point(u + 1, v, l), face_point(u + 1, v + 1, l),
                                  face_point(u, v + 1, l)]
                        top = [face_point(u, v, l + 1), face_point(u + 1, v, l + 1),
                               face_point(u + 1, v + 1, l + 1), face_point(u, v + 1, l + 1)]
                        hexes.append([node(p) for p in bottom + top])
    # Positive Jacobian: n1-n4 counter-clockwise seen from n5-n8.
    xyz = {n[0]: n[1:] for n in nodes}
    fixed = []
    for h in hexes:
        p = [xyz[n] for n in h]
        e1 = [p[1][t] - p[0][t] for t in range(3)]
        e2 = [p[3][t] - p[0][t] for t in range(3)]
        e3 = [p[4][t] - p[0][t] for t in range(3)]
        det = (e1[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - e1[1] * (e2[0] * e3[2] - e2[2] * e3[0])
               + e1[2] * (e2[0] * e3[1] - e2[1] * e3[0]))
        fixed.append(h if det > 0 else [h[0], h[3], h[2], h[1], h[4], h[7], h[6], h[5]])
    return nodes, fixed


def main():
    nodes, hexes = sphere_mesh()
    z0 = R + 0.01  # lowest point 0.01 mm above the wall
    nodes = [(n, x, y, z + z0) for n, x, y, z in nodes]
    centre = min(nodes, key=lambda n: n[1] ** 2 + n[2] ** 2 + (n[3] - z0) ** 2)[0]
    d = Deck(NAME, HEADER)
    for n, x, y, z in nodes:
        d.node(x, y, z, n)
    d.bricks(1, [(e + 1, h) for e, h in enumerate(hexes)])
    d.part(1, "sphere", 1, 1)
    d.prop_solid(1, "bricks")
    d.law1(1, "soft elastic", RHO, E, NU)
    d.grnod_part(1, "sphere nodes", [1])
    d.rwall_plane(1, "ground", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), slide=0, grnod1=1)
    d.inivel(1, "drop", (0.0, 0.0, -V0), 1)
    d.th("RWALL", 1, "wall force", ["DEF"], [1])
    d.th_nodes(2, "centre", ["VZ", "DZ"], [(centre, "centre")])
    d.engine(1.4, 0.002, anim=0.1, anim_outputs=ANIM_CONTACT)
    d.write()
    print(f"{len(nodes)} nodes, {len(hexes)} bricks; Hertz F_max {FMAX:.6g} kN, delta {DMAX:.4g} mm, t_c {TC:.4g} ms")


if __name__ == "__main__":
    main()
