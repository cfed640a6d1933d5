#!/usr/bin/env python3
"""Writes a canonical text snapshot of what mlndt computes on the bundled data.

  scripts/behaviour_snapshot.py BUILD_DIR OUT.txt

Every line is one registration: the command's options, then the pose (12
numbers of the row-major 3x4), scores, iteration counts and termination, all
printed to 10 significant digits; times are left out. Run it on two builds
and diff the files: a refactor that claims "no behaviour change" must give
identical snapshots. Uses only the bundled data in data/.
"""

import csv
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
KOIDE = [os.path.join(ROOT, "data/koide3/251370668.pcd"), os.path.join(ROOT, "data/koide3/251371071.pcd")]
KITTI = os.path.join(ROOT, "data/kitti/pcd")
KITTI_POSES = os.path.join(ROOT, "data/kitti/poses_velo.txt")


def g(value):
    return "%.10g" % value


def align(build, flags):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "r.json")
        cmd = [os.path.join(build, "tools/mlndt_align"), "--output_json=" + out] + flags
        proc = subprocess.run(cmd, capture_output=True, text=True)
        if not os.path.exists(out):
            return "exit %d, no json" % proc.returncode
        # docs/json_schema.md: the registration's result is one object.
        d = json.load(open(out))["registration"]
    pose = [v for row in d["reference_from_input"][:3] for v in row]
    # The covariance of xi in m and rad (RegistrationSummary's units).
    cov = d["covariance"]
    # JSON null: not finite (an unconstrained direction, docs/json_schema.md).
    cov_diag = [math.inf if cov[i][i] is None else cov[i][i] for i in range(6)]
    fields = [
        d["termination_type"],
        "iters=%d" % d["num_iterations"],
        "per_layer=" + ",".join(str(i) for i in d.get("iterations_per_layer", [])),
        "start=%s" % d.get("start_layer"),
        "layers=%s" % d.get("num_layers"),
        "score=" + g(d["initial_score"]) + "->" + g(d["final_score"]),
        "sampled=%d matched=%d" % (d["sampled_points"], d["matched_points"]),
        "pose=" + " ".join(g(v) for v in pose),
        "cov_diag=" + " ".join(g(v) for v in cov_diag),
        "trace_scores=" + " ".join(g(r["score"]) for r in d["trace"]),
    ]
    return " | ".join(fields)


def sequence(build, flags):
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [os.path.join(build, "tools/mlndt_sequence"), "--scans=" + KITTI, "--gt_poses=" + KITTI_POSES,
               "--output_dir=" + tmp, "--plots=false"] + flags
        proc = subprocess.run(cmd, capture_output=True, text=True)
        path = os.path.join(tmp, "pairs.csv")
        if not os.path.exists(path):
            return ["exit %d, no pairs.csv" % proc.returncode]
        lines = []
        for row in csv.DictReader(open(path)):
            keep = [row["reference"], row["input"], row["termination"], "iters=" + row["iterations"],
                    "start=" + row["start_layer"], "guess_failed=" + row["guess_check_failed"]]
            keep += [g(float(row[k])) for k in ("est_tx_m", "est_ty_m", "est_tz_m", "est_alpha_deg",
                                               "est_beta_deg", "est_gamma_deg", "translation_error_cm")]
            lines.append(" ".join(keep))
        return lines


def main():
    build, out_path = sys.argv[1], sys.argv[2]
    kitti = lambda i: os.path.join(KITTI, "%06d.pcd" % i)
    pair_koide = ["--reference=" + KOIDE[0], "--input=" + KOIDE[1]]
    runs = []
    for backend in ("ceres", "newton", "lm"):
        runs.append(pair_koide + ["--backend=" + backend])
        runs.append(["--reference=" + kitti(0), "--input=" + kitti(1), "--backend=" + backend])
        runs.append(["--reference=" + kitti(2), "--input=" + kitti(5), "--backend=" + backend,
                     "--initial_guess=5,3,0,0,0,30"])
    runs += [
        pair_koide + ["--loss=none"],
        pair_koide + ["--loss=huber", "--loss_scale=2"],
        pair_koide + ["--unmatched_policy=zero_residual"],
        pair_koide + ["--sampling=random", "--seed=7"],
        pair_koide + ["--sampling=voxel_centroid"],
        pair_koide + ["--start_layer=2", "--iterations_per_layer=3", "--max_coarse_point_stride=1"],
        pair_koide + ["--finest_cell_size_m=0", "--num_layers=4"],
        pair_koide + ["--finest_cell_size_m=1", "--backend=lm"],
        pair_koide + ["--trust_region_strategy_type=dogleg"],
        pair_koide + ["--method=ndt"],
        pair_koide + ["--method=ndt", "--ndt_cell_size_m=2"],
        pair_koide + ["--method=ndt", "--ndt_cell_size_m=1", "--ndt_neighbors=direct7"],
        ["--reference=" + kitti(0), "--input=" + kitti(1), "--method=ndt", "--ndt_cell_size_m=2"],
        ["--reference=" + kitti(3), "--input=" + kitti(4), "--method=ndt"],
        ["--reference=" + kitti(0), "--input=" + kitti(3), "--initial_guess=10,0,0,0,0,0"],
        ["--reference=" + kitti(4), "--input=" + kitti(6), "--initial_guess=0,0,0,0,0,45", "--backend=lm"],
    ]
    lines = []
    for flags in runs:
        shown = [f.replace(ROOT + "/", "") for f in flags]
        lines.append("align " + " ".join(shown) + " :: " + align(build, flags))
    for flags in (["--step=1", "--init=zero"], ["--step=2", "--init=constant_velocity"],
                  ["--step=1", "--init=gt_fraction:0.5", "--backend=newton"],
                  ["--step=1", "--init=zero", "--adaptive_start_layer"],
                  ["--step=1", "--method=ndt", "--ndt_cell_size_m=2"]):
        for line in sequence(build, flags):
            lines.append("sequence " + " ".join(flags) + " :: " + line)
    with open(out_path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("behaviour_snapshot: %d lines -> %s" % (len(lines), out_path))


if __name__ == "__main__":
    main()
