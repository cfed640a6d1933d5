#!/usr/bin/python3
"""Step-by-step check of an odometry trajectory against a reference.

  scripts/step_errors.py ESTIMATE.txt REFERENCE.txt [scans.csv]
                         [--max_m=0.2] [--max_deg=2]

Both files are KITTI poses, one per scan. For each step k-1 -> k the relative
motion of the estimate is compared with the reference's; a step off by more
than --max_m or --max_deg is counted, by the verdict of scan k in
mlndt_odometry's scans.csv when given (columns "termination_type",
"fallback"). This is how "no wrong pose reported as CONVERGENCE" is checked
on a sequence whose reference is good step to step (the Livox prior: ~2 cm).

With scans.csv a second count judges each scan with a registered pose
(fallback false) by its motion from the last such scan, so a scan right after a
fallback is judged by its own pose, not by the stand-in before it (as
tests/odometry/odometry_livox_test.cc scores); a local-map restart is a
declared discontinuity, and the scans after it are judged from it. The
scans off in that count are listed (verdict, error, the scan judged from).
"""
import csv
import sys
from collections import Counter

import numpy as np


def load(path):
    poses = []
    for row in np.loadtxt(path, ndmin=2):
        pose = np.eye(4)
        pose[:3, :] = row.reshape(3, 4)
        poses.append(pose)
    return poses


def step_error(a, b, c, d):
    """Error of the motion a -> b against the reference motion c -> d."""
    e = np.linalg.inv(np.linalg.inv(c) @ d) @ (np.linalg.inv(a) @ b)
    t = np.linalg.norm(e[:3, 3])
    angle = np.degrees(np.arccos(np.clip((np.trace(e[:3, :3]) - 1) / 2, -1, 1)))
    return t, angle


def count_from_last_pose(estimate, reference, rows, max_m, max_deg):
    counts = Counter()
    right_convergence = 0
    off = []
    last = 0
    for k in range(1, len(estimate)):
        if "the local map restarts" in rows[k]["message"]:
            last = k  # A declared discontinuity: judge from the new map on.
            continue
        if rows[k]["fallback"] == "true":
            continue
        t, a = step_error(estimate[last], estimate[k], reference[last], reference[k])
        if t > max_m or a > max_deg:
            counts[rows[k]["termination_type"]] += 1
            off.append(f"{k} ({rows[k]['termination_type']}, {t:.2f} m {a:.1f} deg from {last})")
        elif rows[k]["termination_type"] == "CONVERGENCE":
            right_convergence += 1
        last = k
    if off:
        print("off from the last registered pose: " + "; ".join(off))
    print(f"from the last registered pose: {sum(counts.values())} scans off; by "
          f"verdict: {dict(counts)}; CONVERGENCE and right: {right_convergence}")


def main(argv):
    options = dict(a[2:].split("=", 1) for a in argv if a.startswith("--"))
    files = [a for a in argv if not a.startswith("--")]
    if len(files) < 2:
        sys.exit(__doc__)
    max_m = float(options.get("max_m", 0.2))
    max_deg = float(options.get("max_deg", 2.0))
    estimate = load(files[0])
    reference = load(files[1])[: len(estimate)]
    rows = list(csv.DictReader(open(files[2]))) if len(files) > 2 else None
    counts = Counter()
    for k in range(1, len(estimate)):
        q = np.linalg.inv(reference[k - 1]) @ reference[k]
        p = np.linalg.inv(estimate[k - 1]) @ estimate[k]
        e = np.linalg.inv(q) @ p
        t = np.linalg.norm(e[:3, 3])
        a = np.degrees(np.arccos(np.clip((np.trace(e[:3, :3]) - 1) / 2, -1, 1)))
        if t > max_m or a > max_deg:
            verdict = rows[k]["termination_type"] if rows else "-"
            counts[verdict] += 1
            print(f"scan {k}: {t:.3f} m {a:.2f} deg off, verdict {verdict}")
    print(f"{sum(counts.values())} of {len(estimate) - 1} steps off by more than "
          f"{max_m} m or {max_deg} deg; by verdict: {dict(counts)}")
    if rows:
        count_from_last_pose(estimate, reference, rows, max_m, max_deg)


if __name__ == "__main__":
    main(sys.argv[1:])
