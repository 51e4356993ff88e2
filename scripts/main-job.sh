#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs dependencies, builds, and runs the main job on the default model.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out/example
./build/bin/hbm-solver decks/examples/impact/impact_0000.rad --out out/example
