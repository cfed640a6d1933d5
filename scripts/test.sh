#!/usr/bin/env bash
# The README's second command: installs what is missing, builds, and runs the
# whole test suite with ctest: the GoogleTest tests and the pytest suite of
# the Python module (python/tests, one ctest test per file) and of the lab's
# module (lab/python/tests). Tests that need
# the larger shared LiDAR data set read it from $MLNDT_DATA_DIR and skip,
# saying why, without it.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
# ON: install_deps.sh has installed pybind11 and Python's packages (and the
# ROS 1 bag libraries), and a build folder configured before they were there
# would keep the module (and bag input) off. The lab's Python module
# mlndt_lab (never installed, not in the wheel) is built here for its tests.
scripts/build.sh -DMLNDT_BUILD_PYTHON=ON -DMLNDT_BUILD_PYTHON_LAB=ON -DMLNDT_WITH_ROSBAG=ON
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
