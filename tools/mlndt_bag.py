#!/usr/bin/python3
"""mlndt_bag: writes a ROS 1 bag of sensor_msgs/PointCloud2 messages from scan files.

  mlndt_bag.py --output=OUT.bag (--times=FILE | --rate=HZ [--start=S])
               [--topic=/points] [--frame_id=lidar]
               [--point_times=none|step:SECONDS|field:NAME]
               [--max_scans=N] [--force] SCAN_OR_FOLDER ...

Each scan file becomes one message, in the order given (a folder gives its
.pcd and .bin files sorted by name): PCD (DATA ascii, binary or
binary_compressed; float x/y/z among any fields) or KITTI .bin (float32 x, y,
z, intensity). The message has the fields x, y, z (float32, or float64 when
the PCD stores them so) and, with --point_times, a per-point time field
"time" relative to the header stamp, which the odometry uses for deskewing:
  step:SECONDS   point k at k * SECONDS (float32), a ramp in file order;
  field:NAME     the PCD's field NAME, in seconds relative to the stamp
                 (float64).
Header stamps (and the bag's record times) come from --times (a text file,
one stamp [s] a line, the first number of each line; exactly one per scan
given) or from --rate: --start + k * (1 / HZ); each in (0, 2^32) s (ROS
time 0 means none). A stamp not after the one before, and a scan without
points, are written as given with a warning (test bags use both).

Exit codes: 0 written; 1 the bag could not be written (a scan's data
unreadable, a full disk, ...: no file is left behind); 2 bad input refused
before any work (a flag, a missing scan or one whose header lacks what the
message needs, a stamp count that does not match, an existing --output
without --force).

Needs Debian's python3-rosbag and python3-sensor-msgs (and python3-numpy).
"""
import argparse
import os
import struct
import sys

import numpy as np

EXIT_FAILURE = 1
EXIT_USAGE = 2

PCD_TYPES = {("F", 4): "<f4", ("F", 8): "<f8", ("U", 1): "<u1", ("U", 2): "<u2",
             ("U", 4): "<u4", ("U", 8): "<u8", ("I", 1): "<i1", ("I", 2): "<i2",
             ("I", 4): "<i4", ("I", 8): "<i8"}


class InputError(Exception):
    """Bad input, refused before any work (exit 2)."""


def lzf_decompress(data, size):
    """LZF (liblzf) decompression, as PCL's binary_compressed uses it."""
    out = bytearray()
    i = 0
    while i < len(data):
        ctrl = data[i]
        i += 1
        if ctrl < 32:
            out += data[i:i + ctrl + 1]
            i += ctrl + 1
            continue
        length = ctrl >> 5
        if length == 7:
            length += data[i]
            i += 1
        ref = len(out) - ((ctrl & 0x1F) << 8) - data[i] - 1
        i += 1
        if ref < 0:
            raise InputError("corrupt binary_compressed data")
        for _ in range(length + 2):
            out.append(out[ref])
            ref += 1
    if len(out) != size:
        raise InputError(f"binary_compressed data holds {len(out)} bytes, not {size}")
    return bytes(out)


def read_pcd_header(data, path):
    header, offset = {}, 0
    while True:
        end = data.find(b"\n", offset)
        if end < 0:
            raise InputError(f"{path}: no DATA line (not a PCD file?)")
        line = data[offset:end].decode("ascii", "replace").strip()
        offset = end + 1
        if not line or line.startswith("#"):
            continue
        key, *values = line.split()
        header[key.upper()] = values
        if key.upper() == "DATA":
            return header, offset


def pcd_dtype(header, path):
    fields = header.get("FIELDS")
    sizes = [int(s) for s in header.get("SIZE", [])]
    types = header.get("TYPE", [])
    counts = [int(c) for c in header.get("COUNT", ["1"] * len(fields or []))]
    if not fields or not len(fields) == len(sizes) == len(types) == len(counts):
        raise InputError(f"{path}: FIELDS, SIZE, TYPE and COUNT do not match")
    columns = []
    for k, (name, size, kind, count) in enumerate(zip(fields, sizes, types, counts)):
        if (kind, size) not in PCD_TYPES:
            raise InputError(f"{path}: field {name} has type {kind}{size}")
        dtype = PCD_TYPES[(kind, size)]
        columns.append((name if name != "_" else f"_pad{k}", dtype, (count,) if count > 1 else ()))
    return np.dtype(columns)


