#!/usr/bin/env python3
"""Along-track error per data set (one scene and path), averaged over its
pairs and the given start, per sensor: the spread of scene means
(lab/records/bias.md).

  per_scene.py SETS_DIR RUNS_CSV [START_KIND]
"""
import collections
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from along_track import motions  # noqa: E402


def main():
    sets, runs = sys.argv[1:3]
    start = sys.argv[3] if len(sys.argv) > 3 else "prior"
    length, kind = motions(sets)
    scenes = collections.defaultdict(list)
    for r in csv.DictReader(open(runs)):
        if r["right"] != "1" or r["start_kind"] != start:
            continue
        scenes[r["dataset"]].append(100 * float(r["along_track_error_m"]) / length[(r["dataset"], r["pair"])])
    by_sensor = collections.defaultdict(list)
    for name, values in scenes.items():
        by_sensor[kind[name][0]].append(sum(values) / len(values))
    for sensor in sorted(by_sensor):
        means = sorted(by_sensor[sensor])
        print("%-8s %2d scenes: scene means from %+.2f to %+.2f %%; |mean| >= 0.3 %% in %d" % (
            sensor, len(means), means[0], means[-1], sum(1 for m in means if abs(m) >= 0.3)))


if __name__ == "__main__":
    main()
