#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Generates contact_tied_bar_0000.rad / _0001.rad (see HEADER):
#   python3 decks/examples/contact_tied_bar/make_deck.py
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_tools"))
import radioss_deck as rd  # noqa: E402

NAME = "contact_tied_bar"
RHO, E, NU = 1.0e-6, 1.0, 0.0          # c = sqrt(E/rho) = 1000 mm/ms, no lateral effect
A, LH, T, V = 10.0, 100.0, 0.05, 1.0    # section side, half length [mm], pulse [ms], amplitude [mm/ms]
HEADER = [
    "contact_tied_bar: a bar made of two non-matching brick meshes tied by /INTER/TYPE2.",
    f"Bar 1 (y = 0): x in [0, {LH}] meshed 4x4 across, x in [{LH}, {2 * LH}] meshed 3x3 across",
    "(element lengths 2.5 and 3.33 mm); the 3x3 part's nodes at x = 100 are tied to the 4x4",
    "part's outer faces. Bar 2 (y = 30): the same bar in one 4x4 mesh (control).",
    f"A half-sine velocity pulse ({V} mm/ms, {T} ms) is imposed at x = 0 (E = {E} GPa,",
    "nu = 0, c = 1000 mm/ms). What it shows: the wave crosses the tie; at x = 50 the",
    "difference between the tied bar and the control bar during the time the interface",
    "reflection would pass (0.13-0.25 ms) stays under 2% of the incident amplitude, and the",
    "transmitted pulse at x = 150 carries the incident amplitude.",
    "Run: hbm-solver decks/examples/contact_tied_bar/contact_tied_bar_0000.rad",
    "Checked by ctest/solver/contact_decks_verification.cpp (label verification).",
]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    s = rd.Starter(NAME, HEADER)
    # Bar 1: left 40 x 4 x 4 (h 2.5), right 30 x 3 x 3 (h 3.333).
    nl, bl, idl = rd.block_mesh(40, 4, 4, 2.5, (0.0, 0.0, 0.0), 1, 1)
    hr = A / 3
    nr, br, idr = rd.block_mesh(30, 3, 3, (LH / 30, hr, hr), (LH, 0.0, 0.0), 10001, 10001)
    # Bar 2 (control): 80 x 4 x 4.
    nc, bc, idc = rd.block_mesh(80, 4, 4, 2.5, (0.0, 30.0, 0.0), 20001, 20001)
    s.nodes(nl + nr + nc)
    s.bricks(1, bl)
    s.bricks(2, br)
    s.bricks(3, bc)
    s.part(1, "bar 1 left 4x4", 1, 1)
    s.part(2, "bar 1 right 3x3", 1, 1)
    s.part(3, "bar 2 control", 1, 1)
    s.prop_solid(1, "bricks")
    s.law1(1, "elastic", RHO, E, NU)
    s.grnod_node(1, "right part nodes at x = 100", [idr(0, j, k) for k in range(4) for j in range(4)])
    s.surf_part(1, "left part faces", [1])
    s.inter2(1, "tie", 1, 1, dsearch=0.1)
    s.grnod_node(2, "loaded ends", [idl(0, j, k) for k in range(5) for j in range(5)] +
                 [idc(0, j, k) for k in range(5) for j in range(5)])
    pts = [(T * i / 40, V * math.sin(math.pi * i / 40)) for i in range(41)] + [(1.0, 0.0)]
    s.funct(1, "half-sine pulse", pts)
    s.impvel(1, "pulse", 1, "X", 2, 1.0)
    s.th_nodes(2, "gauges", ["VX"], [(idl(20, 2, 2), "bar1 x50"), (idr(15, 1, 1), "bar1 x150"),
                                     (idc(20, 2, 2), "control x50"), (idc(60, 2, 2), "control x150")])
    s.th("INTER", 3, "tie force", ["DEF"], [1])
    s.write(os.path.join(here, f"{NAME}_0000.rad"))
    rd.write_atomic(os.path.join(here, f"{NAME}_0001.rad"),
                    rd.engine(NAME, HEADER[:1], tstop=0.3, dt_his=0.001, anim_dt=0.05))


if __name__ == "__main__":
    main()
