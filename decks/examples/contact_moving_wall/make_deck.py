#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Generates contact_moving_wall_0000.rad / _0001.rad (see HEADER). Run from anywhere:
#   python3 decks/examples/contact_moving_wall/make_deck.py
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "deck_tools"))
from radioss_deck import ANIM_CONTACT, Deck  # noqa: E402

NAME = "contact_moving_wall"
N, L = 4, 10.0                      # elements per edge, block edge [mm]
RHO, E, NU = 1.0e-6, 0.01, 0.3      # kg/mm^3, GPa, -
MW, VW = 2.0e-3, 3.0                # wall mass [kg], wall speed [mm/ms]
WALL_NODE = 1000
HEADER = [
    "contact_moving_wall: a moving /RWALL/PLANE of given mass strikes an elastic block.",
    f"Wall node {WALL_NODE} (Mass {MW} kg, VX0 {VW} mm/ms) carries a plane with normal +X, 0.5 mm",
    f"behind a free {L} mm cube of {N}x{N}x{N} LAW1 bricks (mass rho L^3 = 1e-3 kg) at rest.",
    "What it shows: the wall and the block exchange momentum through the wall reaction only, so",
    f"the total X momentum Mw vw + sum m_i v_i stays Mw VW = {MW * VW:g} kg mm/ms to round-off",
    "(output precision) at every time-history row, before, during and after the impact.",
    "Run: hbm-solver decks/examples/contact_moving_wall/contact_moving_wall_0000.rad",
    "Checked by ctest/solver/contact_decks_verification.cpp (label verification).",
]


def main():
    d = Deck(NAME, HEADER)
    grid, bricks = d.block(N, N, N, (L, L, L), (0.0, 0.0, 0.0))
    d.node(-0.5, 0.5 * L, 0.5 * L, WALL_NODE)
    d.bricks(1, bricks)
    d.part(1, "block", 1, 1)
    d.prop_solid(1, "bricks")
    d.law1(1, "soft elastic", RHO, E, NU)
    d.grnod_part(1, "block nodes", [1])
    d.rwall_plane(1, "moving wall", None, (1.0, 0.5 * L, 0.5 * L), grnod1=1,
                  node=WALL_NODE, mass=MW, v0=(VW, 0.0, 0.0))
    d.th("RWALL", 1, "wall force", ["DEF"], [1])
    d.th_nodes(2, "velocities", ["VX"], [(WALL_NODE, "wall")] + [(n, "") for n in grid.values()])
    d.engine(2.0, 0.01, anim=0.5, anim_outputs=ANIM_CONTACT)
    d.write()

if __name__ == "__main__":
    main()
