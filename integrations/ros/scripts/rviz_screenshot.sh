#!/usr/bin/env bash
# RViz's view of mlndt_odometry_node on a bag, drawn on a virtual X display
# (Xvfb) and saved as a PNG (docs/images/rviz_odometry.png was made so):
#   integrations/ros/scripts/rviz_screenshot.sh BAG N_SCANS OUT.png \
#       [FOCAL_X,FOCAL_Y,DISTANCE,YAW,PITCH]
# BAG holds N_SCANS clouds on /points (tools/mlndt_bag.py writes one); the
# view (metres, radians) replaces rviz/odometry.rviz's. roslaunch runs
# odometry.launch with rviz:=true, the bag starts paused and plays once the
# node talks to this script; the picture is taken when the node has given
# its verdict on every cloud. Needs the nodes built (build-ros/, or
# MLNDT_ROS_PREFIX), Xvfb, RViz and xwd (x11-apps). Every process started
# here is stopped on exit.
set -euo pipefail
if (($# < 3)); then
  sed -n '2,13p' "$0" >&2
  exit 2
fi
bag=$(realpath "$1") count=$2 out=$3 view=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
prefix=${MLNDT_ROS_PREFIX:-$here/../../../build-ros/ros}
work=$(mktemp -d)
groups=()
cleanup() {
  for group in "${groups[@]}"; do kill -INT -- "-$group" 2> /dev/null || true; done
  for group in "${groups[@]}"; do
    for _ in $(seq 50); do kill -0 -- "-$group" 2> /dev/null || break; sleep 0.1; done
    kill -KILL -- "-$group" 2> /dev/null || true
  done
  rm -rf "$work"
}
trap cleanup EXIT

# The view.
config=$work/odometry.rviz
cp "$here/../rviz/odometry.rviz" "$config"
if [[ -n $view ]]; then
  IFS=, read -r fx fy distance yaw pitch <<< "$view"
  /usr/bin/python3 - "$config" "$fx" "$fy" "$distance" "$yaw" "$pitch" << 'PY'
import re, sys
path, fx, fy, distance, yaw, pitch = sys.argv[1:]
text = open(path).read()
text = re.sub(r"(Focal Point:\n\s+X:) .*\n(\s+Y:) .*", rf"\1 {fx}\n\2 {fy}", text)
for key, value in (("Distance", distance), ("Yaw", yaw), ("Pitch", pitch)):
    text = re.sub(rf"(\n      {key}:) .*", rf"\1 {value}", text)
open(path, "w").write(text)
PY
fi

# A virtual display: Xvfb writes its number to fd 3 once it accepts clients.
setsid Xvfb -displayfd 3 -screen 0 1400x900x24 -nolisten tcp 3> "$work/display" \
  > "$work/xvfb.log" 2>&1 &
groups+=($!)
for _ in $(seq 100); do [[ -s $work/display ]] && break; sleep 0.1; done
export DISPLAY=":$(cat "$work/display")"

port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
. "$prefix/setup.sh"
export ROS_MASTER_URI=http://127.0.0.1:$port ROS_HOSTNAME=127.0.0.1
export ROS_HOME=$work/ros ROS_LOG_DIR=$work/ros/log
printf 'local_map_period_s: 0\nqueue_size: 100\n' > "$work/params.yaml"
setsid roslaunch -p "$port" mlndt_ros odometry.launch bag:="$bag" rviz:=true paused:=true \
  params:="$work/params.yaml" rate:=2 rviz_config:="$config" > "$work/roslaunch.log" 2>&1 &
groups+=($!)
timeout 600 /usr/bin/python3 "$here/play_and_wait.py" "$count" 600 \
  || { tail -30 "$work/roslaunch.log"; exit 1; }
# RViz draws the last messages within a frame or two (30 frames a second).
sleep 3
xwd -root -silent -display "$DISPLAY" > "$work/screen.xwd"
/usr/bin/python3 "$here/xwd_to_png.py" "$work/screen.xwd" "$out"
echo "rviz_screenshot: $out"
