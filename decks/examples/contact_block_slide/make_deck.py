#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Generates contact_block_slide_0000.rad / _0001.rad (see HEADER):
#   python3 decks/examples/contact_block_slide/make_deck.py
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "deck_tools"))
from radioss_deck import ANIM_CONTACT, Deck  # noqa: E402

NAME = "contact_block_slide"
MU, G, V0, GAP = 0.3, 1.0, 0.3, 0.2     # -, mm/ms^2, mm/ms, mm
RHO, E, NU = 1.0e-6, 0.1, 0.3
HEADER = [
    "contact_block_slide: Coulomb friction of /INTER/TYPE7 and of /RWALL/PLANE (Slide = 2).",
    "Two elastic 4 mm brick blocks (2x2x2 bricks) slide at 0.3 mm/ms in +X under gravity",
    f"g = {G} mm/ms^2 (scaled gravity, 1000 m/s^2, so that the test lasts 1 ms) with mu = {MU}:",
    "block 2 on a fixed brick slab through TYPE7 (gap 0.2 mm, VISs 0.3 to damp the",
    "settling bounce), block 3 on the fixed plane wall z = 0.",
    f"Analytic: both decelerate at mu g = {MU * G} mm/ms^2 and stop at t = V0/(mu g) = 1 ms;",
    "the wall force is the weight m g = 6.4e-5 kN normal and mu m g tangential.",
    "Run: hbm-solver decks/examples/contact_block_slide/contact_block_slide_0000.rad",
    "Checked by ctest/solver/contact_decks_verification.cpp (label verification, 2%).",
]


def main():
    d = Deck(NAME, HEADER)
    _, bg = d.block(8, 3, 1, (16.0, 6.0, 2.0), (0.0, 0.0, -2.0))
    g2, b2 = d.block(2, 2, 2, (4.0, 4.0, 4.0), (2.0, 1.0, GAP), first_node=1001, first_elem=1001)
    g3, b3 = d.block(2, 2, 2, (4.0, 4.0, 4.0), (30.0, 1.0, 0.0), first_node=2001, first_elem=2001)
    d.bricks(1, bg)
    d.bricks(2, b2)
    d.bricks(3, b3)
    d.part(1, "ground slab", 1, 1)
    d.part(2, "block on slab", 1, 1)
    d.part(3, "block on wall", 1, 1)
    d.prop_solid(1, "bricks")
    d.law1(1, "elastic", RHO, E, NU)
    d.grnod_part(1, "ground", [1])
    d.grnod_part(2, "block 2", [2])
    d.grnod_part(3, "block 3", [3])
    d.grnod_part(4, "blocks", [2, 3])
    d.surf_part(1, "slab surface", [1])
    d.bcs(1, "ground fixed", "111", 1)
    d.inter7(1, "block on slab", 2, 1, fric=MU, gapmin=GAP, vis_s=0.3)
    d.rwall_plane(1, "floor wall", (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), slide=2, fric=MU, grnod1=3)
    d.funct(1, "constant", [(0.0, 1.0), (100.0, 1.0)])
    d.grav(1, "scaled gravity", 1, "Z", 4, -G)
    d.inivel(1, "slide", (V0, 0.0, 0.0), 4)
    d.th("INTER", 1, "slab contact", ["DEF"], [1])
    d.th("RWALL", 2, "wall", ["DEF"], [1])
    d.th_nodes(3, "block velocities", ["VX", "VZ"], [(n, "") for n in [*g2.values(), *g3.values()]])
    d.engine(0.9, 0.01, anim=0.1, anim_outputs=ANIM_CONTACT)
    d.write()

if __name__ == "__main__":
    main()
