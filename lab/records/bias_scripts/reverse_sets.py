#!/usr/bin/env python3
"""Copies simulated sets with the scan order reversed (lab/records/bias.md).

  reverse_sets.py SETS_DIR OUT_DIR

Each set's scans are linked in reverse order (scan k becomes n-1-k) and each
pair a_b becomes (n-1-b)_(n-1-a) with the inverse reference_from_input and
prior_from_input: the same pairs registered the other way round (the
former input is now the reference). Poses are reversed too; stamps are kept
increasing. simulation.json is copied (sensor and scene).
"""
import json
import os
import shutil
import sys



def inverse(twelve):
    # [R t]^-1 = [R^T  -R^T t], row-major 3x4.
    r = [[twelve[4 * i + j] for j in range(3)] for i in range(3)]
    t = [twelve[4 * i + 3] for i in range(3)]
    out = []
    for i in range(3):
        row = [r[j][i] for j in range(3)]
        out += row + [-sum(row[j] * t[j] for j in range(3))]
    return out


def reverse(src, dst):
    scans = sorted(os.listdir(os.path.join(src, "pcd")))
    n = len(scans)
    os.makedirs(os.path.join(dst, "pcd"), exist_ok=True)
    for k, name in enumerate(scans):
        link = os.path.join(dst, "pcd", scans[n - 1 - k])
        if os.path.lexists(link):
            os.remove(link)
        os.symlink(os.path.abspath(os.path.join(src, "pcd", name)), link)
    pairs = json.load(open(os.path.join(src, "reference_pairs.json")))
    out = {}
    for key, entry in pairs.items():
        a, b = (int(v) for v in key.split("_"))
        entry = dict(entry)
        for field in ("reference_from_input", "prior_from_input"):
            if field in entry:
                entry[field] = inverse(entry[field])
        out["%d_%d" % (n - 1 - b, n - 1 - a)] = entry
    json.dump(out, open(os.path.join(dst, "reference_pairs.json"), "w"), indent=1)
    poses = open(os.path.join(src, "poses.txt")).read().splitlines()
    open(os.path.join(dst, "poses.txt"), "w").write("\n".join(poses[::-1]) + "\n")
    shutil.copy(os.path.join(src, "times.txt"), dst)
    shutil.copy(os.path.join(src, "simulation.json"), dst)


def main():
    src_dir, dst_dir = sys.argv[1], sys.argv[2]
    for name in sorted(os.listdir(src_dir)):
        reverse(os.path.join(src_dir, name), os.path.join(dst_dir, name))


if __name__ == "__main__":
    main()
