#!/usr/bin/env python3
"""Weak-geometry variants of a KITTI data set folder (issue 22).

For every pair i_j of SRC/reference_pairs.json the reference scan i is kept
whole and the input scan j is cropped four ways, each written as its own data
set folder under OUT, which mlndt_suite reads like any other:

  kitti_crop_ground  the ground only: z < -1.4 m (the sensor is 1.73 m up)
  kitti_crop_near    points within 8 m of the sensor
  kitti_crop_wedge   a +-15 deg wedge ahead (|atan2(y, x)| <= 15 deg)
  kitti_crop_thin    every 200th point

A cropped input is stored as scan 1000 + j (pcd/00100j.pcd), the pair as
"i_(1000+j)" with the source entry's reference and prior, so that the suite
registers the cropped input onto the whole reference. Reference scans are
symbolic links to SRC.

  scripts/make_kitti_crops.py ../shared/data/kitti00_frames_0000_0007 /tmp/crops
  build/lab/programs/mlndt_suite --data_dir=/tmp/crops \\
      --datasets=kitti_crop_ground,kitti_crop_near,kitti_crop_wedge,kitti_crop_thin \\
      --starts=identity,prior,perturbed
"""

import array
import json
import math
import os
import sys

CROPS = {
    "kitti_crop_ground": lambda k, p: p[2] < -1.4,
    "kitti_crop_near": lambda k, p: math.sqrt(p[0]**2 + p[1]**2 + p[2]**2) <= 8.0,
    "kitti_crop_wedge": lambda k, p: abs(math.degrees(math.atan2(p[1], p[0]))) <= 15.0,
    "kitti_crop_thin": lambda k, p: k % 200 == 0,
}
INPUT_OFFSET = 1000


def read_pcd_xyz(path):
    """x, y, z of a binary PCD whose fields are all 4-byte floats."""
    with open(path, "rb") as f:
        header = {}
        while True:
            line = f.readline().decode("ascii").strip()
            key, _, value = line.partition(" ")
            header[key] = value.split()
            if key == "DATA":
                break
        if header["DATA"] != ["binary"] or set(header["TYPE"]) != {"F"}:
            sys.exit(f"{path}: only binary all-float PCD files are read here")
        fields = header["FIELDS"]
        count = int(header["POINTS"][0])
        values = array.array("f")
        values.fromfile(f, count * len(fields))
    ix, iy, iz = (fields.index(a) for a in "xyz")
    stride = len(fields)
    return [(values[k * stride + ix], values[k * stride + iy], values[k * stride + iz])
            for k in range(count)]


def write_pcd_xyz(path, points):
    header = ("# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\n"
              "SIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
              f"WIDTH {len(points)}\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
              f"POINTS {len(points)}\nDATA binary\n")
    values = array.array("f", [c for p in points for c in p])
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        values.tofile(f)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    src, out = sys.argv[1], sys.argv[2]
    with open(os.path.join(src, "reference_pairs.json")) as f:
        pairs = json.load(f)
    scans = {}
    for name, keep in CROPS.items():
        pcd = os.path.join(out, name, "pcd")
        os.makedirs(pcd, exist_ok=True)
        cropped_pairs = {}
        for key, entry in pairs.items():
            i, j = (int(s) for s in key.split("_"))
            link = os.path.join(pcd, f"{i:06d}.pcd")
            if not os.path.lexists(link):
                os.symlink(os.path.abspath(os.path.join(src, "pcd", f"{i:06d}.pcd")), link)
            if j not in scans:
                scans[j] = read_pcd_xyz(os.path.join(src, "pcd", f"{j:06d}.pcd"))
            kept = [p for k, p in enumerate(scans[j]) if keep(k, p)]
            write_pcd_xyz(os.path.join(pcd, f"{INPUT_OFFSET + j:06d}.pcd"), kept)
            cropped_pairs[f"{i}_{INPUT_OFFSET + j}"] = entry
        with open(os.path.join(out, name, "reference_pairs.json"), "w") as f:
            json.dump(cropped_pairs, f, indent=1)
        print(f"{name}: {len(cropped_pairs)} pairs")


if __name__ == "__main__":
    main()
