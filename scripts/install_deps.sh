#!/usr/bin/env bash
# Installs the Debian 12 packages mlndt needs, only those that are missing.
#   scripts/install_deps.sh [--with-pcl] [--with-ros]
# --with-pcl also installs libpcl-dev (large), for -DMLNDT_WITH_PCL=ON.
# --with-ros also installs Debian's ROS 1 (roscore, roslaunch, rosbag, roscpp,
# tf2_ros, the messages, rospy's message modules for the tests, RViz, Xvfb
# and xwd), for -DMLNDT_WITH_ROS=ON (integrations/ros, scripts/check_ros.sh).
# clang, libclang-rt-14-dev (libFuzzer and the sanitizer runtimes) and
# libomp-dev (OpenMP for clang) are for .ci/fuzz; g++'s own ASan, UBSan and
# TSan runtimes (.ci/sanitize) come with g++.
set -euo pipefail

packages=(
  cmake make g++ pkg-config
  libeigen3-dev libceres-dev libgoogle-glog-dev libgflags-dev
  libgtest-dev libgmock-dev libbenchmark-dev liblzf-dev nlohmann-json3-dev
  gnuplot-nox clang-format ccache
  clang libclang-rt-14-dev libomp-dev
  # The Python module (python/) and its tests, for Debian's /usr/bin/python3;
  # pip install . into a venv (scripts/check_pip_install.sh) and
  # mlndt.distributed's Dask.
  pybind11-dev python3-dev python3-numpy python3-pytest
  python3-venv python3-pip python3-setuptools python3-dask python3-distributed
  # ROS 1 bags in the tools (lab/io, MLNDT_WITH_ROSBAG) and the bag written
  # by the tests (python3-rosbag, python3-sensor-msgs).
  librosbag-storage-dev libsensor-msgs-dev python3-rosbag python3-sensor-msgs
  # The lab's LiDAR simulator (lab/sim, MLNDT_WITH_EMBREE): Embree 3.
  libembree-dev
)

for arg in "$@"; do
  case "$arg" in
    --with-pcl) packages+=(libpcl-dev) ;;
    --with-ros)
      packages+=(ros-core-dev libroscpp-dev libtf2-ros-dev libnav-msgs-dev
        libdiagnostic-msgs-dev python3-rosbag python3-roslaunch rosbash catkin
        python3-nav-msgs python3-diagnostic-msgs python3-tf2-msgs python3-std-srvs
        rviz xvfb x11-apps)
      ;;
    *)
      echo "install_deps: unknown argument '$arg' (usage: $0 [--with-pcl] [--with-ros])" >&2
      exit 1
      ;;
  esac
done

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install_deps: all ${#packages[@]} packages are installed"
  exit 0
fi

sudo=""
if [[ $(id -u) -ne 0 ]]; then
  sudo="sudo"
fi
echo "install_deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
