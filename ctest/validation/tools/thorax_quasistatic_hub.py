#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Quasi-static frontal loading of the model's thorax at mid-sternum, against Cavanaugh 1988.

What it does: writes the frontal hub deck with hbm-loadcase (case hub_frontal_4p3: the
152 mm hub face at mid-sternum on the body model), turns it into a quasi-static test and
runs hbm-solver on it:
  - the hub no longer flies: /INIVEL on the impactor is dropped and its main node is driven
    along the hub axis by /IMPVEL at --speed (the velocity ramped up over the first 0.5 mm),
    guided (its other translations and its rotations fixed);
  - the back lies on a rigid support (the subject was supine on a frame): every node of the
    thorax skin more than BACK_OFFSET_MM behind the T8 landmark node is fixed in translation
    (nodes that a rigid body carries are left to it);
  - force = the hub contact's normal force (/TH/INTER FN); deflection = hub travel relative to
    the T8 node from first contact (as the hub cases measure it) and, closer to what
    Cavanaugh's linear pots measured, the sternum node's travel relative to T8.
Reported: force at 5, 10, 15, 20 and 25.4 mm; the secant stiffness over Cavanaugh's 25.4 mm
(one inch) stroke for both deflections; the parts that store the most internal energy at
the end of the stroke. A model far off the test is reported, not failed.

Reference: Cavanaugh JM, Jepsen K, King AI, Quasi-static frontal loading of the thorax of
human cadavers and the Hybrid III dummy, 16th Annual International Workshop on Human
Subjects for Biomechanical Research, Atlanta, 1988 (abstract): two unembalmed cadavers,
supine on a support frame, loaded antero-posteriorly by an Instron machine; over a 25.4 mm
stroke the thorax stiffness at the sternum was 6 to 10 N/mm (3.5 to 6 N/mm at the ribs),
the Hybrid III's 26 to 44 N/mm (32 to 73 N/mm at the ribs); loading rates 1.7 to 102 mm/s
showed no consistent change in stiffness. The loading pad's size is not in the abstract:
the hub here is the 152 mm face of the dynamic hub tests, so the comparison is one of
magnitude (an engineer reads a factor, not a percentage).

Run (from the repository root):
  ctest/validation/tools/thorax_quasistatic_hub.py --loadcase build/bin/hbm-loadcase \\
      --solver build/bin/hbm-solver --model decks/hbm50/hbm50.inc --geometry geometry \\
      --work /tmp/thorax_qs [--speed MM_PER_MS] [--stroke MM] [--report FILE.md]
Exit 1 with a message naming the file (and line) on bad input or a failed run; 0 otherwise.
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from isolated_rib_bending import (DriveSchedule, InputError, channel, file_digest, fmt,  # noqa: E402
                                  ids_in_rows_of_10, in_repo, interpolate, positive_number, read_model, read_time_history,
                                  run_hbm_solver, tool_argument_parser, tool_main, write_report_lines)

TOOL = "ctest/validation/tools/thorax_quasistatic_hub.py"
CASE = "hub_frontal_4p3"
BACK_OFFSET_MM = 25.0        # back support: skin nodes more than this behind the T8 node
BACK_PARTS = ("skin_thorax", "skin_thorax_tria")
CAVANAUGH_STROKE_MM = 25.4
CAVANAUGH_STERNUM = (6.0, 10.0)     # N/mm, cadavers, sternum
CAVANAUGH_HYBRID3 = (26.0, 44.0)    # N/mm, Hybrid III, sternum
REPORT_AT_MM = (5.0, 10.0, 15.0, 20.0, CAVANAUGH_STROKE_MM)
CONTACT_FORCE_N = 1.0        # first contact: the hub force first exceeds this
OUTPUT_STROKE_MM = 0.1       # time histories every 0.1 mm of hub travel


# ---------------------------------------------------------------- deck
def split_cards(lines):
    """[(key, [lines after the key])] of a starter deck; comment and blank lines stay with
    the card before them (the head before the first key is card None)."""
    cards = [(None, [])]
    for line in lines:
        if line.startswith("/"):
            cards.append((line.strip(), []))
        else:
            cards[-1][1].append(line)
    return cards


