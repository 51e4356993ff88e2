# SPDX-License-Identifier: GPL-3.0-or-later
"""Superseded by decks/examples/deck_tools/radioss_deck.py, the one writer of the example
decks; kept only while decks/examples/contact_sphere_rwall/make_deck.py imports it (delete
this folder once that generator uses deck_tools: the same cards, /PART without the blank
thickness field).
Minimal writer of Radioss block-format decks (fixed columns, as in docs/deck-format.md).
Integers in 10 columns, reals in 20 columns, right-aligned. Files are written to a
temporary name and renamed when complete."""

import os


def i10(v):
    return f"{int(v):>10d}"


def f20(v):
    return f"{float(v):>20.12E}"


def blank(n):
    return " " * n


class Starter:
    def __init__(self, name, header_lines):
        self.name = name
        self.out = ["#RADIOSS STARTER"] + ["# " + h if h else "#" for h in header_lines]
        self.out += ["/BEGIN", name, i10(2024) + i10(0),
                     f"{'kg':>20}{'mm':>20}{'ms':>20}", f"{'kg':>20}{'mm':>20}{'ms':>20}"]

    def card(self, keyword, title=None, lines=()):
        self.out.append(keyword)
        if title is not None:
            self.out.append(title)
        self.out.extend(lines)

    def nodes(self, items):  # items: (id, x, y, z)
        self.card("/NODE", None, [i10(n) + f20(x) + f20(y) + f20(z) for n, x, y, z in items])

    def bricks(self, part, items):  # items: (id, [8 nodes])
        self.card(f"/BRICK/{part}", None, [i10(e) + "".join(i10(n) for n in ns) for e, ns in items])

    def shells(self, part, items, thick=0.0):  # items: (id, [4 nodes])
        self.card(f"/SHELL/{part}", None,
                  [i10(e) + "".join(i10(n) for n in ns) + blank(10) + f20(0) + f20(thick) for e, ns in items])

    def part(self, pid, title, prop, mat, thick=0.0):
        self.card(f"/PART/{pid}", title, [i10(prop) + i10(mat) + i10(0) + f20(thick)])

    def prop_solid(self, pid, title, isolid=0, h=0.1, qa=1.1, qb=0.05):
        self.card(f"/PROP/TYPE14/{pid}", title, [i10(isolid), f20(qa) + f20(qb) + f20(h)])

    def prop_shell(self, pid, title, thick, n=5):
        self.card(f"/PROP/TYPE1/{pid}", title, [i10(4), f20(0.01) + f20(0.01) + f20(0.01),
                                                i10(n) + i10(0) + f20(thick)])

    def law1(self, mid, title, rho, e, nu):
        self.card(f"/MAT/LAW1/{mid}", title, [f20(rho), f20(e) + f20(nu)])

    def grnod_node(self, gid, title, ids):
        ids = list(ids)
        self.card(f"/GRNOD/NODE/{gid}", title,
                  ["".join(i10(n) for n in ids[k:k + 10]) for k in range(0, len(ids), 10)])

    def grnod_part(self, gid, title, parts):
        self.card(f"/GRNOD/PART/{gid}", title, ["".join(i10(p) for p in parts)])

    def surf_part(self, sid, title, parts):
        self.card(f"/SURF/PART/{sid}", title, ["".join(i10(p) for p in parts)])

    def inter7(self, iid, title, grnod, surf, stfac=1.0, fric=0.0, gapmin=0.0, vis_s=0.0,
               istf=0, igap=0, tstart=0.0, tstop=0.0):
        self.card(f"/INTER/TYPE7/{iid}", title, [
            i10(grnod) + i10(surf) + i10(istf) + i10(0) + i10(igap),
            f20(0) + f20(0) + f20(0),
            f20(0) + f20(0),
            f20(stfac) + f20(fric) + f20(gapmin) + f20(tstart) + f20(tstop),
            blank(30) + i10(0) + f20(vis_s) + f20(1.0),
            i10(0),
        ])

    def inter2(self, iid, title, grnod, surf, dsearch=0.0):
        self.card(f"/INTER/TYPE2/{iid}", title, [i10(grnod) + i10(surf) + blank(60) + f20(dsearch)])

    def rwall_plane(self, wid, title, point, normal_point, slide=0, fric=0.0, grnod1=0, dsearch=0.0,
                    node=0, mass=0.0, v0=(0.0, 0.0, 0.0)):
        # Fixed wall (node = 0): line 3 is the point M. Moving wall: line 3 is Mass VX0 VY0 VZ0
        # and the wall passes through the node (point is then unused).
        line3 = "".join(f20(c) for c in point) if node == 0 else f20(mass) + "".join(f20(c) for c in v0)
        self.card(f"/RWALL/PLANE/{wid}", title, [
            i10(node) + i10(slide) + i10(grnod1) + i10(0),
            f20(dsearch) + f20(fric),
            line3,
            "".join(f20(c) for c in normal_point),
        ])

    def inivel(self, vid, title, v, grnod):
        self.card(f"/INIVEL/TRA/{vid}", title, ["".join(f20(c) for c in v) + i10(grnod)])

    def funct(self, fid, title, pts):
        self.card(f"/FUNCT/{fid}", title, [f20(x) + f20(y) for x, y in pts])

    def grav(self, gid, title, fct, direction, grnod, scale):
        self.card(f"/GRAV/{gid}", title, [i10(fct) + f"{direction:>10}" + i10(0) + i10(0) + i10(grnod),
                                          f20(1.0) + f20(scale)])

    def impvel(self, iid, title, fct, direction, grnod, scale, tstart=0.0, tstop=0.0):
        self.card(f"/IMPVEL/{iid}", title, [i10(fct) + f"{direction:>10}" + i10(0) + i10(0) + i10(grnod),
                                            f20(1.0) + f20(scale) + f20(tstart) + f20(tstop)])

    def bcs(self, bid, title, tra, grnod):
        self.card(f"/BCS/{bid}", title, [f"   {tra:3s} 000" + i10(0) + i10(grnod)])

    def th(self, kind, tid, title, variables, ids):
        vs = list(variables)
        lines = ["".join(f"{v:>10}" for v in vs[k:k + 10]) for k in range(0, len(vs), 10)]
        ids = list(ids)
        lines += ["".join(i10(n) for n in ids[k:k + 10]) for k in range(0, len(ids), 10)]
        self.card(f"/TH/{kind}/{tid}", title, lines)

    def th_nodes(self, tid, title, variables, nodes):  # nodes: (id, name)
        vs = list(variables)
        lines = ["".join(f"{v:>10}" for v in vs[k:k + 10]) for k in range(0, len(vs), 10)]
        lines += [i10(n) + i10(0) + f"{name:<80}" for n, name in nodes]
        self.card(f"/TH/NODE/{tid}", title, lines)

    def write(self, path):
        write_atomic(path, "\n".join(self.out + ["/END"]) + "\n")


