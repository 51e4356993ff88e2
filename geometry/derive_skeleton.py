#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Derives geometry/skeleton.urdf and geometry/segment_targets.csv from the reference
# numbers quoted below (each with its source). Run once by hand when a source number
# changes: python3 geometry/derive_skeleton.py; the outputs are committed and are what
# hbm-deckgen reads. Plain arithmetic only (segment axes, centre of gravity fractions,
# inertia from radii of gyration, parallel-axis sums).
import math, os

HERE = os.path.dirname(os.path.abspath(__file__))

# --- joint centres, model frame mm (VIVA+ 50M seated reference points) ---------------
# source: VIVA+ v0.2 (LGPL-3.0) 50M seated reference points (vivaplus-50M-seated-reference_points.k), PIPER names;
# hip labels in the source are swapped for the acetabula: femoral head centres used (right has y<0).
J = {
    'hip_r': (3.9, -92.8, 3.7), 'hip_l': (1.0, 87.9, 2.3),
    'knee_r': (402.2, -111.4, 88.9), 'knee_l': (402.2, 111.4, 88.9),
    'ankle_r': (682.9, -112.6, -179.1), 'ankle_l': (682.8, 110.5, -180.9),
    'sc_r': (-108.8, -20.9, 463.1), 'sc_l': (-108.8, 20.9, 463.1),
    'gh_r': (-171.6, -156.5, 435.4), 'gh_l': (-171.6, 156.5, 435.4),
    'elbow_r': (-20.9, -213.5, 206.0), 'elbow_l': (-23.9, 212.9, 208.4),
    'wrist_r': (230.1, -174.8, 275.2), 'wrist_l': (227.6, 176.0, 274.7),
}
# Acromioclavicular joint: not in the source. Estimate: 25 mm medial of the acromion tip
# (biacromial breadth 410.3/2 = 205 mm, ANSUR II midsize) and 33 mm above the GH centre.
J['ac_r'] = (-168.0, -180.0, 468.0)
J['ac_l'] = (-168.0, 180.0, 468.0)

# spine: endplate centres (spine_landmarks.csv); joint = midpoint of the disc
spine = []
with open(os.path.join(HERE, 'spine_landmarks.csv')) as f:
    rows = [l.strip() for l in f if l.strip() and not l.startswith('#')]
for r in rows[1:]:
    lv, ux, uz, lx, lz = r.split(',')
    spine.append((lv, float(ux), float(uz), float(lx), float(lz)))
sp = {s[0]: s for s in spine}
def disc(upper, lower):  # joint between vertebra `upper` (its lower plate) and `lower` (its upper plate)
    a, b = sp[upper], sp[lower]
    return ((a[3] + b[1]) / 2, 0.0, (a[4] + b[2]) / 2)

# --- masses (kg): VIVA+ 50M / Schneider 1983 (segment_masses_50M.csv) ------------------
# head 4.42 (VIVA+ 50M); upper extremities both 7.7 (VIVA+) split with Dempster 1955
# upper arm : forearm : hand = 2.65 : 1.55 : 0.6; lower extremities both 23.5 (VIVA+):
# thigh 8.0, shank 3.0 (VIVA+), foot = 23.5/2 - 8.0 - 3.0 = 0.75 (remainder).
arm = 7.7 / 2
m_upper_arm = arm * 2.65 / 4.8
m_forearm = arm * 1.55 / 4.8
m_hand = arm * 0.6 / 4.8
m_thigh, m_shank, m_foot = 8.0, 3.0, 23.5 / 2 - 8.0 - 3.0
# Zatsiorsky mean male (zatsiorsky_male_bsp.csv): CoM % of length from proximal, radii of
# gyration % of length (sagittal, transverse, longitudinal).
Z = {'upper_arm': (55.02, 32.8, 31.0, 18.2), 'forearm': (57.26, 29.5, 28.4, 13.0),
     'hand': (63.09, 28.5, 23.3, 1.2), 'thigh': (45.49, 26.7, 26.7, 12.1),
     'shank': (40.47, 28.1, 27.5, 11.4), 'foot': (55.85, 25.7, 24.5, 12.4)}

