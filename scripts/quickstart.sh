#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, and aligns the
# Velodyne scan pair bundled in data/ (the main job).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
build/tools/mlndt_align data/koide3/251370668.pcd data/koide3/251371071.pcd \
  --expected_matrix_file=data/koide3/T_target_source.txt \
  --output_json=build/align_result.json "$@"
echo "result written to build/align_result.json"
