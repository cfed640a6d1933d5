#!/usr/bin/env python3
"""Along-track bias of mlndt_suite runs on simulated sets (lab/records/bias.md).

  along_track.py SETS_DIR RUNS_CSV [RUNS_CSV ...]

For every right run on a constrained pair: the signed error along the true
motion, (t_estimate - t_true) . t_true / |t_true|, divided by |t_true|
(mlndt_suite's along_track_error_m over the motion length). Prints per
sensor x scene x start (and all starts) n, mean +- standard error [% of the
motion], the standard deviation and the mean motion [m]; one block per runs.csv (a label is its
parent folder's name).
"""
import collections
import csv
import json
import math
import os
import sys


def motions(sets):
    length, kind = {}, {}
    for name in os.listdir(sets):
        folder = os.path.join(sets, name)
        sim = json.load(open(os.path.join(folder, "simulation.json")))
        kind[name] = (sim["sensor"]["name"], sim["scene"]["kind"])
        pairs = json.load(open(os.path.join(folder, "reference_pairs.json")))
        for key, entry in pairs.items():
            t = entry["reference_from_input"]
            length[(name, key)] = math.sqrt(t[3] ** 2 + t[7] ** 2 + t[11] ** 2)
    return length, kind


def stats(values):
    n = len(values)
    if n == 0:
        return "n=  0"
    mean = sum(values) / n
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1)) if n > 1 else float("nan")
    return "n=%3d  %+.3f +- %.3f %% (sd %.3f)" % (n, mean, sd / math.sqrt(n), sd)


def main():
    sets, runs_files = sys.argv[1], sys.argv[2:]
    length, kind = motions(sets)
    for runs_file in runs_files:
        label = os.path.basename(os.path.dirname(os.path.abspath(runs_file)))
        cells = collections.defaultdict(list)
        steps = collections.defaultdict(list)
        wrong = collections.Counter()
        for run in csv.DictReader(open(runs_file)):
            key = (run["dataset"], run["pair"])
            sensor_scene = kind[run["dataset"]]
            if run["right"] != "1" or run["along_track_error_m"] in ("", "nan"):
                wrong[sensor_scene] += 1
                continue
            share = 100.0 * float(run["along_track_error_m"]) / length[key]
            for start in ("all", run["start_kind"]):
                cells[sensor_scene + (start,)].append(share)
                steps[sensor_scene + (start,)].append(length[key])
        print("== %s (%s)" % (label, runs_file))
        for key in sorted(cells):
            print("%-8s %-8s %-9s %s  (mean motion %.2f m)%s" % (
                key[0], key[1], key[2], stats(cells[key]),
                sum(steps[key]) / len(steps[key]),
                "  [%d not right]" % wrong[key[:2]] if key[2] == "all" and wrong[key[:2]] else ""))


if __name__ == "__main__":
    main()
