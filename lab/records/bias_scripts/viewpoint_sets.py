#!/usr/bin/env python3
"""Pairs whose reference map is seen from the input's viewpoint
(lab/records/bias.md).

  viewpoint_sets.py SETS_DIR MAP_SENSOR INPUT_SENSOR OUT_DIR

For each pair a_b of INPUT_SENSOR's sets that has a twin set of MAP_SENSOR
(same seed, scene and path): two sets of one pair each,
  <MAP>@input-<INPUT>_..._<seed>_<a>_<b>: scan 0 = MAP_SENSOR's scan b (seen
      from the input's pose) moved into frame a by the exact
      reference_from_input, scan 1 = INPUT_SENSOR's scan b;
  <MAP>@reference-<INPUT>_..._<seed>_<a>_<b>: scan 0 = MAP_SENSOR's scan a
      (seen from the reference pose, the control), scan 1 = the same input;
pair 0_1 with the original exact matrices. The map's points are the same
surfaces either way; only the viewpoint their sampling is centred on
differs. Binary PCDs with FIELDS x y z time ring (mlndt_simulate's).
"""
import json
import os
import struct
import sys


def read_pcd(path):
    data = open(path, "rb").read()
    end = data.index(b"DATA binary\n") + len(b"DATA binary\n")
    return data[:end], data[end:]


def moved_pcd(src, dst, twelve):
    header, body = read_pcd(src)
    out = bytearray(body)
    r = [twelve[0:3], twelve[4:7], twelve[8:11]]
    t = [twelve[3], twelve[7], twelve[11]]
    for off in range(0, len(body), 18):
        x, y, z = struct.unpack_from("<fff", body, off)
        struct.pack_into("<fff", out, off, *(
            r[i][0] * x + r[i][1] * y + r[i][2] * z + t[i] for i in range(3)))
    open(dst, "wb").write(header + bytes(out))


def write_set(dst, map_scan, input_scan, entry, sim, sensor, twelve=None):
    os.makedirs(os.path.join(dst, "pcd"), exist_ok=True)
    if twelve is None:
        link = os.path.join(dst, "pcd", "000000.pcd")
        if os.path.lexists(link):
            os.remove(link)
        os.symlink(os.path.abspath(map_scan), link)
    else:
        moved_pcd(map_scan, os.path.join(dst, "pcd", "000000.pcd"), twelve)
    link = os.path.join(dst, "pcd", "000001.pcd")
    if os.path.lexists(link):
        os.remove(link)
    os.symlink(os.path.abspath(input_scan), link)
    json.dump({"0_1": entry}, open(os.path.join(dst, "reference_pairs.json"), "w"), indent=1)
    open(os.path.join(dst, "times.txt"), "w").write("0\n0.1\n")
    sim = dict(sim)
    sim["sensor"] = dict(sim["sensor"], name=sensor)
    json.dump(sim, open(os.path.join(dst, "simulation.json"), "w"))


def main():
    sets, map_sensor, input_sensor, out = sys.argv[1:5]
    for name in sorted(os.listdir(sets)):
        if not name.startswith(input_sensor + "_") or name[len(input_sensor) + 1].isdigit():
            continue
        rest = name[len(input_sensor):]
        twin = os.path.join(sets, map_sensor + rest)
        if not os.path.isdir(twin):
            continue
        sim = json.load(open(os.path.join(sets, name, "simulation.json")))
        pairs = json.load(open(os.path.join(sets, name, "reference_pairs.json")))
        for key, entry in pairs.items():
            a, b = (int(v) for v in key.split("_"))
            scan = lambda folder, k: os.path.join(folder, "pcd", "%06d.pcd" % k)
            tag = "%s_%d_%d" % (rest, a, b)
            write_set(os.path.join(out, map_sensor + "@input-" + input_sensor + tag),
                      scan(twin, b), scan(os.path.join(sets, name), b), entry, sim,
                      map_sensor + "@input-" + input_sensor, entry["reference_from_input"])
            write_set(os.path.join(out, map_sensor + "@reference-" + input_sensor + tag),
                      scan(twin, a), scan(os.path.join(sets, name), b), entry, sim,
                      map_sensor + "@reference-" + input_sensor)


if __name__ == "__main__":
    main()
