#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Regression test of issue 6: the generated drop deck (the body model dropped at 5 m/s
onto a rigid floor for 20 ms) must terminate normally with energy error < 2 %, added mass
< 1 % and hourglass energy < 10 % of internal energy (at the end and at every output time
where the internal energy exceeds 10 % of its peak, as docs/validation.md takes it).

  check_drop_run.py SOLVER_EXE DROP_STARTER_DECK WORK_DIR
"""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "validation", "tools"))
from validation_report import global_history, part_hourglass_end, run_health  # noqa: E402

LIMITS = {"energy error": 2.0, "added mass": 1.0, "hourglass / internal": 10.0}  # per cent


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
    if bad:
        print("over the limit: " + ", ".join(bad))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
