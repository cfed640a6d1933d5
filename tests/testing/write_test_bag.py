#!/usr/bin/python3
"""Writes a ROS 1 bag of sensor_msgs/PointCloud2 messages from PCD files for
the tests, with the user tool tools/mlndt_bag.py (the same messages):

  write_test_bag.py OUT.bag TOPIC [--stamps=FILE] [--point_time]
                    [--other_topic=NAME] SCAN.pcd ...

is mlndt_bag.py --output=OUT.bag --topic=TOPIC --force and
  --stamps=FILE   --times=FILE (one stamp per scan), else --rate=10
                  --start=1000 (stamps 1000 + 0.1 i s);
  --point_time    --point_times=step:1e-6 (float32 field "time" = i * 1e-6 s
                  for point i: a ramp the reader must return);
  --other_topic   also a std_msgs/String message on that topic;
  --header_stamps=FILE  then sets the messages' header stamps to FILE's (one
                  a line; may repeat, be 0 or go back, as a driver's can,
                  which mlndt_bag.py refuses), the record times unchanged.
The frame is "lidar". Kept for the tests' callers (tests/testing/test_bag.cc,
lab/python/tests/test_ros_bag.py).
"""
import importlib.util
import pathlib
import sys

TOOL = pathlib.Path(__file__).resolve().parents[2] / "tools" / "mlndt_bag.py"


def load_tool():
    spec = importlib.util.spec_from_file_location("mlndt_bag", TOOL)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def set_header_stamps(out, topic, stamps_path):
    import os
    import rosbag
    import rospy
    with open(stamps_path) as f:
        stamps = [float(line) for line in f if line.strip()]
    rewritten = out + ".stamps.bag"
    with rosbag.Bag(out) as source, rosbag.Bag(rewritten, "w") as target:
        for k, (name, msg, t) in enumerate(source.read_messages(topics=[topic])):
            msg.header.stamp = rospy.Time.from_sec(stamps[k])
            target.write(name, msg, t)
    os.replace(rewritten, out)


def main(argv):
    options = [a for a in argv if a.startswith("--")]
    positional = [a for a in argv if not a.startswith("--")]
    if len(positional) < 3:
        sys.exit(__doc__)
    out, topic, scans = positional[0], positional[1], positional[2:]
    args = [f"--output={out}", f"--topic={topic}", "--frame_id=lidar", "--force"]
    stamps = ["--rate=10", "--start=1000"]
    other_topic = None
    header_stamps = None
    for option in options:
        if option.startswith("--stamps="):
            stamps = ["--times=" + option.split("=", 1)[1]]
        elif option == "--point_time":
            args.append("--point_times=step:1e-6")
        elif option.startswith("--other_topic="):
            other_topic = option.split("=", 1)[1]
        elif option.startswith("--header_stamps="):
            header_stamps = option.split("=", 1)[1]
        else:
            sys.exit(f"unknown option {option}")
    code = load_tool().main(args + stamps + scans)
    if code != 0:
        return code
    if header_stamps is not None:
        set_header_stamps(out, topic, header_stamps)
    if other_topic is None:
        return 0
    import rosbag
    from std_msgs.msg import String
    with rosbag.Bag(out, "a") as bag:
        first = next(bag.read_messages(topics=[topic]))
        bag.write(other_topic, String(data="not a cloud"), first.timestamp)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