def card_body(card_lines):
    """The card's lines without comments."""
    return [line for line in card_lines if not line.startswith("#")]


def landmark_nodes(path, cards):
    """{label: node id} of the /TH/NODE card 'impactor and landmarks'."""
    for key, body in cards:
        if key and key.startswith("/TH/NODE/"):
            rows = card_body(body)[2:]
            found = {}
            for row in rows:
                try:
                    found[row[10:].strip()] = int(row[0:10])
                except ValueError:
                    raise InputError(f"{path}: {key}: '{row}' is not a node id and a label") from None
            if {"impactor", "T8", "sternum"} <= found.keys():
                return found
    raise InputError(f"{path}: no /TH/NODE card with the nodes 'impactor', 'T8' and 'sternum' "
                     f"(is it an hbm-loadcase {CASE} deck?)")


def time_history_ids(path, cards):
    """Ids of the hub deck's /TH/NODE, /TH/INTER and /TH/PART cards and of the contact the
    /TH/INTER card asks for (hbm-loadcase numbers them above the model's own ids)."""
    ids = {}
    for key, body in cards:
        for kind in ("NODE", "INTER", "PART"):
            if key and key.startswith(f"/TH/{kind}/") and kind not in ids:
                try:
                    ids[kind] = int(key.split("/")[3])
                    if kind == "INTER":
                        ids["contact"] = int(card_body(body)[2].split()[0])
                except (IndexError, ValueError):
                    raise InputError(f"{path}: {key}: expected an id and, for /TH/INTER, a third line "
                                     f"naming the contact") from None
    missing = [k for k in ("NODE", "INTER", "PART") if k not in ids]
    if missing:
        raise InputError(f"{path}: no /TH/{', /TH/'.join(missing)} card (is it an hbm-loadcase {CASE} deck?)")
    return ids


def rigid_body_nodes(model):
    """Main and secondary nodes of every /RBODY of the model (a /BCS on them is refused)."""
    nodes = set()
    for (kind, _), card in model.cards.items():
        if kind != "RBODY" or len(card.lines) < 2:
            continue
        row = card.lines[1]
        try:
            nodes.add(int(row[0:10]))
            grnod = int(row[60:70]) if row[60:70].strip() else 0
        except ValueError:
            raise InputError(f"{model.path}:{card.line_no + 2}: {card.key}: node id (columns 1-10) and "
                             f"node group (61-70) expected: '{row}'") from None
        if grnod:
            group = model.card("GRNOD", grnod, card)
            nodes.update(int(v) for line in group.lines[1:] for v in line.split())
    return nodes


def back_support_nodes(model, t8_x, travel_sign):
    """Thorax skin nodes more than BACK_OFFSET_MM behind T8 along the hub travel, without
    rigid-body nodes; sorted."""
    carried = rigid_body_nodes(model)
    nodes = set()
    for title in BACK_PARTS:
        pid = model.part_id(title)
        for kind, count in (("SHELL", 4), ("SH3N", 3)):
            for row in model.element_nodes(kind, pid, 10, count):
                nodes.update(row)
    behind = [n for n in nodes if n not in carried
              and travel_sign * (model.node(n, "the back support")[0] - t8_x) > BACK_OFFSET_MM]
    if not behind:
        raise InputError(f"{model.path}: no node of {', '.join(BACK_PARTS)} lies {BACK_OFFSET_MM:g} mm behind T8")
    return sorted(behind)


