#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Generates contact_blocks_collide_0000.rad / _0001.rad (see HEADER). Run from anywhere:
#   python3 decks/examples/contact_blocks_collide/make_deck.py
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "deck_tools"))
from radioss_deck import ANIM_CONTACT, Deck  # noqa: E402

NAME = "contact_blocks_collide"
N, L, GAP0, V0 = 6, 10.0, 0.5, 5.0           # elements per edge, edge [mm], initial gap [mm], speed [mm/ms]
RHO, E, NU = 1.0e-6, 0.01, 0.3               # kg/mm^3, GPa, -
HEADER = [
    "contact_blocks_collide: two elastic brick blocks collide through /INTER/TYPE7.",
    f"Block A ({N}x{N}x{N} bricks, {L} mm cube) moves at {V0} mm/ms in +X towards block B at rest,",
    f"{GAP0} mm away. Two TYPE7 interfaces (A nodes on B's surface, B nodes on A's surface), no",
    "friction, no contact damping (VISs = 1e-30: 0 or blank reads as 0.05, as in OpenRadioss).",
    "What it shows: total X momentum is conserved to",
    "the output precision (the contact forces are equal and opposite by construction) and the",
    "energy balance (kinetic + internal + hourglass + contact = initial) holds within 1%; after",
    "separation the contact energy is back to ~0. Bulk viscosity is off (qa = qb = 1e-30; 0 reads as the default) so that",
    "the balance isolates the contact (with the default qa, qb the balance reads -1.15%, see",
    "the contact report: the solid's bulk-viscosity accounting, not the contact).",
    "Analytic values: momentum m V0 with m = rho L^3 = 1e-3 kg -> 5e-3 kg mm/ms; energy",
    "0.5 m V0^2 = 1.25e-2 J.",
    "Run: hbm-solver decks/examples/contact_blocks_collide/contact_blocks_collide_0000.rad",
    "Checked by ctest/solver/contact_decks_verification.cpp (label verification).",
]


def main():
    d = Deck(NAME, HEADER)
    ga, ba = d.block(N, N, N, (L, L, L), (0.0, 0.0, 0.0))
    gb, bb = d.block(N, N, N, (L, L, L), (L + GAP0, 0.0, 0.0))
    d.bricks(1, ba)
    d.bricks(2, bb)
    d.part(1, "block A", 1, 1)
    d.part(2, "block B", 1, 1)
    d.prop_solid(1, "bricks", qa=1e-30, qb=1e-30)
    d.law1(1, "soft elastic", RHO, E, NU)
    d.grnod_part(1, "nodes of A", [1])
    d.grnod_part(2, "nodes of B", [2])
    d.surf_part(1, "surface of A", [1])
    d.surf_part(2, "surface of B", [2])
    d.inter7(1, "A nodes on B", 1, 2, gapmin=0.2, vis_s=1e-30)
    d.inter7(2, "B nodes on A", 2, 1, gapmin=0.2, vis_s=1e-30)
    d.inivel(1, "A moves", (V0, 0.0, 0.0), 1)
    d.th("INTER", 1, "contact forces", ["DEF"], [1, 2])
    d.th_nodes(2, "all node velocities", ["VX"], [(n, "") for n in [*ga.values(), *gb.values()]])
    d.engine(0.8, 0.005, anim=0.1, anim_outputs=ANIM_CONTACT)
    d.write()

if __name__ == "__main__":
    main()
