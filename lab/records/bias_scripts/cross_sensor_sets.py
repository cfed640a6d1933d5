#!/usr/bin/env python3
"""Pairs whose reference comes from one sensor and input from another
(lab/records/bias.md).

  cross_sensor_sets.py SETS_DIR REFERENCE_SENSOR INPUT_SENSOR OUT_DIR

Every sensor of a seed and scene travels the same path (docs/simulator.md),
so scan k of REFERENCE_SENSOR's set and scan k of INPUT_SENSOR's set share
a pose. For every set of REFERENCE_SENSOR with a twin of INPUT_SENSOR, a set
named <ref>-<input>_<scene>_<trajectory>_<seed> holds scans 2k (the
reference sensor's scan k) and 2k+1 (the input sensor's scan k) and, for
each pair a_b of the original, the pair (2a)_(2b+1) with the same exact
matrices. simulation.json is the reference sensor's with the sensor name
replaced by "<ref>-<input>".
"""
import json
import os
import sys


def main():
    sets, ref, inp, out = sys.argv[1:5]
    for name in sorted(os.listdir(sets)):
        if not name.startswith(ref + "_") or name[len(ref) + 1].isdigit():
            continue
        rest = name[len(ref):]
        twin = os.path.join(sets, inp + rest)
        if not os.path.isdir(twin):
            continue
        dst = os.path.join(out, ref + "-" + inp + rest)
        os.makedirs(os.path.join(dst, "pcd"), exist_ok=True)
        scans = sorted(os.listdir(os.path.join(sets, name, "pcd")))
        for k, scan in enumerate(scans):
            for index, folder in ((2 * k, os.path.join(sets, name)), (2 * k + 1, twin)):
                link = os.path.join(dst, "pcd", "%06d.pcd" % index)
                if os.path.lexists(link):
                    os.remove(link)
                os.symlink(os.path.abspath(os.path.join(folder, "pcd", scan)), link)
        pairs = json.load(open(os.path.join(sets, name, "reference_pairs.json")))
        out_pairs = {}
        for key, entry in pairs.items():
            a, b = (int(v) for v in key.split("_"))
            out_pairs["%d_%d" % (2 * a, 2 * b + 1)] = entry
        json.dump(out_pairs, open(os.path.join(dst, "reference_pairs.json"), "w"), indent=1)
        poses = open(os.path.join(sets, name, "poses.txt")).read().splitlines()
        open(os.path.join(dst, "poses.txt"), "w").write("\n".join(p for p in poses for _ in (0, 1)) + "\n")
        times = open(os.path.join(sets, name, "times.txt")).read().split()
        open(os.path.join(dst, "times.txt"), "w").write(
            "\n".join("%s\n%.9f" % (t, float(t) + 1e-6) for t in times) + "\n")
        sim = json.load(open(os.path.join(sets, name, "simulation.json")))
        sim["sensor"]["name"] = ref + "-" + inp
        json.dump(sim, open(os.path.join(dst, "simulation.json"), "w"))


if __name__ == "__main__":
    main()
