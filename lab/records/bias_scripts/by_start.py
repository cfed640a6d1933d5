#!/usr/bin/env python3
"""Along-track error per sensor and start (offset) of one runs.csv, in mm
and % of the motion (lab/records/bias.md).

  by_start.py SETS_DIR RUNS_CSV
"""
import collections
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from along_track import motions  # noqa: E402


def main():
    sets, runs = sys.argv[1:3]
    length, kind = motions(sets)
    groups = collections.defaultdict(list)
    for r in csv.DictReader(open(runs)):
        if r["right"] != "1":
            continue
        along = float(r["along_track_error_m"])
        groups[(kind[r["dataset"]][0], r["start"])].append(
            (1000 * along, 100 * along / length[(r["dataset"], r["pair"])]))
    for key in sorted(groups):
        v = groups[key]
        n = len(v)
        mean = sum(a for a, _ in v) / n
        sd = math.sqrt(sum((a - mean) ** 2 for a, _ in v) / (n - 1)) if n > 1 else float("nan")
        print("%-8s %-10s n=%3d along-track %+.2f mm (sd %.2f mm), %+.3f %% of the motion" % (
            key[0], key[1], n, mean, sd, sum(b for _, b in v) / n))


if __name__ == "__main__":
    main()
