#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Generates contact_shell_fold_0000.rad / _0001.rad (see HEADER):
#   python3 decks/examples/contact_shell_fold/make_deck.py
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "contact_tools"))
import radioss_deck as rd  # noqa: E402

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
    here = os.path.dirname(os.path.abspath(__file__))
    nx, ny = int(L / H), int(W / H)
    narc = 4
    # Centre line of the U in the x-z plane: lower leg from x = L to 0 at z = 0, the
    # half circle around (0, RF), upper leg from 0 to L at z = 2 RF.
    line = [(L - i * H, 0.0) for i in range(nx)]
    line += [(-RF * math.sin(math.pi * k / narc), RF - RF * math.cos(math.pi * k / narc)) for k in range(narc)]
    line += [(i * H, 2 * RF) for i in range(nx + 1)]
    nid = lambda s, j: 1 + s + len(line) * j
    nodes = [(nid(s, j), x, j * W / ny, z) for j in range(ny + 1) for s, (x, z) in enumerate(line)]
    shells = []
    e = 1
    for j in range(ny):
        for s in range(len(line) - 1):
            shells.append((e, [nid(s, j), nid(s + 1, j), nid(s + 1, j + 1), nid(s, j + 1)]))
            e += 1
    st = rd.Starter(NAME, HEADER)
    st.nodes(nodes)
    st.shells(1, shells)
    st.part(1, "strip", 1, 1)
    st.prop_shell(1, "shell t = 1", T)
    st.law1(1, "polymer", 1.0e-6, 0.2, 0.3)
    st.grnod_part(1, "strip nodes", [1])
    st.grnod_node(2, "clamped lower leg", [nid(s, j) for j in range(ny + 1) for s in range(nx)])
    upper = [nid(s, j) for j in range(ny + 1) for s in range(nx + narc, len(line))]
    st.grnod_node(3, "upper leg", upper)
    st.surf_part(1, "strip surface", [1])
    st.bcs(1, "clamp", "111", 2)
    st.inter7(1, "self contact", 1, 1, gapmin=T, vis_s=0.05)
    st.inivel(1, "throw", (0.0, 0.0, -V0), 3)
    pairs = []
    for x in (10.0, 20.0, 30.0):
        s_low = [s for s, (px, pz) in enumerate(line) if abs(px - x) < 1e-9 and pz == 0.0][0]
        s_up = [s for s, (px, pz) in enumerate(line) if abs(px - x) < 1e-9 and pz > 0][0]
        pairs += [(nid(s_low, ny // 2), f"lower x{int(x)}"), (nid(s_up, ny // 2), f"upper x{int(x)}")]
    st.th_nodes(2, "legs", ["DZ"], pairs)
    st.th("INTER", 3, "self contact", ["DEF", "NACT"], [1])
    st.write(os.path.join(here, f"{NAME}_0000.rad"))
    rd.write_atomic(os.path.join(here, f"{NAME}_0001.rad"),
                    rd.engine(NAME, HEADER[:1], tstop=2.0, dt_his=0.005, anim_dt=0.1))


if __name__ == "__main__":
    main()
