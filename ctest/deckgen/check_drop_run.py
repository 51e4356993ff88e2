#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Regression test of issue 6: the generated drop deck (the body model dropped at 5 m/s
onto a rigid floor for 20 ms) must terminate normally with energy error < 2 %, added mass
< 1 % and hourglass energy < 10 % of internal energy (at the end and at every output time
where the internal energy exceeds 10 % of its peak, as docs/validation.md takes it), and no
element may switch to small strain before the feet reach the floor (the body falls rigidly).

  check_drop_run.py SOLVER_EXE DROP_STARTER_DECK WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "validation", "tools"))
from validation_report import global_history, part_hourglass_end, run_health, small_strain_switches  # noqa: E402

LIMITS = {"energy error": 2.0, "added mass": 1.0, "hourglass / internal": 10.0}  # per cent


def first_contact_time(starter):
    """Time at which the falling model reaches the floor: clearance / speed from the deck's header line."""
    m = re.search(r"dropped at ([0-9.]+) m/s onto a rigid floor ([0-9.]+) mm below", open(starter).read())
    return float(m.group(2)) / float(m.group(1)) if m else None


def main():
    exe, deck, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    r = subprocess.run([exe, deck, "--out", work], capture_output=True, text=True)
    listing = [f for f in os.listdir(work) if f.endswith("_0001.out")] if os.path.isdir(work) else []
    text = open(os.path.join(work, listing[0]), errors="replace").read() if listing else ""
    if r.returncode != 0 or "NORMAL TERMINATION" not in text:
        print(f"drop run did not terminate normally (exit {r.returncode})\n{r.stderr[-2000:]}\n{text[-2000:]}")
        return 1
    h = global_history(work)
    if h is None or not h["time"]:
        print(f"{work}: no time history")
        return 1
    ie, he = h["internal energy"], h["hourglass energy"]
    health = run_health(h)
    if health["hg_end"] is None:
        print(f"{work}: no internal energy at the end of the drop (nothing deformed?)")
        return 1
    got = {"energy error": health["energy_err"], "added mass": health["added"],
           "hourglass / internal": max(health["hg_end"], health["hg_max"] or 0.0)}
    print(f"drop deck, {h['time'][-1]:.2f} ms: internal {ie[-1]:.2f} J, hourglass {he[-1]:.2f} J; "
          + ", ".join(f"{k} {v:.3f} % (limit {LIMITS[k]} %)" for k, v in got.items()))
    print("parts with most hourglass energy (HE / IE, J): "
          + ", ".join(f"{n} {a:.2f} / {b:.2f}" for n, a, b in part_hourglass_end(work)))
    bad = [k for k, v in got.items() if not v < LIMITS[k]]
    # Small strain switch (/DT/BRICK/CST, /DT/SHELL/CST): an element freezes its geometry when
    # deformation has brought its step to Tmin; before the feet reach the floor the body moves
    # rigidly, so no element may switch then.
    t_contact = first_contact_time(deck)
    switches = small_strain_switches(text)
    if switches:
        print("switched to small strain: " + ", ".join(
            f"{p} {n} (first at {t} ms)" for _, p, n, _, t, _ in switches))
    if t_contact is None:
        print(f"{deck}: no 'dropped at ... m/s onto a rigid floor ... mm below' header line")
        return 1
    early = [(p, t) for _, p, _, _, t, _ in switches if t is None or t < t_contact]
    if early:
        print(f"elements switched before the first floor contact ({t_contact:.3f} ms): "
              + ", ".join(f"{p} at {t} ms" for p, t in early))
        bad.append("switch before contact")
    if bad:
        print("over the limit: " + ", ".join(bad))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