def quasi_static_starter(path, model, schedule, speed):
    """The hub deck's starter lines turned into the quasi-static test (module docstring);
    returns (lines, landmark node ids, time-history ids, number of back nodes, hub axis
    0/1/2, travel sign)."""
    with open(path) as f:
        cards = split_cards(f.read().splitlines())
    marks = landmark_nodes(path, cards)
    th_ids = time_history_ids(path, cards)
    inivel = [(k, b) for k, b in cards if k and k.startswith("/INIVEL/TRA/")]
    if len(inivel) != 1:
        raise InputError(f"{path}: {len(inivel)} /INIVEL/TRA cards (the hub deck has one, on the impactor)")
    try:
        travel = [float(card_body(inivel[0][1])[1][k:k + 20]) for k in (0, 20, 40)]
    except (IndexError, ValueError):
        raise InputError(f"{path}: {inivel[0][0]}: second line is not vx vy vz in 20 columns") from None
    axis = max(range(3), key=lambda k: abs(travel[k]))
    if any(abs(travel[k]) > 1e-9 * abs(travel[axis]) for k in range(3) if k != axis):
        raise InputError(f"{path}: {inivel[0][0]}: the hub does not travel along a global axis")
    sign = 1.0 if travel[axis] > 0 else -1.0
    t8 = model.node(marks["T8"], "the T8 landmark")
    back = back_support_nodes(model, t8[axis], sign)
    out, guided = [], False
    for key, body in cards:
        if key and key.startswith("/INIVEL/TRA/"):
            continue  # the hub is driven instead
        if key == "/END":
            break
        if key and key.startswith("/BCS/") and body and "impactor" in body[0]:
            # the hub's rotations stay fixed; its translations across the drive axis too
            body = [body[0], "   " + "".join("0" if k == axis else "1" for k in range(3)) + " 111" + body[1][10:]]
            guided = True
        out += ([key] if key else []) + body
    if not guided:
        raise InputError(f"{path}: no /BCS card titled 'impactor ...' (the hub deck guides its impactor with one)")
    direction = "XYZ"[axis]
    # ids of the drive and the back support: above every id of the deck (hbm-loadcase numbers
    # its cards above the model's)
    drive_id = 1 + max(int(k.rsplit("/", 1)[1]) for k, _ in cards if k and k.rsplit("/", 1)[1].isdigit())
    back_id = drive_id + 1
    out += schedule.funct_lines(drive_id)
    out += [f"/GRNOD/NODE/{drive_id}", "driven hub main node", f"{marks['impactor']:10d}",
            f"/IMPVEL/{drive_id}", "hub driven at constant speed",
            f"{drive_id:10d}{direction:>10}{0:10d}{0:10d}{drive_id:10d}",
            f"{1.0:20.10E}{sign * speed:20.10E}{0.0:20.10E}{0.0:20.10E}",
            f"/GRNOD/NODE/{back_id}", "back support: thorax skin behind T8"] + ids_in_rows_of_10(back)
    out += [f"/BCS/{back_id}", "back support (subject supine on a rigid frame)",
            f"   111 000{0:10d}{back_id:10d}", "/END"]
    return out, marks, th_ids, len(back), axis, sign


def engine_lines(path, schedule, speed):
    """The hub deck's engine file with the run's end time and the output interval of this test."""
    with open(path) as f:
        cards = split_cards(f.read().splitlines())
    out = []
    for key, body in cards:
        if key and key.startswith("/RUN/"):
            body = [f"{schedule.tstop:g}"] + body[1:]
        elif key and key.startswith("/TFILE/"):
            body = [f"{OUTPUT_STROKE_MM / speed:g}"] + body[1:]
        elif key and key.startswith("/ANIM/DT"):
            body = [f"0 {schedule.tstop / 5:g}"] + body[1:]
        out += ([key] if key else []) + body
    return out


