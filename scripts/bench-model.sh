#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Whole-model bench (issue #8): runs the body model deck decks/hub_frontal_6p7 shortened
# to END_MS (default 3 ms = 2000 cycles of 1.5 us) on 1 and 2 threads and prints the
# listing's timing table: ns per element-cycle per element kind (keyword, law,
# formulation) and ns per node-cycle per phase (assembly, contact/loads, constraints,
# time step, nodal update, energies, output). The deck is copied to a temporary folder;
# only the /RUN end time changes.
#   scripts/bench-model.sh [BUILD_DIR [END_MS [THREADS...]]]
#   e.g. scripts/bench-model.sh build 3 1 2
# BENCH_KEEP=DIR keeps the run folders (listing, time histories) in DIR.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-build}"
end_ms="${2:-3}"
shift $(( $# > 2 ? 2 : $# ))
threads=("$@")
[ ${#threads[@]} -gt 0 ] || threads=(1 2)
case "$build" in /*) ;; *) build="$root/$build" ;; esac
solver="$build/bin/hbm-solver"
[ -x "$solver" ] || { echo "bench-model: no $solver (build the hbm-solver target first)" >&2; exit 2; }
case_name=hub_frontal_6p7
work="$(mktemp -d /tmp/hbm-bench-model.XXXXXX)"
trap 'if [ -n "${BENCH_KEEP:-}" ]; then mkdir -p "$BENCH_KEEP" && cp -r "$work"/run_t* "$BENCH_KEEP"/; fi; rm -rf "$work"' EXIT
mkdir -p "$work/decks"
# The committed decks (a deck being regenerated in the working tree can be half-written).
if git -C "$root" rev-parse --verify -q HEAD > /dev/null; then
  git -C "$root" archive HEAD decks/hbm50 "decks/$case_name" | tar -x -C "$work"
else
  cp -r "$root/decks/hbm50" "$root/decks/$case_name" "$work/decks/"
fi
engine="$work/decks/$case_name/${case_name}_0001.rad"
# The line after /RUN/... is the end time.
awk -v t="$end_ms" 'prev ~ /^\/RUN\// { print t; prev = ""; next } { print; prev = $0 }' \
  "$engine" > "$engine.new" && mv "$engine.new" "$engine"
grep -A1 '^/RUN/' "$engine" | tail -1 | grep -qx "$end_ms" || { echo "bench-model: cannot set the /RUN time" >&2; exit 2; }
echo "hbm bench-model: $case_name (decks of $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo 'the working tree')), end time $end_ms ms, solver $solver"
echo "machine: $(nproc) cores, $(uptime | sed 's/.*load/load/')"
for t in "${threads[@]}"; do
  out="$work/run_t$t"
  mkdir -p "$out"
  if ! /usr/bin/time -o "$out/time.txt" -f "%e %U %S" \
      "$solver" "$work/decks/$case_name/${case_name}_0000.rad" --out "$out" --threads "$t" > "$out/stdout.txt" 2>&1; then
    echo "bench-model: run with $t threads failed:" >&2
    tail -5 "$out/stdout.txt" >&2
    exit 1
  fi
  read -r p_wall p_user p_sys < "$out/time.txt"
  echo
  echo "=== threads $t: process wall $p_wall s, user $p_user s, system $p_sys s; load after: $(cut -d' ' -f1-3 /proc/loadavg)"
  sed -n '/^TIMING/,/^$/p' "$out/${case_name}_0001.out"
  # Per-cycle energy error of the last printed cycle (same deck: 1 and 2 threads agree).
  grep -E '^ +[0-9]+ ' "$out/${case_name}_0001.out" | tail -1 | sed 's/^/last cycle: /'
done
# Results must not depend on the thread count: the time histories of the runs are
# compared byte for byte.
first="${threads[0]}"
for t in "${threads[@]:1}"; do
  same=yes
  for f in "$work/run_t$first"/*.csv; do
    cmp -s "$f" "$work/run_t$t/$(basename "$f")" || { same=no; echo "differs: $(basename "$f") ($first vs $t threads)"; }
  done
  echo "time histories $first vs $t threads byte-identical: $same"
done
