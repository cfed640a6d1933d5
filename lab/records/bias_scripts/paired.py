#!/usr/bin/env python3
"""Paired difference of the along-track error between two variants on the
same pairs and starts (lab/records/bias.md).

  paired.py SETS_DIR BASE_RUNS_CSV VARIANT_RUNS_CSV [--reversed]

Per sensor: mean +- standard error of (variant - base) in % of the motion,
over the pairs right in both. With --reversed the variant ran on
reverse_sets.py's copies: its pair (n-1-b)_(n-1-a) is matched to a_b, and
the line also gives the mean of (variant + base) / 2 (the part of the error
both directions share: an estimate T_ba = T_ab^-1 gives variant = base) and
of (base - variant) / 2 (the part that changes sign with the roles).
"""
import collections
import csv
import math
import sys

sys.path.insert(0, __import__("os").path.dirname(__file__))
from along_track import motions  # noqa: E402


def load(path, length, n_scans, flip):
    out = {}
    for run in csv.DictReader(open(path)):
        if run["right"] != "1" or run["along_track_error_m"] in ("", "nan"):
            continue
        pair = run["pair"]
        if flip:
            a, b = (int(v) for v in pair.split("_"))
            pair = "%d_%d" % (n_scans - 1 - b, n_scans - 1 - a)
        share = 100.0 * float(run["along_track_error_m"]) / length[(run["dataset"], run["pair"])]
        out[(run["dataset"], pair, run["start_kind"])] = share
    return out


def mean_se(values):
    n = len(values)
    mean = sum(values) / n
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1)) if n > 1 else float("nan")
    return "%+.3f +- %.3f" % (mean, sd / math.sqrt(n))


def main():
    sets, base_path, variant_path = sys.argv[1:4]
    flip = "--reversed" in sys.argv[4:]
    length, kind = motions(sets)
    base = load(base_path, length, 4, False)
    variant = load(variant_path, length, 4, flip)
    groups = collections.defaultdict(list)
    for key, value in base.items():
        if key in variant:
            groups[kind[key[0]][0]].append((value, variant[key]))
    for sensor in sorted(groups):
        v = groups[sensor]
        line = "%-8s n=%3d  variant - base %s %%" % (sensor, len(v), mean_se([b - a for a, b in v]))
        if flip:
            line += "  shared (a+b)/2 %s %%  role (a-b)/2 %s %%" % (
                mean_se([(a + b) / 2 for a, b in v]), mean_se([(a - b) / 2 for a, b in v]))
        print(line)


if __name__ == "__main__":
    main()
