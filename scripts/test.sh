#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs dependencies, builds, and runs every test except the long `validation` label.
# The deck mutation test is also built and run with AddressSanitizer and UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" -LE validation
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHBM_SANITIZE=ON -DHBM_BUILD_DECKGEN=OFF
cmake --build build-asan -j "$(nproc)" --target deck_sanitized_tests
ctest --test-dir build-asan --output-on-failure -L sanitize
