#!/usr/bin/env bash
# The README's second command: installs what is missing, builds, and runs the
# whole test suite with ctest. Tests that need the larger shared LiDAR data
# set read it from $MLNDT_DATA_DIR and skip, saying why, without it.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
