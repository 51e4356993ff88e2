#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Validation chain (issue 8): generate the hub pendulum load cases on the body model
# (hbm-loadcase), run each with hbm-solver, rate it with hbm-corridors, and write the
# biofidelity table docs/validation.md (ctest/validation/tools/validation_report.py).
#
#   scripts/validate.sh [--build DIR] [--work DIR] [--cases "NAME ..."|all] [--tstop MS]
#                       [--model FILE | --deckgen "OPTIONS"] [--geometry DIR]
#                       [--doc FILE|--no-doc] [--threads N] [--jobs N] [--deck-hook SCRIPT]
#
# Defaults: build/, work folder out/validation, all cases, 60 ms, decks/hbm50/hbm50.inc,
# docs/validation.md. With the default end time the decks are (re)generated in place in
# decks/<case>/ (the committed load-case decks); with --tstop they go to WORK/decks/.
# --jobs N runs N cases at the same time (each solver then gets nproc/N threads, at least
# 1; results do not depend on the thread count). Every step runs for every case and the
# table is written in any case; the exit status is 0 only if every run terminated
# normally and every rating was written, 1 otherwise, 2 on bad usage. --deck-hook SCRIPT:
# `bash SCRIPT CASE_0000.rad` runs on every generated case deck before the runs (a model
# variant that rewrites the model the deck includes); with --tstop only, so that the committed
# decks are not touched, and on copies of the model folders in WORK/model/ (the base model's
# and each posed variant's), so that the committed model is not either. Cases that share a
# model share its copy: the hook runs once per case deck and must give the same file when
# run again (set a value, do not add to it). --deckgen "OPTIONS": validate a model variant instead of --model:
# hbm-deckgen OPTIONS (e.g. "--pleura --mediastinum 25", docs/deckgen.md) builds the body
# model and its posed variant (the arm-raised model of the oblique cases) into WORK/model/;
# with --tstop only, as --deck-hook. --geometry DIR: the geometry sources hbm-loadcase (and
# hbm-deckgen for --deckgen) read (default geometry).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build=build work=out/validation cases=all tstop="" model=decks/hbm50/hbm50.inc doc=docs/validation.md
threads="" jobs=1 deck_hook="" deckgen_options="" deckgen_set="" model_set="" geometry=geometry
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --cases) cases=$2; shift 2 ;;
    --tstop) tstop=$2; shift 2 ;;
    --model) model=$2; model_set=1; shift 2 ;;
    --deckgen) deckgen_options=$2; deckgen_set=1; shift 2 ;;
    --geometry) geometry=$2; shift 2 ;;
    --doc) doc=$2; shift 2 ;;
    --no-doc) doc=""; shift ;;
    --threads) threads=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --deck-hook) deck_hook=$2; shift 2 ;;
    -h|--help) sed -n '3,25p' "$0"; exit 0 ;;
    *) echo "validate.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
bin=$build/bin
for t in hbm-loadcase hbm-solver hbm-corridors; do
  [[ -x $bin/$t ]] || { echo "validate.sh: $bin/$t not built (cmake --build $build --target $t)" >&2; exit 2; }
done
if [[ -n $deck_hook ]]; then
  [[ -n $tstop ]] || { echo "validate.sh: --deck-hook needs --tstop (it edits the decks it is given)" >&2; exit 2; }
  [[ -f $deck_hook ]] || { echo "validate.sh: --deck-hook $deck_hook: no such file" >&2; exit 2; }
fi
[[ $cases == all ]] && cases=$("$bin/hbm-loadcase" --list | awk '{print $1}')
if [[ -n $deckgen_set ]]; then
  [[ -z $model_set ]] || { echo "validate.sh: --deckgen builds the model: give --model or --deckgen, not both" >&2; exit 2; }
  [[ -n $tstop ]] || { echo "validate.sh: --deckgen needs --tstop (the committed decks are not rewritten for a variant)" >&2; exit 2; }
  [[ -x $bin/hbm-deckgen ]] || { echo "validate.sh: $bin/hbm-deckgen not built (cmake --build $build --target hbm-deckgen)" >&2; exit 2; }
  # The base model, and each posed variant the cases run on (hbm-loadcase --print-posed-model:
  # its path beside the base model's folder, as in decks/, and the options that pose it),
  # all with the variant's options.
  read -r -a variant <<< "$deckgen_options"
  rm -rf "$work/model"
  mkdir -p "$work/model"
  deckgen_variant() {  # FOLDER NAME [OPTIONS...]
    local dir=$1 name=$2
    shift 2
    "$bin/hbm-deckgen" -g "$geometry" -o "$work/model/$dir" -n "$name" --no-drop "$@" "${variant[@]}" \
      > "$work/model/$dir.log" 2>&1 ||
      { echo "validate.sh: hbm-deckgen ${*:+$* }${deckgen_options} failed (see $work/model/$dir.log):" >&2
        tail -3 "$work/model/$dir.log" >&2; exit 1; }
  }
  deckgen_variant hbm50 hbm50
  for c in $cases; do "$bin/hbm-loadcase" --case "$c" --print-posed-model; done | sort -u |
    while read -r posed pose; do
      deckgen_variant "$(dirname "$posed")" "$(basename "$posed" .inc)" $pose
    done
  model=$work/model/hbm50/hbm50.inc
  echo "model variant: hbm-deckgen ${deckgen_options} -> $model"