def engine(name, header_lines, tstop, dt_his, anim_dt=0.0, print_every=100, nodal_dt=None):
    out = ["#RADIOSS ENGINE"] + ["# " + h if h else "#" for h in header_lines]
    out += [f"/RUN/{name}/1", f"{tstop:.6g}", "/TFILE/4", f"{dt_his:.6g}", f"/PRINT/-{print_every}"]
    if anim_dt > 0:
        out += ["/ANIM/DT", f"0 {anim_dt:.6g}", "/ANIM/VECT/VEL", "/ANIM/VECT/CONT"]
    if nodal_dt:
        out += ["/DT/NODA/CST", f"{nodal_dt[0]:.6g} {nodal_dt[1]:.6g}"]
    return "\n".join(out) + "\n"


def write_atomic(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def block_mesh(nx, ny, nz, h, origin, first_node, first_elem):
    """Regular brick block; returns (nodes [(id,x,y,z)], bricks [(id,[8])], node_id(i,j,k))."""
    ox, oy, oz = origin
    hx, hy, hz = (h, h, h) if not isinstance(h, tuple) else h
    nid = lambda i, j, k: first_node + i + (nx + 1) * (j + (ny + 1) * k)
    nodes = [(nid(i, j, k), ox + i * hx, oy + j * hy, oz + k * hz)
             for k in range(nz + 1) for j in range(ny + 1) for i in range(nx + 1)]
    bricks = []
    e = first_elem
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                bricks.append((e, [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                                   nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                                   nid(i, j + 1, k + 1)]))
                e += 1
    return nodes, bricks, nid
