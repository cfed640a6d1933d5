#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, and aligns the
# Velodyne scan pair bundled in data/ (the main job).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
build/tools/mlndt_align --output_json=build/align_result.json "$@"
echo "result written to build/align_result.json"
