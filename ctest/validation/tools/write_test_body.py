#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes a small stand-in body model (an include file without /BEGIN, like
decks/hbm50/hbm50.inc) for the load-case generator's regression test: a block of soft
LAW1 bricks (x -240..100, y -160..160, z 200..460 mm, 40 mm cells)
covered by skin shells (part "skin_thorax"), a strip of triangles on the front face titled
"sternum" sharing the skin nodes, and the bricks around the T8 body centre of
geometry/spine_landmarks.csv in part "thoracic_vertebrae". Units kg, mm, ms, GPa.

Usage: write_test_body.py OUT.inc [--omit-sternum]
"""
import sys

def main():
    if len(sys.argv) < 2:
        sys.exit("usage: write_test_body.py OUT.inc [--omit-sternum]")
    out, omit_sternum = sys.argv[1], "--omit-sternum" in sys.argv[2:]
    xs = [-240 + 40 * i for i in range(9)]   # -240 .. 80, then front face at 100
    xs.append(100)
    ys = [-160 + 40 * i for i in range(9)]
    zs = [200 + 40 * i for i in range(7)] + [460]
    nid = {}
    lines = ["# Stand-in body for the hbm-loadcase regression test (ctest/validation/tools/write_test_body.py).",
             "/NODE"]
    for k, z in enumerate(zs):
        for j, y in enumerate(ys):
            for i, x in enumerate(xs):
                n = len(nid) + 1
                nid[(i, j, k)] = n
                lines.append(f"{n:10d}{x:20.6f}{y:20.6f}{z:20.6f}")
    ni, nj, nk = len(xs), len(ys), len(zs)
    # T8 body centre (-195.6, 0, 330): cells whose centre is within 45 mm of it are spine.
    def cell_centre(i, j, k):
        return ((xs[i] + xs[i + 1]) / 2, (ys[j] + ys[j + 1]) / 2, (zs[k] + zs[k + 1]) / 2)
    flesh, spine = [], []
    for k in range(nk - 1):
        for j in range(nj - 1):
            for i in range(ni - 1):
                c = [nid[(i, j, k)], nid[(i + 1, j, k)], nid[(i + 1, j + 1, k)], nid[(i, j + 1, k)],
                     nid[(i, j, k + 1)], nid[(i + 1, j, k + 1)], nid[(i + 1, j + 1, k + 1)], nid[(i, j + 1, k + 1)]]
                x, y, z = cell_centre(i, j, k)
                near = ((x + 195.6) ** 2 + y ** 2 + (z - 330.0) ** 2) ** 0.5 < 45
                (spine if near else flesh).append(c)
    eid = [0]
    def block(kw, part, elems):
        lines.append(f"{kw}/{part}")
        for e in elems:
            eid[0] += 1
            lines.append(f"{eid[0]:10d}" + "".join(f"{n:10d}" for n in e))
    block("/BRICK", 1, flesh)
    block("/BRICK", 2, spine)
    # Skin: all outer faces, outward normals.
    skin = []
    for k in range(nk - 1):
        for j in range(nj - 1):
            skin.append([nid[(ni - 1, j, k)], nid[(ni - 1, j + 1, k)], nid[(ni - 1, j + 1, k + 1)], nid[(ni - 1, j, k + 1)]])
            skin.append([nid[(0, j, k)], nid[(0, j, k + 1)], nid[(0, j + 1, k + 1)], nid[(0, j + 1, k)]])
        for i in range(ni - 1):
            skin.append([nid[(i, nj - 1, k)], nid[(i, nj - 1, k + 1)], nid[(i + 1, nj - 1, k + 1)], nid[(i + 1, nj - 1, k)]])
            skin.append([nid[(i, 0, k)], nid[(i + 1, 0, k)], nid[(i + 1, 0, k + 1)], nid[(i, 0, k + 1)]])
    for j in range(nj - 1):
        for i in range(ni - 1):
            skin.append([nid[(i, j, nk - 1)], nid[(i + 1, j, nk - 1)], nid[(i + 1, j + 1, nk - 1)], nid[(i, j + 1, nk - 1)]])
            skin.append([nid[(i, j, 0)], nid[(i, j + 1, 0)], nid[(i + 1, j + 1, 0)], nid[(i + 1, j, 0)]])
    block("/SHELL", 3, skin)
    # Sternum: triangles on the front face, |y| <= 40, 240 <= z <= 420.
    tri = []
    for k in range(nk - 1):
        for j in range(nj - 1):
            if abs(ys[j]) <= 40 and abs(ys[j + 1]) <= 40 and zs[k] >= 240 and zs[k + 1] <= 420:
                a, b = nid[(ni - 1, j, k)], nid[(ni - 1, j + 1, k)]
                c, d = nid[(ni - 1, j + 1, k + 1)], nid[(ni - 1, j, k + 1)]
                tri += [[a, b, c], [a, c, d]]
    if not omit_sternum:
        block("/SH3N", 4, tri)
    parts = [(1, "flesh_thorax", 14, 1), (2, "thoracic_vertebrae", 14, 2), (3, "skin_thorax", 1, 3)]
    if not omit_sternum:
        parts.append((4, "sternum", 2, 4))
    for pid, title, prop, mat in parts:
        lines += [f"/PART/{pid}", title, f"{prop:10d}{mat:10d}"]
    lines += ["/PROP/TYPE14/14", "solid", f"{1:10d}",
              "/PROP/TYPE1/1", "skin shell", f"{0:10d}", f"{0.01:20.3f}{0.01:20.3f}{0.01:20.3f}",
              f"{0:10d}{0:10d}{1.0:20.3f}",
              "/PROP/TYPE1/2", "sternum shell", f"{0:10d}", f"{0.01:20.3f}{0.01:20.3f}{0.01:20.3f}",
              f"{0:10d}{0:10d}{4.0:20.3f}"]
    # rho kg/mm3, E GPa: soft tissue 1 MPa, spine 100 MPa, skin 10 MPa, sternum 1 GPa.
    for mid, title, rho, e, nu in [(1, "soft tissue", 1.0e-6, 0.001, 0.45), (2, "spine", 1.5e-6, 0.1, 0.3),
                                   (3, "skin", 1.1e-6, 0.01, 0.45), (4, "sternum", 1.5e-6, 1.0, 0.3)]:
        lines += [f"/MAT/LAW1/{mid}", title, f"{rho:20.6E}", f"{e:20.6E}{nu:20.6f}"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")

if __name__ == "__main__":
    main()