def write_test(args):
    """hbm-loadcase writes the hub deck; it is rewritten into the quasi-static test.
    Returns (starter path, landmarks, time-history ids, back node count, axis, sign)."""
    decks = os.path.join(args.work, "decks")
    try:
        r = subprocess.run([args.loadcase, "--model", args.model, "--geometry", args.geometry, "--case", CASE,
                            "--decks", decks], capture_output=True, text=True)
    except OSError as e:
        raise InputError(f"{args.loadcase}: cannot run hbm-loadcase ({e.strerror})") from None
    if r.returncode != 0:
        raise InputError(f"hbm-loadcase exited {r.returncode}:\n  " + "\n  ".join(r.stderr.strip().splitlines()[-6:]))
    folder = os.path.join(decks, CASE)
    starter, engine = (os.path.join(folder, f"{CASE}_000{k}.rad") for k in (0, 1))
    model = read_model(args.model)
    # the hub starts 3 mm clear of the skin: the stroke counts from first contact
    schedule = DriveSchedule(args.stroke + 8.0, args.speed)
    lines, marks, th_ids, n_back, axis, sign = quasi_static_starter(starter, model, schedule, args.speed)
    engine_text = engine_lines(engine, schedule, args.speed)
    with open(starter, "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(engine, "w") as f:
        f.write("\n".join(engine_text) + "\n")
    return starter, marks, th_ids, n_back, axis, sign


# ---------------------------------------------------------------- results
class Result:
    def __init__(self, deflection, sternum, force, energies, wall_s, error):
        self.deflection = deflection  # hub travel relative to T8 from first contact [mm]
        self.sternum = sternum        # sternum travel relative to T8 from first contact [mm]
        self.force = force            # [N]
        self.energies = energies      # [(J, part title)] at the end of the stroke, largest first
        self.wall_s = wall_s
        self.error = error

    def force_at(self, d):
        return interpolate(d, self.deflection, self.force)

    def secant(self, d):
        f = self.force_at(d)
        return None if f is None else f / d

    def sternum_secant(self, d):
        """Force over the sternum's travel at the hub travel d (Cavanaugh's pots sat on the sternum)."""
        f, s = self.force_at(d), interpolate(d, self.deflection, self.sternum)
        return None if f is None or s is None or s <= 0 else f / s


def read_result(out, marks, th_ids, axis, sign, stroke, wall_s):
    name = "XYZ"[axis]
    node_csv, inter_csv, part_csv = (os.path.join(out, f"{CASE}_TH_{kind}_{th_ids[kind]}.csv")
                                     for kind in ("NODE", "INTER", "PART"))
    nodes, inter, parts = (read_time_history(p) for p in (node_csv, inter_csv, part_csv))
    time = channel(nodes, node_csv, "time", "ms")
    if channel(inter, inter_csv, "time", "ms") != time or channel(parts, part_csv, "time", "ms") != time:
        raise InputError(f"{node_csv}: its times differ from those of the other time histories")
    travel = {label: channel(nodes, node_csv, f"node {nid} {label} D{name}", "mm") for label, nid in marks.items()}
    force = channel(inter, inter_csv, f"inter {th_ids['contact']} impactor contact FN", "N")
    error = max(abs(e) for e in channel(nodes, node_csv, "energy error", "-"))
    first = next((i for i, f in enumerate(force) if f > CONTACT_FORCE_N), None)
    if first is None:
        raise InputError(f"{inter_csv}: the hub force never exceeds {CONTACT_FORCE_N:g} N: no contact")
    hub = [sign * (a - b) for a, b in zip(travel["impactor"], travel["T8"])]
    ster = [sign * (a - b) for a, b in zip(travel["sternum"], travel["T8"])]
    deflection = [h - hub[first] for h in hub[first:]]
    sternum = [s - ster[first] for s in ster[first:]]
    end = next((i for i, d in enumerate(deflection) if d >= stroke), len(deflection) - 1)
    if deflection[end] < stroke:
        raise InputError(f"{node_csv}: the hub travelled {deflection[end]:.1f} mm after first contact, "
                         f"less than the {stroke:g} mm stroke")
    # the solver writes the part histories on the same cycles: row first + end
    # columns 'part ID TITLE IE'
    energies = sorted(((values[first + end], key[len("part "):-len(" IE")].split(" ", 1)[1])
                       for key, (_, values) in parts.items() if key.startswith("part ") and key.endswith(" IE")),
                      reverse=True)
    # the loading branch: only samples whose hub travel exceeds every earlier one (the
    # curves are read by interpolation over the travel)
    rows, reach = [], -1.0
    for k in range(end + 1):
        if deflection[k] > reach:
            rows.append(k)
            reach = deflection[k]
    return Result([deflection[k] for k in rows], [sternum[k] for k in rows], [force[first + k] for k in rows],
                  energies, wall_s, error)


def band(values):
    return f"{values[0]:g}-{values[1]:g}"


def summary_lines(result, args):
    s = CAVANAUGH_STROKE_MM
    hub_k, sternum_k = result.secant(s), result.sternum_secant(s)
    mid = sum(CAVANAUGH_STERNUM) / 2
    lines = [f"force at hub travel {', '.join(f'{d:g}' for d in REPORT_AT_MM)} mm: "
             + " / ".join(fmt(result.force_at(d), ".0f") for d in REPORT_AT_MM) + " N",
             f"secant stiffness over {s:g} mm of hub travel: {fmt(hub_k, '.1f')} N/mm; "
             f"over the sternum's travel then ({fmt(interpolate(s, result.deflection, result.sternum), '.1f')} mm): "
             f"{fmt(sternum_k, '.1f')} N/mm",
             f"Cavanaugh 1988 ({s:g} mm stroke): cadavers {band(CAVANAUGH_STERNUM)} N/mm at the sternum, "
             f"Hybrid III {band(CAVANAUGH_HYBRID3)} N/mm; model / cadaver mid-range "
             f"{fmt(None if sternum_k is None else sternum_k / mid, '.1f')} over the sternum's travel "
             f"(what the pots measured), {fmt(None if hub_k is None else hub_k / mid, '.1f')} over the hub's",
             "internal energy at the end of the stroke: "
             + ", ".join(f"{name} {e:.2f} J" for e, name in result.energies[:8]),
             f"hub speed {args.speed:g} mm/ms, energy error max {100 * result.error:.2f} %, solver {result.wall_s:.0f} s"]
    return lines


def write_report(path, args, result, n_back):
    lines = ["<!-- Written by " + TOOL + "; do not edit by hand. -->",
             "# Quasi-static frontal thorax loading (Cavanaugh 1988)", "",
             f"Model `{in_repo(args.model)}` (sha256 {file_digest(args.model)}), case `{CASE}` rewritten: hub driven at "
             f"{args.speed:g} mm/ms over {args.stroke:g} mm after first contact, back supported "
             f"({n_back} thorax skin nodes more than {BACK_OFFSET_MM:g} mm behind T8 fixed).", ""]
    lines += ["- " + line for line in summary_lines(result, args)]
    lines += ["", "| hub travel [mm] | force [N] | sternum travel [mm] |", "|---|---|---|"]
    for d in REPORT_AT_MM:
        lines.append(f"| {d:g} | {fmt(result.force_at(d), '.0f')} | "
                     f"{fmt(interpolate(d, result.deflection, result.sternum), '.1f')} |")
    lines += ["", "Reference: " + __doc__.split("Reference: ", 1)[1].split("\n\n", 1)[0].replace("\n", " ")]
    write_report_lines(path, lines)


# ---------------------------------------------------------------- main
def parse_args(argv):
    ap = tool_argument_parser(__doc__)
    ap.add_argument("--loadcase", required=True, help="hbm-loadcase executable")
    ap.add_argument("--solver", required=True, help="hbm-solver executable")
    ap.add_argument("--model", required=True, help="body model include (decks/hbm50/hbm50.inc)")
    ap.add_argument("--geometry", required=True, help="geometry sources (geometry/)")
    ap.add_argument("--work", required=True, help="folder for the deck and the run")
    ap.add_argument("--speed", type=positive_number, default=0.1,
                    help="hub speed [mm/ms] (default 0.1 = 100 mm/s, Cavanaugh's fastest rate)")
    ap.add_argument("--stroke", type=positive_number, default=CAVANAUGH_STROKE_MM,
                    help=f"hub travel after first contact [mm] (default {CAVANAUGH_STROKE_MM:g})")
    ap.add_argument("--report", help="write a Markdown report here")
    args = ap.parse_args(argv)
    if args.stroke < CAVANAUGH_STROKE_MM:
        ap.error(f"--stroke must be at least Cavanaugh's {CAVANAUGH_STROKE_MM:g} mm")
    return args


def run(args):
    starter, marks, th_ids, n_back, axis, sign = write_test(args)
    out, _, wall = run_hbm_solver(args.solver, starter)
    result = read_result(out, marks, th_ids, axis, sign, args.stroke, wall)
    for line in summary_lines(result, args):
        print(line)
    if args.report:
        write_report(args.report, args, result, n_back)
        print(f"report: {args.report}")
    return 0


def main(argv=None):
    return tool_main(parse_args, run, argv)


if __name__ == "__main__":
    sys.exit(main())