def read_pcd(path):
    """The PCD's points as a structured array with its fields."""
    with open(path, "rb") as f:
        data = f.read()
    header, offset = read_pcd_header(data, path)
    dtype = pcd_dtype(header, path)
    n = int(header.get("POINTS", ["0"])[0])
    kind = header["DATA"][0]
    if kind == "ascii":
        rows = [line.split() for line in data[offset:].decode("ascii").splitlines()
                if line.strip()]
        if len(rows) != n or any(len(row) != len(dtype.names) for row in rows):
            raise InputError(f"{path}: {len(rows)} ascii rows of one value per field "
                             f"for POINTS {n}")
        values = np.array(rows, dtype=np.float64).reshape(n, len(dtype.names))
        points = np.zeros(n, dtype=dtype)
        for k, name in enumerate(dtype.names):
            points[name] = values[:, k]
        return points
    if kind == "binary":
        if len(data) - offset < n * dtype.itemsize:
            raise InputError(f"{path}: binary data shorter than POINTS {n}")
        return np.frombuffer(data, dtype=dtype, count=n, offset=offset)
    if kind == "binary_compressed":
        compressed, size = struct.unpack_from("<II", data, offset)
        raw = lzf_decompress(data[offset + 8:offset + 8 + compressed], size)
        # Stored field by field (all x, then all y, ...).
        points = np.zeros(n, dtype=dtype)
        start = 0
        for name in dtype.names:
            field = np.dtype([(name, dtype.fields[name][0])])
            points[name] = np.frombuffer(raw, dtype=field, count=n, offset=start)[name]
            start += n * field.itemsize
        return points
    raise InputError(f"{path}: DATA {kind} is not supported")


def check_scan(path, point_times):
    """Reads what a scan's header says (not its points): refused before any
    work when it cannot be read as the message needs."""
    if path.endswith(".bin"):
        if os.path.getsize(path) % 16:
            raise InputError(f"{path}: not a KITTI .bin (size is not 16 bytes a point)")
        if point_times and point_times[0] == "field":
            raise InputError(f"{path}: a KITTI .bin has no field {point_times[1]}")
        return
    with open(path, "rb") as f:
        head = f.read(4096)
    header, _ = read_pcd_header(head, path)
    dtype = pcd_dtype(header, path)
    for axis in "xyz":
        if axis not in dtype.names or dtype[axis].kind != "f" or dtype[axis].shape:
            raise InputError(f"{path}: no float field {axis}")
    if point_times and point_times[0] == "field" and point_times[1] not in dtype.names:
        raise InputError(f"{path}: no field {point_times[1]} for --point_times")
    if header["DATA"][0] not in ("ascii", "binary", "binary_compressed"):
        raise InputError(f"{path}: DATA {header['DATA'][0]} is not supported")


def read_scan(path):
    if path.endswith(".bin"):
        raw = np.fromfile(path, dtype="<f4")
        if raw.size % 4:
            raise InputError(f"{path}: not a KITTI .bin (size is not 16 bytes a point)")
        raw = raw.reshape(-1, 4)
        points = np.zeros(len(raw), dtype=[("x", "<f4"), ("y", "<f4"), ("z", "<f4"),
                                           ("intensity", "<f4")])
        for k, name in enumerate(("x", "y", "z", "intensity")):
            points[name] = raw[:, k]
        return points
    return read_pcd(path)


def make_message(points, stamp, frame_id, point_times, time_field):
    import rospy
    from sensor_msgs.msg import PointCloud2, PointField
    xyz_type = "<f8" if points.dtype["x"].itemsize == 8 else "<f4"
    columns = [("x", xyz_type), ("y", xyz_type), ("z", xyz_type)]
    if point_times is not None:
        columns.append(("time", "<f4" if point_times[0] == "step" else "<f8"))
    out = np.zeros(len(points), dtype=columns)
    for axis in "xyz":
        out[axis] = points[axis]
    if point_times is not None:
        mode, value = point_times
        if mode == "step":
            # float32 of k * step (k * step in double first).
            out["time"] = (np.arange(len(points), dtype=np.float64) * value).astype(np.float32)
        else:
            out["time"] = points[time_field].astype(np.float64)
    msg = PointCloud2()
    msg.header.stamp = rospy.Time.from_sec(stamp)
    msg.header.frame_id = frame_id
    msg.height, msg.width = 1, len(points)
    kinds = {"<f4": PointField.FLOAT32, "<f8": PointField.FLOAT64}
    msg.fields = [PointField(name, out.dtype.fields[name][1], kinds[out.dtype[name].str], 1)
                  for name in out.dtype.names]
    msg.is_bigendian = False
    msg.point_step = out.dtype.itemsize
    msg.row_step = msg.point_step * msg.width
    msg.is_dense = False
    msg.data = out.tobytes()
    return msg


def list_scans(inputs):
    scans = []
    for item in inputs:
        if os.path.isdir(item):
            names = sorted(n for n in os.listdir(item) if n.endswith((".pcd", ".bin")))
            if not names:
                raise InputError(f"{item}: no .pcd or .bin files")
            scans += [os.path.join(item, n) for n in names]
        elif os.path.isfile(item):
            if not item.endswith((".pcd", ".bin")):
                raise InputError(f"{item}: not a .pcd or .bin file")
            scans.append(item)
        else:
            raise InputError(f"{item}: no such file or folder")
    if not scans:
        raise InputError("no scans given")
    return scans


