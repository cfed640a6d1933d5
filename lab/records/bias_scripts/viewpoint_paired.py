#!/usr/bin/env python3
"""Paired difference, map seen from the input's viewpoint minus map seen
from the reference's, over viewpoint_sets.py's sets (lab/records/bias.md).

  viewpoint_paired.py SETS_DIR RUNS_CSV
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
    length, _ = motions(sets)
    share = {}
    for r in csv.DictReader(open(runs)):
        if r["right"] == "1":
            share[r["dataset"]] = 100 * float(r["along_track_error_m"]) / length[(r["dataset"], r["pair"])]
    diffs = collections.defaultdict(list)
    for name, value in share.items():
        if "@input-" not in name:
            continue
        control = name.replace("@input-", "@reference-")
        if control in share:
            diffs[name.split("_street")[0].replace("@input", "")].append(value - share[control])
    for key in sorted(diffs):
        d = diffs[key]
        n = len(d)
        mean = sum(d) / n
        sd = math.sqrt(sum((v - mean) ** 2 for v in d) / (n - 1))
        print("%-16s n=%3d  input viewpoint - reference viewpoint %+.3f +- %.3f %% of the motion" % (
            key, n, mean, sd / math.sqrt(n)))


if __name__ == "__main__":
    main()
