#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# validate.sh --deck-hook rewrites the model the case decks include: it must do so on copies
# in WORK/model/, never on the committed decks/hbm50/hbm50.inc (regression: a hook once
# edited the repository's model). Runs the 6.7 m/s frontal hub for 3 ms with a hook that
# marks every model it is given, then checks that the committed model is byte-identical,
# that the copy carries the mark, and that the case deck includes the copy.
#   check_deck_hook_copies_model.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -euo pipefail
src=$1 build=$2 work=$3
model=$src/decks/hbm50/hbm50.inc
[[ -f $model ]] || { echo "no committed model $model" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
before=$(sha256sum "$model" | cut -d' ' -f1)
hook=$work/mark_model.sh
cat > "$hook" <<'HOOK'
deck=$1
for inc in $(grep '^#include' "$deck" | awk '{print $2}'); do
  f="$(dirname "$deck")/$inc"
  grep -q '^# deck hook mark$' "$f" || echo '# deck hook mark' >> "$f"
done
HOOK
bash "$src/scripts/validate.sh" --build "$build" --work "$work/run" --cases hub_frontal_6p7 --tstop 3 \
  --no-doc --deck-hook "$hook" > "$work/validate.log" 2>&1 ||
  { echo "validate.sh failed:" >&2; tail -20 "$work/validate.log" >&2; exit 1; }
after=$(sha256sum "$model" | cut -d' ' -f1)
[[ $before == "$after" ]] || { echo "FAIL: the deck hook changed the committed model $model" >&2; exit 1; }
grep -q '^# deck hook mark$' "$work/run/model/hbm50/hbm50.inc" ||
  { echo "FAIL: the model copy $work/run/model/hbm50/hbm50.inc has no hook mark" >&2; exit 1; }
inc=$(grep -m1 '^#include' "$work/run/decks/hub_frontal_6p7/hub_frontal_6p7_0000.rad" | awk '{print $2}')
[[ $(cd "$work/run/decks/hub_frontal_6p7" && realpath "$inc") == "$(realpath "$work/run/model/hbm50/hbm50.inc")" ]] ||
  { echo "FAIL: the case deck includes $inc, not the model copy" >&2; exit 1; }
echo "deck hook ran on the model copy; committed model unchanged (sha256 ${before:0:12})"
