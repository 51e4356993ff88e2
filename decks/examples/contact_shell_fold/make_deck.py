#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Generates contact_shell_fold_0000.rad / _0001.rad (see HEADER):
#   python3 decks/examples/contact_shell_fold/make_deck.py
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "deck_tools"))
from radioss_deck import ANIM_CONTACT, Deck  # noqa: E402

NAME = "contact_shell_fold"
T, L, W, H, RF = 1.0, 40.0, 10.0, 2.0, 2.5   # thickness, leg length, width, element, fold radius [mm]
V0 = 10.0                                     # mm/ms
HEADER = [
    "contact_shell_fold: a shell strip folded onto itself, /INTER/TYPE7 self-contact.",
    f"A strip (t = {T} mm, {W} mm wide, 4-node shells of {H} mm) is bent into a U: two {L} mm",
    f"legs {2 * RF} mm apart joined by a half-circle fold. The lower leg is clamped (all nodes);",
    f"the upper leg is thrown onto the lower one at {V0} mm/ms. One TYPE7 interface, all",
    f"strip nodes secondary on the strip's own surface (self-contact), gap = t = {T} mm.",
    "What it shows: the legs never cross (mid-surface distance > 0 at every output), i.e.",
    "no penetration beyond the gap; the upper leg rebounds; contact energy in /TH/INTER.",
    "Run: hbm-solver decks/examples/contact_shell_fold/contact_shell_fold_0000.rad",
    "Checked by ctest/solver/contact_decks_verification.cpp (label verification).",
]


def main():
    nx, ny = int(L / H), int(W / H)
    narc = 4
    # Centre line of the U in the x-z plane: lower leg from x = L to 0 at z = 0, the
    # half circle around (0, RF), upper leg from 0 to L at z = 2 RF.
    line = [(L - i * H, 0.0) for i in range(nx)]
    line += [(-RF * math.sin(math.pi * k / narc), RF - RF * math.cos(math.pi * k / narc)) for k in range(narc)]
    line += [(i * H, 2 * RF) for i in range(nx + 1)]
    nid = lambda s, j: 1 + s + len(line) * j
    d = Deck(NAME, HEADER)
    for j in range(ny + 1):
        for s, (x, z) in enumerate(line):
            d.node(x, j * W / ny, z, nid(s, j))
    shells = []
    e = 1
    for j in range(ny):
        for s in range(len(line) - 1):
            shells.append((e, [nid(s, j), nid(s + 1, j), nid(s + 1, j + 1), nid(s, j + 1)]))
            e += 1
    d.shells(1, shells)
    d.part(1, "strip", 1, 1)
    d.prop_shell(1, "shell t = 1", T, 5, ishell=4)
    d.law1(1, "polymer", 1.0e-6, 0.2, 0.3)
    d.grnod_part(1, "strip nodes", [1])
    d.grnod_node(2, "clamped lower leg", [nid(s, j) for j in range(ny + 1) for s in range(nx)])
    upper = [nid(s, j) for j in range(ny + 1) for s in range(nx + narc, len(line))]
    d.grnod_node(3, "upper leg", upper)
    d.surf_part(1, "strip surface", [1])
    d.bcs(1, "clamp", "111", 2)
    d.inter7(1, "self contact", 1, 1, gapmin=T, vis_s=0.05)
    d.inivel(1, "throw", (0.0, 0.0, -V0), 3)
    pairs = []
    for x in (10.0, 20.0, 30.0):
        s_low = [s for s, (px, pz) in enumerate(line) if abs(px - x) < 1e-9 and pz == 0.0][0]
        s_up = [s for s, (px, pz) in enumerate(line) if abs(px - x) < 1e-9 and pz > 0][0]
        pairs += [(nid(s_low, ny // 2), f"lower x{int(x)}"), (nid(s_up, ny // 2), f"upper x{int(x)}")]
    d.th_nodes(2, "legs", ["DZ"], pairs)
    d.th("INTER", 3, "self contact", ["DEF", "NACT"], [1])
    d.engine(2.0, 0.005, anim=0.1, anim_outputs=ANIM_CONTACT)
    d.write()


if __name__ == "__main__":
    main()
