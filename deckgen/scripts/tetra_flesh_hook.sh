#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Deck hook for scripts/validate.sh --deck-hook: the model a generated case deck includes is
# replaced by its tetra-flesh variant (tetra_flesh.py; parts in TETRA_FLESH_PARTS, default
# flesh_thorax), written next to the case deck as model_tetra_flesh.inc.
#   tetra_flesh_hook.sh CASE_0000.rad
set -euo pipefail
deck=$1
dir=$(dirname "$deck")
inc=$(grep -m1 '^#include ' "$deck" | awk '{print $2}')
[[ -n $inc ]] || { echo "tetra_flesh_hook.sh: $deck includes no model" >&2; exit 1; }
[[ $inc == model_tetra_flesh.inc ]] && exit 0
python3 "$(dirname "$0")/tetra_flesh.py" "$dir/$inc" "$dir/model_tetra_flesh.inc" --parts "${TETRA_FLESH_PARTS:-flesh_thorax}"
sed -i "s|^#include $inc\$|#include model_tetra_flesh.inc|" "$deck"
