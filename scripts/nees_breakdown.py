#!/usr/bin/python3
"""Why a data set's NEES is far from 6: per pair of a reference_pairs.json,
registered from its prior as mlndt_bench --starts=prior does (default
options), the error e against the reference (pose vector of Eq. 11: t [m],
Euler angles [rad]) and the weighted covariance P / w
(w = kCalibratedPairInformationScale, 0.055), with

  nees      e^T (P/w)^-1 e (mlndt_bench's NEES times w);
  top       the share of it along the covariance's least certain...most
            certain eigen-directions: the largest single share, and what
            that direction is made of (translation vs rotation);
  sigma     the predicted 1-sigma translation [cm] and rotation [deg] (the
            square roots of the largest eigenvalues of the two 3x3 blocks);
  spread    the reference's own uncertainty (reference_pairs.json spread_m,
            spread_deg: the largest distance of its five registrations from
            their consensus);
  nees_ref  e^T (P/w + R)^-1 e with R = diag(spread_m^2/3 x3,
            spread_rad^2/3 x3): the NEES when the reference's own error is
            counted (the spread taken as the 1-sigma length of its error).

    PYTHONPATH=build/python /usr/bin/python3 scripts/nees_breakdown.py \
        $MLNDT_DATA_DIR/3dtk_example_scans $MLNDT_DATA_DIR/koide3_velodyne_pair [--max_pairs 40]
"""

import argparse
import json
import re
from pathlib import Path

import numpy as np

import mlndt

W = 0.055
EXTENSIONS = {".pcd", ".ply", ".bin", ".3d", ".xyz", ".txt"}


def scan_file(folder, number):
    """The cloud file whose name holds `number` (as lab's FindScanFile)."""
    for directory in (folder / "pcd", folder):
        if not directory.is_dir():
            continue
        found = [
            p
            for p in sorted(directory.iterdir())
            if p.suffix in EXTENSIONS and [int(d) for d in re.findall(r"\d+", p.stem)][-1:] == [number]
        ]
        if found:
            return found[0]
    raise FileNotFoundError(f"{folder}: no scan numbered {number}")


def matrix(numbers):
    m = np.eye(4)
    m[:3, :] = np.array(numbers).reshape(3, 4)
    return m


def breakdown(folder, key, entry):
    i, j = (int(v) for v in key.split("_"))
    prior = matrix(entry["prior_from_input"])
    reference = matrix(entry["reference_from_input"])
    result = mlndt.register(mlndt.read_cloud(scan_file(folder, i)), mlndt.read_cloud(scan_file(folder, j)), prior)
    if not result.usable or not np.all(np.isfinite(result.covariance)):
        return None
    e = mlndt.xi_from_pose(result.reference_from_input) - mlndt.xi_from_pose(reference)
    p = result.covariance / W
    values, vectors = np.linalg.eigh(p)
    shares = (vectors.T @ e) ** 2 / values
    top = int(np.argmax(shares))
    spread = np.array([entry["spread_m"]] * 3 + [np.radians(entry["spread_deg"])] * 3) ** 2 / 3
    return {
        "pair": f"{folder.name} {key}",
        "err": (np.linalg.norm(e[:3]) * 100, np.degrees(np.linalg.norm(e[3:]))),
        "nees": float(e @ np.linalg.solve(p, e)),
        "top_share": shares[top] / shares.sum(),
        "top_rotation": float(np.sum(vectors[3:, top] ** 2)),
        "sigma": (np.sqrt(np.linalg.eigvalsh(p[:3, :3])[-1]) * 100, np.degrees(np.sqrt(np.linalg.eigvalsh(p[3:, 3:])[-1]))),
        "spread": (entry["spread_m"] * 100, entry["spread_deg"]),
        "nees_ref": float(e @ np.linalg.solve(p + np.diag(spread), e)),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folders", nargs="+", type=Path)
    parser.add_argument("--max_pairs", type=int, default=40)
    arguments = parser.parse_args()
    print("| pair | error [cm / deg] | NEES (w = 0.055) | largest share (its rotation part) | predicted sigma [cm / deg] | reference spread [cm / deg] | NEES with the reference's spread |")
    print("|---|---|---|---|---|---|---|")
    for folder in arguments.folders:
        pairs = json.loads((folder / "reference_pairs.json").read_text())
        rows = []
        for key, entry in list(pairs.items())[: arguments.max_pairs]:
            if "prior_from_input" not in entry or "spread_m" not in entry:
                continue
            row = breakdown(folder, key, entry)
            if row is None:
                print(f"| {folder.name} {key} | not usable | | | | | |")
                continue
            rows.append(row)
            if len(pairs) <= 3:
                print(
                    f"| {row['pair']} | {row['err'][0]:.2f} / {row['err'][1]:.3f} | {row['nees']:.1f} | "
                    f"{row['top_share']:.2f} ({row['top_rotation']:.2f}) | {row['sigma'][0]:.2f} / {row['sigma'][1]:.3f} | "
                    f"{row['spread'][0]:.2f} / {row['spread'][1]:.3f} | {row['nees_ref']:.1f} |"
                )
        if rows:
            mean = lambda k: np.mean([r[k] for r in rows])  # noqa: E731
            print(
                f"| **{folder.name}, mean of {len(rows)}** | {np.mean([r['err'][0] for r in rows]):.2f} / "
                f"{np.mean([r['err'][1] for r in rows]):.3f} | {mean('nees'):.1f} | {mean('top_share'):.2f} "
                f"({mean('top_rotation'):.2f}) | {np.mean([r['sigma'][0] for r in rows]):.2f} / "
                f"{np.mean([r['sigma'][1] for r in rows]):.3f} | {np.mean([r['spread'][0] for r in rows]):.2f} / "
                f"{np.mean([r['spread'][1] for r in rows]):.3f} | {mean('nees_ref'):.1f} |",
                flush=True,
            )


if __name__ == "__main__":
    main()
