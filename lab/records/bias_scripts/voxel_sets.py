#!/usr/bin/env python3
"""Copies simulated sets with every scan replaced by its voxel centroids
(lab/records/bias.md): a data-side test of an area-uniform map and input.

  voxel_sets.py SETS_DIR OUT_DIR VOXEL_M [NAME_GLOB]

Each scan's points (sensor frame) are grouped in cubes of VOXEL_M and each
occupied cube becomes its centroid (time and ring of its first point), so
that where the pattern is denser than one point per cube the density per
surface area no longer depends on the distance to the sensor. Poses,
pairs and simulation.json are copied unchanged.
"""
import fnmatch
import json
import math
import os
import shutil
import struct
import sys


def voxelize(src, dst, voxel):
    data = open(src, "rb").read()
    end = data.index(b"DATA binary\n") + len(b"DATA binary\n")
    header, body = data[:end].decode(), data[end:]
    cubes = {}
    for off in range(0, len(body), 18):
        x, y, z = struct.unpack_from("<fff", body, off)
        key = (math.floor(x / voxel), math.floor(y / voxel), math.floor(z / voxel))
        c = cubes.get(key)
        if c is None:
            cubes[key] = [x, y, z, 1, body[off + 12:off + 18]]
        else:
            c[0] += x
            c[1] += y
            c[2] += z
            c[3] += 1
    out = bytearray()
    for x, y, z, n, rest in cubes.values():
        out += struct.pack("<fff", x / n, y / n, z / n) + rest
    n = len(cubes)
    lines = []
    for line in header.splitlines():
        if line.startswith("WIDTH"):
            line = "WIDTH %d" % n
        elif line.startswith("POINTS"):
            line = "POINTS %d" % n
        lines.append(line)
    open(dst, "wb").write(("\n".join(lines) + "\n").encode() + bytes(out))


def main():
    sets, out, voxel = sys.argv[1], sys.argv[2], float(sys.argv[3])
    glob = sys.argv[4] if len(sys.argv) > 4 else "*"
    for name in sorted(os.listdir(sets)):
        if not fnmatch.fnmatch(name, glob):
            continue
        src, dst = os.path.join(sets, name), os.path.join(out, name)
        os.makedirs(os.path.join(dst, "pcd"), exist_ok=True)
        for scan in sorted(os.listdir(os.path.join(src, "pcd"))):
            voxelize(os.path.join(src, "pcd", scan), os.path.join(dst, "pcd", scan), voxel)
        for f in ("poses.txt", "times.txt", "reference_pairs.json", "simulation.json"):
            shutil.copy(os.path.join(src, f), dst)


if __name__ == "__main__":
    main()
