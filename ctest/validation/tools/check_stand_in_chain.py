#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Regression test of the load-case chain on a stand-in body (write_test_body.py):
hbm-loadcase writes the 6.7 m/s frontal hub deck, hbm-solver runs it for 2 ms.
Asserts what physics fixes:
  - kinetic energy at t = 0 equals 1/2 m v^2 of the 23.4 kg impactor at 6.7 m/s
    (525.213 J; the body is at rest) within 0.1 %: the rigid body carries exactly 23.4 kg;
  - rigid-body force / main-node acceleration = 23.4 kg (0.1 %) whenever the force is
    above 1 kN: the 'impactor AX' channel the corridor case scales by 23.4 kg
    is the rigid body's acceleration;
  - the contact force (sqrt(FN^2 + FT^2)) equals the rigid body's resultant force within
    2 % whenever it is above 1 kN (the stand-in's plateau is 3-5 kN after a first-contact
    spike of some 50 kN): the impactor is loaded by the skin contact only;
  - first contact (FN > 0) between 0.25 and 0.40 ms: the face is placed 3 mm from the
    skin with a 1 mm contact gap, (3 - 1) mm / 6.7 mm/ms = 0.299 ms, +- 0.1 ms for the
    penalty onset and the 0.01 ms output interval;
  - normal termination, energy error below 2 %;
and on bad input (a body without a 'sternum' part): exit 1, a message naming the missing
part and listing the model's parts, and no output folder; on an unknown option: exit 2
(usage) naming it.

  check_stand_in_chain.py LOADCASE_EXE SOLVER_EXE SOURCE_DIR WORK_DIR
"""
import csv
import math
import os
import shutil
import subprocess
import sys


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def table(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def col(head, text):
    hits = [i for i, h in enumerate(head) if text in h]
    if len(hits) != 1:
        fail(f"column '{text}': {len(hits)} matches in {head}")
    return hits[0]


def main():
    loadcase, solver, src, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    body = os.path.join(work, "body.inc")
    subprocess.run([sys.executable, os.path.join(src, "ctest/validation/tools/write_test_body.py"), body], check=True)
    geometry = os.path.join(src, "geometry")
    deck_dir = os.path.join(work, "hub_frontal_6p7")
    r = subprocess.run([loadcase, "--model", body, "--geometry", geometry, "--case", "hub_frontal_6p7",
                        "--out", deck_dir, "--tstop", "2"], capture_output=True, text=True)
    print(r.stdout, r.stderr)
    if r.returncode != 0:
        fail(f"hbm-loadcase exit {r.returncode}")
    run = os.path.join(work, "run")
    r = subprocess.run([solver, os.path.join(deck_dir, "hub_frontal_6p7_0000.rad"), "--out", run],
                       capture_output=True, text=True)
    print(r.stdout[-3000:], r.stderr[-2000:])
    if r.returncode != 0 or "NORMAL TERMINATION" not in r.stdout:
        fail(f"hbm-solver exit {r.returncode}")

    hn, dn = table(os.path.join(run, "hub_frontal_6p7_TH_NODE_1001.csv"))
    hr, dr = table(os.path.join(run, "hub_frontal_6p7_TH_RBODY_1002.csv"))
    hi, di = table(os.path.join(run, "hub_frontal_6p7_TH_INTER_1003.csv"))
    m, v = 23.4, 6.7
    ke0 = dn[0][col(hn, "kinetic energy")]
    if abs(ke0 / (0.5 * m * v * v) - 1) > 1e-3:
        fail(f"kinetic energy at t=0 {ke0} J, expected {0.5 * m * v * v} J")
    print(f"ok: kinetic energy at t=0 {ke0:.3f} J = 1/2 m v^2 {0.5 * m * v * v:.3f} J")
    err = max(abs(row[col(hn, "energy error")]) for row in dn)
    if err > 0.02:
        fail(f"energy error {err}")
    ax, fx = col(hn, "impactor AX"), col(hr, "impactor rigid body FX")
    fy, fz = col(hr, "impactor rigid body FY"), col(hr, "impactor rigid body FZ")
    fn, ft = col(hi, "impactor contact FN"), col(hi, "impactor contact FT")
    if len(dn) != len(dr) or len(dn) != len(di):
        fail("time-history files have different row counts")
    fpk = max(abs(row[fx]) for row in dr)
    if fpk <= 0:
        fail("no impactor force")
    n_mass = n_contact = 0
    for a_row, r_row, i_row in zip(dn, dr, di):
        f = r_row[fx]
        if abs(f) > 1.0:
            n_mass += 1
            if abs(f / a_row[ax] / m - 1) > 1e-3:
                fail(f"t={a_row[0]}: rigid-body FX / impactor AX = {f / a_row[ax]} kg, expected {m}")
        fres = math.sqrt(r_row[fx] ** 2 + r_row[fy] ** 2 + r_row[fz] ** 2)
        if fres > 1.0:
            n_contact += 1
            fc = math.hypot(i_row[fn], i_row[ft])
            if abs(fc / fres - 1) > 0.02:
                fail(f"t={a_row[0]}: contact force {fc} kN vs rigid-body force {fres} kN")
    if n_mass < 20 or n_contact < 20:
        fail(f"too few loaded samples ({n_mass}, {n_contact})")
    print(f"ok: impactor mass from force/acceleration and contact = rigid-body force on {n_mass} / {n_contact} samples")
    t_first = next((row[0] for row in di if row[fn] > 0), None)
    if t_first is None or not (0.25 <= t_first <= 0.40):
        fail(f"first contact at {t_first} ms, expected 0.299 ms +- 0.1")
    print(f"ok: first contact at {t_first} ms")

    # Bad input: no sternum part.
    bad = os.path.join(work, "body_no_sternum.inc")
    subprocess.run([sys.executable, os.path.join(src, "ctest/validation/tools/write_test_body.py"), bad,
                    "--omit-sternum"], check=True)
    out_bad = os.path.join(work, "bad_case")
    r = subprocess.run([loadcase, "--model", bad, "--geometry", geometry, "--case", "hub_frontal_6p7",
                        "--out", out_bad], capture_output=True, text=True)
    if r.returncode != 1 or "sternum" not in r.stderr or "skin_thorax" not in r.stderr:
        fail(f"bad input: exit {r.returncode}, stderr {r.stderr!r}")
    if os.path.exists(out_bad) or any(n.startswith(".bad_case") for n in os.listdir(work)):
        fail("bad input left an output folder")
    print("ok: missing sternum part -> exit 1, parts listed, nothing written")

    # A bad command line is a usage error (exit 2, like a missing --case), naming the option.
    r = subprocess.run([loadcase, "--model", bad, "--case", "hub_frontal_6p7", "--out", out_bad, "--no-such-option"],
                       capture_output=True, text=True)
    if r.returncode != 2 or "--no-such-option" not in r.stderr:
        fail(f"bad command line: exit {r.returncode}, stderr {r.stderr!r}")
    if os.path.exists(out_bad):
        fail("bad command line left an output folder")
    print("ok: unknown option -> exit 2, option named, nothing written")


if __name__ == "__main__":
    main()
