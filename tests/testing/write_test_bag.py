#!/usr/bin/python3
"""Writes a ROS 1 bag of sensor_msgs/PointCloud2 messages from PCD files.

Test data for the bag reader (lab/io/ros_bag_scans.h), made at test time with
the real python3-rosbag from the bundled or shared scans:

  write_test_bag.py OUT.bag TOPIC [--stamps=FILE] [--point_time]
                    [--other_topic=NAME] SCAN.pcd ...

Each PCD (DATA binary or ascii, float32 x/y/z among any fields) becomes one
message with fields x, y, z (float32) and, with --point_time, a float32 field
"time" = k * 1e-6 s for point k (a ramp the reader must return). Header stamps
come from --stamps (one number per scan) or are 1000 + 0.1 i s. With
--other_topic, a std_msgs/String message is written on that topic too.
"""
import struct
import sys

import rosbag
import rospy
from sensor_msgs.msg import PointCloud2, PointField
from std_msgs.msg import String


def read_pcd_xyz(path):
    with open(path, "rb") as f:
        data = f.read()
    header = {}
    offset = 0
    while True:
        end = data.index(b"\n", offset)
        line = data[offset:end].decode("ascii").strip()
        offset = end + 1
        if not line or line.startswith("#"):
            continue
        key, *values = line.split()
        header[key.upper()] = values
        if key.upper() == "DATA":
            break
    fields = header["FIELDS"]
    sizes = [int(s) for s in header["SIZE"]]
    types = header["TYPE"]
    counts = [int(c) for c in header.get("COUNT", ["1"] * len(fields))]
    n = int(header["POINTS"][0])
    kind = header["DATA"][0]
    points = []
    if kind == "ascii":
        for line in data[offset:].decode("ascii").splitlines():
            values = line.split()
            if values:
                points.append(tuple(float(values[fields.index(a)]) for a in "xyz"))
        return points
    if kind != "binary":
        sys.exit(f"{path}: DATA {kind} is not supported by this script")
    step = sum(s * c for s, c in zip(sizes, counts))
    offsets = {}
    o = 0
    for name, s, t, c in zip(fields, sizes, types, counts):
        offsets[name] = (o, s, t)
        o += s * c
    for a in "xyz":
        if offsets[a][1:] != (4, "F"):
            sys.exit(f"{path}: field {a} is not float32")
    for k in range(n):
        base = offset + k * step
        points.append(tuple(struct.unpack_from("<f", data, base + offsets[a][0])[0]
                            for a in "xyz"))
    return points


def make_message(points, stamp, point_time, frame_id):
    msg = PointCloud2()
    msg.header.stamp = rospy.Time.from_sec(stamp)
    msg.header.frame_id = frame_id
    msg.height = 1
    msg.width = len(points)
    msg.fields = [PointField("x", 0, PointField.FLOAT32, 1),
                  PointField("y", 4, PointField.FLOAT32, 1),
                  PointField("z", 8, PointField.FLOAT32, 1)]
    if point_time:
        msg.fields.append(PointField("time", 12, PointField.FLOAT32, 1))
    msg.point_step = 16 if point_time else 12
    msg.row_step = msg.point_step * msg.width
    msg.is_bigendian = False
    msg.is_dense = False
    buffer = bytearray(msg.row_step)
    for k, p in enumerate(points):
        struct.pack_into("<fff", buffer, k * msg.point_step, *p)
        if point_time:
            struct.pack_into("<f", buffer, k * msg.point_step + 12, k * 1e-6)
    msg.data = bytes(buffer)
    return msg


def main(argv):
    options = [a for a in argv if a.startswith("--")]
    positional = [a for a in argv if not a.startswith("--")]
    if len(positional) < 3:
        sys.exit(__doc__)
    out, topic, scans = positional[0], positional[1], positional[2:]
    stamps = [1000.0 + 0.1 * i for i in range(len(scans))]
    point_time = False
    other_topic = None
    for option in options:
        if option.startswith("--stamps="):
            with open(option.split("=", 1)[1]) as f:
                stamps = [float(line) for line in f if line.strip()]
        elif option == "--point_time":
            point_time = True
        elif option.startswith("--other_topic="):
            other_topic = option.split("=", 1)[1]
        else:
            sys.exit(f"unknown option {option}")
    if len(stamps) < len(scans):
        sys.exit(f"{len(stamps)} stamps for {len(scans)} scans")
    with rosbag.Bag(out, "w") as bag:
        for i, path in enumerate(scans):
            msg = make_message(read_pcd_xyz(path), stamps[i], point_time, "lidar")
            bag.write(topic, msg, msg.header.stamp)
        if other_topic:
            bag.write(other_topic, String(data="not a cloud"),
                      rospy.Time.from_sec(stamps[0]))


if __name__ == "__main__":
    main(sys.argv[1:])
