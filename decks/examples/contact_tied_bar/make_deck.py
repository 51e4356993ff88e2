#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Generates contact_tied_bar_0000.rad / _0001.rad (see HEADER):
#   python3 decks/examples/contact_tied_bar/make_deck.py
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "deck_tools"))
from radioss_deck import ANIM_CONTACT, Deck  # noqa: E402

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
    d = Deck(NAME, HEADER)
    # Bar 1: left 40 x 4 x 4 (h 2.5), right 30 x 3 x 3 (h 3.333).
    gl, bl = d.block(40, 4, 4, (LH, A, A), (0.0, 0.0, 0.0))
    gr, br = d.block(30, 3, 3, (LH, A, A), (LH, 0.0, 0.0), first_node=10001, first_elem=10001)
    # Bar 2 (control): 80 x 4 x 4.
    gc, bc = d.block(80, 4, 4, (2 * LH, A, A), (0.0, 30.0, 0.0), first_node=20001, first_elem=20001)
    d.bricks(1, bl)
    d.bricks(2, br)
    d.bricks(3, bc)
    d.part(1, "bar 1 left 4x4", 1, 1)
    d.part(2, "bar 1 right 3x3", 1, 1)
    d.part(3, "bar 2 control", 1, 1)
    d.prop_solid(1, "bricks")
    d.law1(1, "elastic", RHO, E, NU)
    d.grnod_node(1, "right part nodes at x = 100", [gr[(0, j, k)] for k in range(4) for j in range(4)])
    d.surf_part(1, "left part faces", [1])
    d.inter2(1, "tie", 1, 1, dsearch=0.1)
    d.grnod_node(2, "loaded ends", [gl[(0, j, k)] for k in range(5) for j in range(5)] +
                 [gc[(0, j, k)] for k in range(5) for j in range(5)])
    pts = [(T * i / 40, V * math.sin(math.pi * i / 40)) for i in range(41)] + [(1.0, 0.0)]
    d.funct(1, "half-sine pulse", pts)
    d.impvel(1, "pulse", 1, "X", 2, 1.0)
    d.th_nodes(2, "gauges", ["VX"], [(gl[(20, 2, 2)], "bar1 x50"), (gr[(15, 1, 1)], "bar1 x150"),
                                     (gc[(20, 2, 2)], "control x50"), (gc[(60, 2, 2)], "control x150")])
    d.th("INTER", 3, "tie force", ["DEF"], [1])
    d.engine(0.3, 0.001, anim=0.05, anim_outputs=ANIM_CONTACT)
    d.write()

if __name__ == "__main__":
    main()