def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def add(a, b): return tuple(x + y for x, y in zip(a, b))
def mul(a, s): return tuple(x * s for x in a)
def norm(a): return math.sqrt(sum(x * x for x in a))

def segment(p, d, m, z, length=None):
    """Mass, CoG and inertia tensor (kg mm^2, model axes, about CoG) of a segment from
    proximal joint p to distal point d with Zatsiorsky fractions z."""
    ax = sub(d, p); L = length or norm(ax); a = mul(ax, 1 / norm(ax))
    cog = add(p, mul(a, L * z[0] / 100))
    it = m * (L * (z[1] + z[2]) / 200) ** 2   # transverse: mean of sagittal and transverse
    il = m * (L * z[3] / 100) ** 2
    I = [[(it if i != j else it) * ((1 if i == j else 0) - a[i] * a[j]) + il * a[i] * a[j]
          for j in range(3)] for i in range(3)]
    return m, cog, I

def combine(*segs):
    M = sum(s[0] for s in segs)
    c = mul(tuple(sum(s[0] * s[1][k] for s in segs) for k in range(3)), 1 / M)
    I = [[0.0] * 3 for _ in range(3)]
    for m, g, Is in segs:
        r = sub(g, c); rr = sum(x * x for x in r)
        for i in range(3):
            for j in range(3):
                I[i][j] += Is[i][j] + m * ((rr if i == j else 0) - r[i] * r[j])
    return M, c, I

links = {}
for s in ('r', 'l'):
    links['humerus_' + s] = segment(J['gh_' + s], J['elbow_' + s], m_upper_arm, Z['upper_arm'])
    fa = segment(J['elbow_' + s], J['wrist_' + s], m_forearm, Z['forearm'])
    # hand continues the forearm axis; hand length 192.7 mm (ANSUR II midsize)
    ax = sub(J['wrist_' + s], J['elbow_' + s]); ax = mul(ax, 1 / norm(ax))
    hd = segment(J['wrist_' + s], add(J['wrist_' + s], mul(ax, 192.7)), m_hand, Z['hand'])
    links['forearm_' + s] = combine(fa, hd)
    links['femur_' + s] = segment(J['hip_' + s], J['knee_' + s], m_thigh, Z['thigh'])
    sh = segment(J['knee_' + s], J['ankle_' + s], m_shank, Z['shank'])
    # foot: heel 50 mm behind and 60 mm below the ankle, toe along x (foot length 270.3 mm,
    # ANSUR II midsize), flat foot on the floor (estimate of the seated driver foot)
    heel = add(J['ankle_' + s], (-50.0, 0.0, -60.0))
    ft = segment(heel, add(heel, (270.3, 0.0, 0.0)), m_foot, Z['foot'])
    links['tibia_' + s] = combine(sh, ft)

# head: mass and inertia Yoganandan 2009 (head_inertia_50M.csv), CG relative to tragion
# (1.3, 26.4) mm; tragion estimated 10 mm anterior and 25 mm superior of the occipital
# condyles (C0-C1 joint); principal axes taken along the model axes (Frankfort plane horizontal).
oc = (sp['C1'][1], 0.0, sp['C1'][2])
head_cg = add(oc, (10.0 + 1.3, 0.0, 25.0 + 26.4))
links['head'] = (4.42, head_cg, [[21491, 0, 0], [0, 23323, 0], [0, 0, 15489]])

# --- joints ------------------------------------------------------------------------------
# (name, parent, child, origin (model frame), axis, lower, upper) limits in rad relative
# to the seated posture, from the normal range of motion (AAOS 1965 tables as quoted in
# Norkin & White, Measurement of Joint Motion) minus the seated angle.
joints = []
chain = ['S1', 'L5', 'L4', 'L3', 'L2', 'L1', 'T12', 'T11', 'T10', 'T9', 'T8', 'T7', 'T6',
         'T5', 'T4', 'T3', 'T2', 'T1', 'C7', 'C6', 'C5', 'C4', 'C3', 'C2', 'C1']
link_of = {'S1': 'pelvis'}
for lv in chain[1:]:
    link_of[lv] = lv
for lower, upper in zip(chain, chain[1:]):
    joints.append((f'{upper}_{lower}', link_of[lower], upper, disc(upper, lower), (0, 1, 0), -0.15, 0.15))
