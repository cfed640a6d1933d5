#!/usr/bin/env bash
# The ROS 1 nodes (integrations/ros, docs/ros.md) end to end, in their own
# build folder build-ros/: installs Debian's ROS 1 packages
# (scripts/install_deps.sh --with-ros), configures with -DMLNDT_WITH_ROS=ON,
# builds the nodes, the tools their tests compare against and the tests, and
# runs them: the core's unit tests (ros_core/*), the tests with real ROS
# processes (ros/test_ros_nodes: roscore, rosbag play, roslaunch), the bag
# tool's and the PointCloud2 decoder's tests. Exit code 0 when all pass.
#   scripts/check_ros.sh [--no-install]
# Logs: build-ros/check_ros.log (configure and build), ctest's output.
set -euo pipefail
cd "$(dirname "$0")/.."

if [[ ${1:-} != --no-install ]]; then
  scripts/install_deps.sh --with-ros
fi

launcher=()
if command -v ccache > /dev/null; then
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(pwd)}"
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
mkdir -p build-ros
log=build-ros/check_ros.log
start=$SECONDS
cmake -S . -B build-ros -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
  -DMLNDT_WITH_ROS=ON -DMLNDT_WITH_ROSBAG=ON -DMLNDT_BUILD_TESTS=ON \
  -DMLNDT_BUILD_BENCHMARKS=OFF -DMLNDT_BUILD_PYTHON=OFF > "$log" 2>&1 \
  || { cat "$log"; exit 1; }
cmake --build build-ros -j"$(nproc)" --target mlndt_ros_tests tools_tests \
  io_tests >> "$log" 2>&1 || { tail -50 "$log"; exit 1; }
echo "check_ros: built in $((SECONDS - start)) s (log in $log)"

ctest --test-dir build-ros --output-on-failure --timeout 600 \
  -R '^(ros|ros_core)/|/(MlndtBag|DecodePointCloud2|RosBagScans)\.'
echo "check_ros: ok in $((SECONDS - start)) s"