fi
[[ -f $model ]] || { echo "validate.sh: no body model $model (generate it with hbm-deckgen)" >&2; exit 1; }
if [[ -n $deck_hook && -z $deckgen_set ]]; then
  # The hook rewrites the model the case decks include: give it copies (the base model's
  # folder and each posed variant's beside it, as hbm-loadcase finds them), never the
  # committed files.
  model_dir=$(cd "$(dirname "$model")" && pwd)
  rm -rf "$work/model"
  mkdir -p "$work/model"
  cp -r "$model_dir" "$work/model/"
  for c in $cases; do "$bin/hbm-loadcase" --case "$c" --print-posed-model; done | sort -u |
    while read -r posed _; do
      posed_dir=$(dirname "$model_dir")/$(dirname "$posed")
      [[ -d $posed_dir ]] || { echo "validate.sh: no posed model folder $posed_dir" >&2; exit 1; }
      [[ -d $work/model/$(basename "$posed_dir") ]] || cp -r "$posed_dir" "$work/model/"
    done
  model=$work/model/$(basename "$model_dir")/$(basename "$model")
  echo "deck hook: the model and its posed variants copied to $work/model/"
fi
mkdir -p "$work/runs" "$work/reports"
if [[ -n $tstop ]]; then decks=$work/decks; else decks=decks; fi

# 1. decks
for c in $cases; do
  args=(--model "$model" --geometry "$geometry" --case "$c" --decks "$decks")
  [[ -n $tstop ]] && args+=(--tstop "$tstop")
  "$bin/hbm-loadcase" "${args[@]}" | tee "$work/runs/$c.loadcase.txt"
done

if [[ -n $deck_hook ]]; then
  for c in $cases; do bash "$deck_hook" "$decks/$c/${c}_0000.rad"; done
fi

# 2. runs (wall time measured here; the solver's own timing table is in its listing)
run_case() {
  local c=$1 th=()
  [[ -n $threads ]] && th=(--threads "$threads")
  rm -rf "$work/runs/$c"
  local t0 t1 rc=0
  t0=$(date +%s%N)
  "$bin/hbm-solver" "$decks/$c/${c}_0000.rad" --out "$work/runs/$c" "${th[@]}" > "$work/runs/$c.log" 2>&1 || rc=$?
  t1=$(date +%s%N)
  local ms=$(( (t1 - t0) / 1000000 ))
  printf 'exit_code=%d\nwall_s=%d.%03d\nthreads=%s\nnproc=%s\n' "$rc" $((ms / 1000)) $((ms % 1000)) \
    "${threads:-default}" "$(nproc)" > "$work/runs/$c.run.txt"
  echo "run $c: exit $rc, $(grep -m1 wall_s "$work/runs/$c.run.txt")"
}
if [[ $jobs -gt 1 && -z $threads ]]; then threads=$(( $(nproc) / jobs )); [[ $threads -ge 1 ]] || threads=1; fi
n=0
for c in $cases; do
  run_case "$c" &
  n=$((n + 1))
  if [[ $n -ge $jobs ]]; then wait -n || true; n=$((n - 1)); fi
done
wait

# 3. ratings (a run that produced no usable time history is reported, not rated)
status=0
for c in $cases; do
  grep -q '^exit_code=0$' "$work/runs/$c.run.txt" || { echo "run $c did not terminate normally" >&2; status=1; }
  corridor=$("$bin/hbm-loadcase" --case "$c" --print-corridor-case)
  if ! "$bin/hbm-corridors" --case "$corridor" --th "$work/runs/$c" --out "$work/reports/$c" --quiet \
       > "$work/reports/$c.log" 2>&1; then
    echo "rate $c: hbm-corridors failed (see $work/reports/$c.log):" >&2
    tail -5 "$work/reports/$c.log" >&2
    status=1
  else
    echo "rate $c: $work/reports/$c/report.md"
  fi
done

# 4. table
if [[ -n $doc ]]; then
  /usr/bin/python3 ctest/validation/tools/validation_report.py --work "$work" --cases "$cases" \
    --model "$model" --out "$doc" --images "$(dirname "$doc")/images/validation"
  echo "wrote $doc"
fi
exit $status