joints.append(('C0_C1', 'C1', 'head', oc, (0, 1, 0), -0.4, 0.4))
for s, sg in (('r', -1), ('l', 1)):
    joints.append((f'sternoclavicular_{s}', 'T1', f'clavicle_{s}', J['sc_' + s], (1, 0, 0), -0.3, 0.3))
    joints.append((f'acromioclavicular_{s}', f'clavicle_{s}', f'scapula_{s}', J['ac_' + s], (1, 0, 0), -0.2, 0.2))
    joints.append((f'shoulder_{s}', f'scapula_{s}', f'humerus_{s}', J['gh_' + s], (0, 1, 0), -2.0, 1.0))
    joints.append((f'elbow_{s}', f'humerus_{s}', f'forearm_{s}', J['elbow_' + s], (0, 1, 0), -1.2, 1.0))
    joints.append((f'hip_{s}', 'pelvis', f'femur_{s}', J['hip_' + s], (0, 1, 0), -0.6, 0.6))
    joints.append((f'knee_{s}', f'femur_{s}', f'tibia_{s}', J['knee_' + s], (0, 1, 0), -0.8, 1.0))

origin_of = {'pelvis': (0.0, 0.0, 0.0)}
for name, parent, child, o, *_ in joints:
    origin_of[child] = o

def f(x): return f'{x:.4f}'.rstrip('0').rstrip('.') if abs(x) > 1e-12 else '0'

out = ['<?xml version="1.0"?>',
       '<!-- 50th percentile male driver skeleton, seated posture (VIVA+ 50M seated). Units: lengths in',
       '     METRES as URDF requires (hbm-deckgen converts to mm), mass kg, inertia kg*m^2.',
       '     Generated by geometry/derive_skeleton.py from: VIVA+ v0.2 50M seated reference points',
       '     (joint centres, vertebral endplates: spine_landmarks.csv), VIVA+/Schneider 1983 and',
       '     Dempster 1955 segment masses, Zatsiorsky mean-male CoM and radii of gyration,',
       '     Yoganandan 2009 head mass and inertia; estimates marked in derive_skeleton.py.',
       '     Link frames are parallel to the model frame in the seated posture; a link frame sits',
       '     at the joint to its parent. Inertial blocks only for the rigid segments. -->',
       '<robot name="hbm50_seated_driver">']
names = ['pelvis'] + [j[2] for j in joints]
for n in names:
    if n in links:
        m, c, I = links[n]
        o = origin_of[n]
        r = [(c[k] - o[k]) / 1000 for k in range(3)]
        out.append(f'  <link name="{n}">')
        out.append(f'    <inertial>')
        out.append(f'      <origin xyz="{f(r[0])} {f(r[1])} {f(r[2])}" rpy="0 0 0"/>')
        out.append(f'      <mass value="{m:.4f}"/>')
        s = 1e-6
        out.append(f'      <inertia ixx="{I[0][0]*s:.6e}" ixy="{I[0][1]*s:.6e}" ixz="{I[0][2]*s:.6e}" '
                   f'iyy="{I[1][1]*s:.6e}" iyz="{I[1][2]*s:.6e}" izz="{I[2][2]*s:.6e}"/>')
        out.append(f'    </inertial>')
        out.append(f'  </link>')
    else:
        out.append(f'  <link name="{n}"/>')
for name, parent, child, o, axis, lo, hi in joints:
    po = origin_of[parent]
    r = [(o[k] - po[k]) / 1000 for k in range(3)]
    out.append(f'  <joint name="{name}" type="revolute">')
    out.append(f'    <parent link="{parent}"/>')
    out.append(f'    <child link="{child}"/>')
    out.append(f'    <origin xyz="{f(r[0])} {f(r[1])} {f(r[2])}" rpy="0 0 0"/>')
    out.append(f'    <axis xyz="{axis[0]} {axis[1]} {axis[2]}"/>')
    out.append(f'    <limit lower="{lo}" upper="{hi}" effort="0" velocity="0"/>')
    out.append(f'  </joint>')
out.append('</robot>')
with open(os.path.join(HERE, 'skeleton.urdf'), 'w') as fo:
    fo.write('\n'.join(out) + '\n')
print('wrote skeleton.urdf')
