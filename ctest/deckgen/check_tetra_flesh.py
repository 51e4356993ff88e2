#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Regression test of the tetra-flesh variant (deckgen/scripts/tetra_flesh.py,
docs/engine-design.md §12.9): the thoracic flesh of the committed model cut into average
nodal pressure tetras, under the first 3 ms of the 6.7 m/s frontal hub impact.

  - the tool cuts every flesh_thorax brick into six tetras (count);
  - the tetras hold the bricks' mass (the six tetras of a brick with plane faces fill it
    exactly; the torso's warped faces leave less than 0.5 %);
  - the run terminates normally with energy error below 0.1 %, the tetras store internal
    energy (they carry the load) and no hourglass energy (a tetra has no hourglass mode);
  - a malformed brick line is an error naming the file and line, exit 1, no output written.

  check_tetra_flesh.py SOLVER_EXE TOOL MODEL_INC CASE_DIR WORK_DIR
"""
import csv
import glob
import os
import re
import shutil
import subprocess
import sys


def part_mass(listing, title):
    m = re.search(r"part\s+\d+\s+mass\s+([0-9.eE+-]+).*\s" + re.escape(title) + r"\s*$", listing, re.M)
    return float(m.group(1)) if m else None


def run(exe, deck, out, tstop):
    shutil.rmtree(out, ignore_errors=True)
    engine = deck.replace("_0000.rad", "_0001.rad")
    text = open(engine).read()
    text = re.sub(r"(/RUN/[^\n]*\n)[^\n]*\n", lambda m: m.group(1) + f"{tstop}\n", text, count=1)
    open(engine, "w").write(text)
    r = subprocess.run([exe, deck, "--out", out], capture_output=True, text=True)
    listing = glob.glob(os.path.join(out, "*_0001.out"))
    return r, open(listing[0], errors="replace").read() if listing else ""


def main():
    exe, tool, model, case_dir, work = sys.argv[1:6]
    shutil.rmtree(work, ignore_errors=True)
    errors = []
    for variant in ("bricks", "tetras"):
        os.makedirs(os.path.join(work, variant, "hbm50"))
        case = os.path.join(work, variant, "case")
        shutil.copytree(case_dir, case)
        inc = os.path.join(work, variant, "hbm50", "hbm50.inc")  # what '#include ../hbm50/hbm50.inc' finds
        if variant == "bricks":
            shutil.copy(model, inc)
        else:
            r = subprocess.run([sys.executable, tool, model, inc], capture_output=True, text=True)
            print(r.stdout + r.stderr)
            m = re.search(r"(\d+) bricks of flesh_thorax -> (\d+) tetras", r.stdout)
            if r.returncode != 0 or not m or int(m.group(2)) != 6 * int(m.group(1)) or int(m.group(1)) == 0:
                print("tetra_flesh.py did not cut the thoracic flesh")
                return 1
    # Bad input: the first flesh_thorax brick line cut short.
    lines = open(model).read().split("\n")
    k = lines.index("/BRICK/1") + 1
    lines[k] = lines[k][:35]
    bad = os.path.join(work, "bad.inc")
    open(bad, "w").write("\n".join(lines))
    bad_out = os.path.join(work, "bad_out.inc")
    r = subprocess.run([sys.executable, tool, bad, bad_out], capture_output=True, text=True)
    print(r.stderr.strip())
    if r.returncode != 1 or f"bad.inc:{k + 1}:" not in r.stderr or os.path.exists(bad_out):
        errors.append(f"a short brick line is not an error naming bad.inc:{k + 1} with exit 1 and no output")
    deck = glob.glob(os.path.join(work, "bricks", "case", "*_0000.rad"))[0]
    _, brick_listing = run(exe, deck, os.path.join(work, "bricks", "out"), 0.003)
    deck = glob.glob(os.path.join(work, "tetras", "case", "*_0000.rad"))[0]
    out = os.path.join(work, "tetras", "out")
    r, listing = run(exe, deck, out, 3.0)
    if r.returncode != 0 or "NORMAL TERMINATION" not in listing:
        print(f"tetra variant run did not terminate normally (exit {r.returncode})\n{r.stderr[-2000:]}\n{listing[-2000:]}")
        return 1
    m_b, m_t = part_mass(brick_listing, "flesh_thorax"), part_mass(listing, "flesh_thorax")
    print(f"flesh_thorax mass: bricks {m_b} kg, tetras {m_t} kg")
    if m_b is None or m_t is None or abs(m_t / m_b - 1) > 0.005:
        errors.append("the tetras do not hold the bricks' mass within 0.5 %")
    th = glob.glob(os.path.join(out, "*_TH_PART_*.csv"))
    rows = list(csv.reader(open(th[0])))
    h = rows[0]
    ie, he, err = h.index("part 1 flesh_thorax IE [J]"), h.index("part 1 flesh_thorax HE [J]"), h.index("energy error [-]")
    data = [[float(v) for v in x] for x in rows[1:]]
    max_err = max(abs(x[err]) for x in data)
    print(f"3 ms: flesh_thorax IE {data[-1][ie]:.3f} J, HE max {max(abs(x[he]) for x in data):.3g} J, "
          f"energy error max {100 * max_err:.4f} %")
    if max_err > 1e-3:
        errors.append("energy error above 0.1 %")
    if not data[-1][ie] > 0.1:
        errors.append("the tetras carry no load (internal energy below 0.1 J)")
    if any(x[he] != 0.0 for x in data):
        errors.append("hourglass energy in the tetras")
    for e in errors:
        print("FAIL:", e)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
