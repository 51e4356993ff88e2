#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs dependencies, builds, generates the body model (decks/hbm50/), writes the 6.7 m/s
# frontal hub impact deck on it (Lebarbe & Petit 2012), runs it (60 ms) and writes its
# corridor report: out/hub_frontal_6p7/ (solver output), out/hub_frontal_6p7_report/
# (report.md, report.html, plots/hub_force_deflection_6p7.png, summary.json).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/bin/hbm-deckgen --out decks/hbm50
./build/bin/hbm-loadcase --model decks/hbm50/hbm50.inc --case hub_frontal_6p7 --decks decks
mkdir -p out
./build/bin/hbm-solver decks/hub_frontal_6p7/hub_frontal_6p7_0000.rad --out out/hub_frontal_6p7
./build/bin/hbm-corridors --case "$(./build/bin/hbm-loadcase --case hub_frontal_6p7 --print-corridor-case)" \
  --th out/hub_frontal_6p7 --out out/hub_frontal_6p7_report
echo "report: out/hub_frontal_6p7_report/report.md"
