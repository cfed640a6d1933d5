#!/usr/bin/env bash
# The README's first command: installs what is missing, builds the library
# and mlndt_align only (scripts/test.sh builds the rest: the other tools, the
# tests and the Python module), and aligns the Velodyne scan pair bundled in
# data/ (the main job). Says what it is doing at each step.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
echo "quickstart 1/3: Debian packages (installs only the missing ones; the first time takes minutes)"
scripts/install_deps.sh
echo "quickstart 2/3: building the library and mlndt_align in build/ (a first build takes a few minutes; progress in build.log)"
MLNDT_BUILD_TARGETS=mlndt_align scripts/build.sh
echo "quickstart 3/3: aligning data/koide3's two scans ($((SECONDS - start)) s so far)"
build/tools/mlndt_align data/koide3/251370668.pcd data/koide3/251371071.pcd \
  --expected_matrix_file=data/koide3/T_target_source.txt \
  --output_json=build/align_result.json "$@"
echo "result written to build/align_result.json"