def stamps_for(args, count):
    if args.times:
        try:
            with open(args.times) as f:
                stamps = [float(line.split()[0]) for line in f
                          if line.strip() and not line.lstrip().startswith("#")]
        except (OSError, ValueError) as e:
            raise InputError(f"--times={args.times}: {e}")
        if len(stamps) != args.given_scans:
            raise InputError(f"--times={args.times} has {len(stamps)} stamps for "
                             f"{args.given_scans} scans (one per scan)")
        return stamps[:count]
    if not args.rate > 0:
        raise InputError("--rate must be > 0 (scans per second)")
    period = 1.0 / args.rate
    return [args.start + period * k for k in range(count)]


def check_stamps(stamps):
    for k, stamp in enumerate(stamps):
        if not (stamp > 0 and stamp < 4294967295):
            raise InputError(f"stamp {k} is {stamp!r}: ROS stamps must be in (0, 2^32) s "
                             "(time 0 means none, and a bag cannot index it)")


def parse_point_times(text):
    if text == "none":
        return None
    mode, _, value = text.partition(":")
    if mode == "step":
        try:
            step = float(value)
        except ValueError:
            step = -1.0
        if not step > 0:
            raise InputError(f"--point_times={text}: step:SECONDS needs a positive number")
        return ("step", step)
    if mode == "field" and value:
        return ("field", value)
    raise InputError(f"--point_times={text}: expected none, step:SECONDS or field:NAME")


def parse_args(argv):
    parser = argparse.ArgumentParser(
        prog="mlndt_bag.py", description=__doc__.split("\n\n")[0],
        epilog="\n\n".join(__doc__.split("\n\n")[1:]),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scans", nargs="+", metavar="SCAN_OR_FOLDER")
    parser.add_argument("--output", required=True, help="the bag to write")
    parser.add_argument("--topic", default="/points", help="topic of the clouds (default /points)")
    parser.add_argument("--frame_id", default="lidar", help="header.frame_id (default lidar)")
    parser.add_argument("--times", default="", help="stamps file, one stamp [s] per scan")
    parser.add_argument("--rate", type=float, default=None, help="scans per second (without --times)")
    parser.add_argument("--start", type=float, default=1.0,
                        help="first stamp with --rate [s] (default 1; > 0)")
    parser.add_argument("--point_times", default="none",
                        help="none | step:SECONDS | field:NAME (per-point time field 'time')")
    parser.add_argument("--max_scans", type=int, default=0, help="only the first N scans (0 = all)")
    parser.add_argument("--force", action="store_true", help="replace an existing --output")
    return parser.parse_args(argv)


def check_inputs(args):
    """Everything refused before any work: (scans, stamps, point_times)."""
    if bool(args.times) == (args.rate is not None):
        raise InputError("give --times=FILE or --rate=HZ (one of them)")
    if args.max_scans < 0:
        raise InputError("--max_scans must be >= 0")
    if os.path.exists(args.output) and not args.force:
        raise InputError(f"--output={args.output} exists (give --force to replace it)")
    point_times = parse_point_times(args.point_times)
    scans = list_scans(args.scans)
    args.given_scans = len(scans)
    if args.max_scans > 0:
        scans = scans[:args.max_scans]
    stamps = stamps_for(args, len(scans))
    check_stamps(stamps)
    for path in scans:
        try:
            check_scan(path, point_times)
        except OSError as e:
            raise InputError(f"{path}: {e}")
    return scans, stamps, point_times


def write_bag(args, scans, stamps, point_times):
    import rosbag
    import rospy
    temporary = f"{args.output}.tmp-{os.getpid()}"
    try:
        with rosbag.Bag(temporary, "w") as bag:
            previous = None
            for k, (path, stamp) in enumerate(zip(scans, stamps)):
                points = read_scan(path)
                if len(points) == 0:
                    print(f"mlndt_bag: warning: {path} has no points (an empty cloud)",
                          file=sys.stderr)
                if previous is not None and not stamp > previous:
                    print(f"mlndt_bag: warning: stamp {k} ({stamp!r}) is not after the one "
                          f"before ({previous!r})", file=sys.stderr)
                previous = stamp
                msg = make_message(points, stamp, args.frame_id, point_times,
                                   point_times[1] if point_times else None)
                bag.write(args.topic, msg, rospy.Time.from_sec(stamp))
        os.replace(temporary, args.output)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def main(argv):
    args = parse_args(argv)
    try:
        scans, stamps, point_times = check_inputs(args)
    except InputError as e:
        print(f"mlndt_bag: {e}", file=sys.stderr)
        return EXIT_USAGE
    try:
        import rosbag  # noqa: F401  (Debian's python3-rosbag)
        from sensor_msgs.msg import PointCloud2  # noqa: F401
    except ImportError as e:
        print(f"mlndt_bag: {e} (install python3-rosbag and python3-sensor-msgs; run with "
              "/usr/bin/python3)", file=sys.stderr)
        return EXIT_FAILURE
    try:
        write_bag(args, scans, stamps, point_times)
    except (InputError, OSError, ValueError) as e:
        print(f"mlndt_bag: writing {args.output} failed: {e}", file=sys.stderr)
        return EXIT_FAILURE
    print(f"mlndt_bag: {args.output}: {len(scans)} clouds on {args.topic}, stamps "
          f"{stamps[0]:.6f} .. {stamps[-1]:.6f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
