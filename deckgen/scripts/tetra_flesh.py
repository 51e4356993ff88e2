#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Soft-tissue variant of a generated model: the bricks of the named parts become average
nodal pressure tetras (/TETRA4, /PROP/TYPE14 Itetra4 3; docs/engine-design.md §12.9).

  tetra_flesh.py MODEL.inc OUT.inc [--parts flesh_thorax,...]

Each brick is cut into the six tetras around its diagonal n1-n7 (Radioss /BRICK order):
every face is cut along its diagonal through n1 or n7, so neighbouring bricks of the
torso's structured grid, all oriented alike, share their cuts (checked: the tool stops if
two bricks of the named parts would cut a shared face differently). Faces shared with
bricks of other parts stay quads on the brick side (no pyramid transition). /SURF/SEG quads
lying on a cut face are replaced by the two triangles of the cut, so tied and contact
surfaces still lie on element faces. The parts get a new /PROP/TYPE14 (the old property's
qa, qb kept). Element count: five more per brick; the model's 10 000-12 000 element budget
(issue #6) does not hold for the variant.

Exit 1 with a message naming file and line on input it cannot read; nothing is written
then (the output appears complete or not at all).
"""
import argparse
import os
import sys
import tempfile

# Radioss /BRICK order: n1-n4 one face, n5-n8 the opposite one (n1 under n5). Indices 0-7.
KUHN = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]
FACES = [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]


class DeckError(Exception):
    pass


def fields(line, path, lineno, n, kind=int):
    try:
        v = [kind(x) for x in line.split()[:n]]
    except ValueError as e:
        raise DeckError(f"{path}:{lineno}: cannot read '{line.strip()}': {e}")
    if len(v) < n:
        raise DeckError(f"{path}:{lineno}: expected {n} fields, got '{line.strip()}'")
    return v


def cards(lines):
    """(keyword line index, keyword, [data line indices]) for every card; comments skipped."""
    out = []
    for i, ln in enumerate(lines):
        if ln.startswith('/'):
            out.append((i, ln.strip(), []))
        elif out and not ln.startswith('#'):
            out[-1][2].append(i)
    return out


def signed_volume(x, n):
    a = [x[n[1]][k] - x[n[0]][k] for k in range(3)]
    c = [x[n[2]][k] - x[n[0]][k] for k in range(3)]
    d = [x[n[3]][k] - x[n[0]][k] for k in range(3)]
    return a[0] * (c[1] * d[2] - c[2] * d[1]) + a[1] * (c[2] * d[0] - c[0] * d[2]) + a[2] * (c[0] * d[1] - c[1] * d[0])


def convert(path, part_names):
    lines = open(path).read().split('\n')
    cs = cards(lines)
    # Parts by title, properties in use, nodes, largest solid element id.
    part_id, part_prop_line, props = {}, {}, set()
    x = {}
    max_eid = 0
    for i, kw, data in cs:
        key = kw.split('/')
        if kw.startswith('/PART/'):
            if len(data) < 2:
                raise DeckError(f"{path}:{i + 1}: {kw}: title and property/material line expected")
            part_id[lines[data[0]].strip()] = int(key[2])
            part_prop_line[int(key[2])] = data[1]
        elif kw.startswith('/PROP/'):
            props.add(int(key[3]))
        elif kw.startswith('/NODE'):
            for d in data:
                if lines[d].strip():
                    f = lines[d].split()
                    nid = fields(lines[d], path, d + 1, 1)[0]
                    x[nid] = fields(' '.join(f[1:4]), path, d + 1, 3, float)
        elif kw.startswith(('/BRICK/', '/TETRA4/')):
            for d in data:
                if lines[d].strip():
                    max_eid = max(max_eid, fields(lines[d], path, d + 1, 1)[0])
    missing = [p for p in part_names if p not in part_id]
    if missing:
        raise DeckError(f"{path}: no /PART titled {', '.join(missing)}")
    if not part_names:
        raise DeckError("no part named to cut (--parts)")
    targets = {part_id[p] for p in part_names}
    target_prop_lines = {part_prop_line[p] for p in targets}  # their /PART property lines
    prop_id = max(props | {0}) + 1

    # Cut the bricks; face cut per face (node set -> diagonal), checked for agreement.
    tets, cut_of_face = {}, {}
    drop = set()
    for i, kw, data in cs:
        if not kw.startswith('/BRICK/') or int(kw.split('/')[2]) not in targets:
            continue
        pid = int(kw.split('/')[2])
        drop.add(i)
        drop.update(data)
        for d in data:
            if not lines[d].strip():
                continue
            n = fields(lines[d], path, d + 1, 9)[1:]
            for nid in n:
                if nid not in x:
                    raise DeckError(f"{path}:{d + 1}: {kw}: node {nid} is not defined")
            for fc in FACES:
                q = [n[k] for k in fc]
                diag = next(frozenset((q[a], q[(a + 2) % 4])) for a in range(4) if fc[a] in (0, 6))
                key = frozenset(q)
                if cut_of_face.setdefault(key, diag) != diag:
                    raise DeckError(f"{path}:{d + 1}: {kw}: brick {n} cuts a face it shares with another brick "
                                    "along the other diagonal (bricks not oriented alike)")
            for t in KUHN:
                tn = [n[k] for k in t]
                if signed_volume(x, tn) < 0:
                    tn[2], tn[3] = tn[3], tn[2]
                if signed_volume(x, tn) <= 0:
                    raise DeckError(f"{path}:{d + 1}: {kw}: brick {n} gives a tetra of zero volume")
                tets.setdefault(pid, []).append(tn)

    out, n_split = [], 0
    seg_card = False
    first_brick = min((i for i, kw, _ in cs if kw.startswith('/BRICK/')), default=None)
    new_prop_at = min((i for i, kw, _ in cs if kw.startswith('/PROP/')), default=first_brick)
    eid = max_eid
    for k, ln in enumerate(lines):
        if k == new_prop_at:
            out += [f'/PROP/TYPE14/{prop_id}', 'soft tissue tetras: average nodal pressure (Itetra4 3)',
                    '%10d%10d%10d%10d%10d%10d%10d' % (0, 0, 0, 0, 0, 0, 3),
                    '%20s%20s' % ('1.1', '0.05')]
        if k == first_brick:
            for pid in sorted(tets):
                out.append(f'/TETRA4/{pid}')
                for tn in tets[pid]:
                    eid += 1
                    out.append('%10d%10d%10d%10d%10d' % (eid, *tn))
        if k in drop:
            continue
        if ln.startswith('/'):
            seg_card = ln.startswith('/SURF/SEG/')
        elif seg_card and ln.strip() and not ln.startswith('#') and ln[:10].strip() == '':
            q = fields(ln, path, k + 1, min(4, len(ln.split())))  # a triangle leaves n4 blank
            key = frozenset(q)
            if len(q) == 4 and len(key) == 4 and key in cut_of_face:
                dg = cut_of_face[key]
                a0 = next(a for a in range(4) if q[a] in dg and q[(a + 2) % 4] in dg)
                a, b, c, d = (q[(a0 + j) % 4] for j in range(4))
                out.append('%10s%10d%10d%10d%10d' % ('', a, b, c, c))
                out.append('%10s%10d%10d%10d%10d' % ('', a, c, d, d))
                n_split += 1
                continue
        if k in target_prop_lines:
            ln = '%10d%s' % (prop_id, ln[10:])
        out.append(ln)
    n_bricks = sum(len(v) for v in tets.values()) // 6
    return '\n'.join(out), n_bricks, n_split, prop_id


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('model')
    ap.add_argument('out')
    ap.add_argument('--parts', default='flesh_thorax', help='comma-separated part titles (default flesh_thorax)')
    a = ap.parse_args()
    try:
        text, n_bricks, n_split, prop_id = convert(a.model, [p for p in a.parts.split(',') if p])
    except (DeckError, OSError) as e:
        print(f"tetra_flesh.py: {e}", file=sys.stderr)
        return 1
    d = os.path.dirname(os.path.abspath(a.out))
    fd, tmp = tempfile.mkstemp(dir=d, prefix='.tetra_flesh.')
    with os.fdopen(fd, 'w') as f:
        f.write(text)
    os.chmod(tmp, 0o644)
    os.replace(tmp, a.out)
    print(f"{a.out}: {n_bricks} bricks of {a.parts} -> {6 * n_bricks} tetras (/PROP/TYPE14/{prop_id}, Itetra4 3), "
          f"{n_split} /SURF/SEG quads cut in two")
    return 0


if __name__ == '__main__':
    sys.exit(main())
