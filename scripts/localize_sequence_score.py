#!/usr/bin/env python3
"""Scores an mlndt_localize run against reference poses, scan by scan.

  scripts/localize_sequence_score.py OUTPUT_DIR REFERENCE_KITTI [TOL_M TOL_DEG]

OUTPUT_DIR is mlndt_localize's --output_dir (scans.csv: each scan's verdict
and its registration's pose). A scan is right when the registration's pose
is within TOL_M (default 0.2 m) and TOL_DEG (1 deg) of its reference pose
(line k of REFERENCE_KITTI for scan k). Prints the scans by verdict, right
and wrong.
"""
import csv
import math
import sys



def kitti(path):
    """3x4 row-major matrices, one a line."""
    return [[float(x) for x in line.split()] for line in open(path)
            if len(line.split()) == 12]


def error(reference, pose):
    """Translation [m] and rotation angle [deg] between two 3x4 poses."""
    t = math.sqrt(sum((reference[4 * i + 3] - pose[4 * i + 3]) ** 2
                      for i in range(3)))
    # trace(R_ref^T R) = sum of the element-wise products.
    trace = sum(reference[4 * i + j] * pose[4 * i + j]
                for i in range(3) for j in range(3))
    r = math.degrees(math.acos(max(-1.0, min(1.0, (trace - 1) / 2))))
    return t, r


def main():
    out, ref_path = sys.argv[1], sys.argv[2]
    tol_m = float(sys.argv[3]) if len(sys.argv) > 3 else 0.2
    tol_deg = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0
    reference = kitti(ref_path)
    counts = {}
    usable_right = 0
    rows = list(csv.DictReader(open(out + "/scans.csv")))
    for row in rows:
        k = int(row["index"])
        pose = [float(x) for x in
                row["registration.reference_from_input"].split()][:12]
        t, r = error(reference[k], pose)
        right = t < tol_m and r < tol_deg
        verdict = row["registration.termination_type"]
        key = (verdict, "right" if right else "wrong")
        counts[key] = counts.get(key, 0) + 1
        if right and verdict in ("CONVERGENCE", "NO_CONVERGENCE"):
            usable_right += 1
    print("scans %d, usable and right %d (tolerance %.2f m / %.1f deg)" %
          (len(rows), usable_right, tol_m, tol_deg))
    for key in sorted(counts):
        print("  %-15s %-5s %d" % (key[0], key[1], counts[key]))


if __name__ == "__main__":
    main()
