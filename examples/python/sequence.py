#!/usr/bin/env python3
"""Registers every scan of a folder onto the one before it and writes the
trajectory in the KITTI format.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/sequence.py SCANS_FOLDER \
        [--output trajectory.txt] [--preset default|paper] [--initial-uncertainty metres,degrees]

Scans are the folder's cloud files (.pcd, .ply, .bin, .3d, .xyz, .txt) in
name order. Each scan's map is built once (LayeredMap, from its
range-filtered points) and the next scan is registered onto it from a
constant-velocity guess: the motion of the pair before. A pair whose result
is not usable keeps the guess (dead reckoning) and says so on stderr.

The trajectory has one line per scan: the 12 numbers of the row-major 3x4
world_from_scan, with the first scan as the world (the scans' own frame, e.g.
the Velodyne frame for KITTI .bin files, not KITTI's camera frame).
Without a folder it runs the KITTI 00 frames 0-7 bundled in data/kitti/pcd.
"""

import argparse
import sys
import time
from pathlib import Path

import numpy as np

import mlndt

BUNDLED = Path(__file__).resolve().parents[2] / "data" / "kitti" / "pcd"
EXTENSIONS = {".pcd", ".ply", ".bin", ".3d", ".xyz", ".txt"}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scans", nargs="?", default=str(BUNDLED))
    parser.add_argument("--output", default="trajectory.txt")
    parser.add_argument("--preset", default="default", choices=["default", "paper"])
    parser.add_argument("--initial-uncertainty", help="how far a constant-velocity guess may be off: metres,degrees")
    args = parser.parse_args()

    paths = sorted(p for p in Path(args.scans).iterdir() if p.suffix.lower() in EXTENSIONS)
    if len(paths) < 2:
        raise SystemExit(f"sequence.py: {args.scans} holds {len(paths)} scans; need at least 2")
    uncertainty = [float(v) for v in args.initial_uncertainty.split(",")] if args.initial_uncertainty else None

    world_from_scan = [np.eye(4)]
    previous_from_current = np.eye(4)  # The constant-velocity guess.
    reference_map = mlndt.LayeredMap.build(mlndt.filter_range(mlndt.read_cloud(paths[0])))
    for k in range(1, len(paths)):
        scan = mlndt.read_cloud(paths[k])
        start = time.perf_counter()
        result = reference_map.register(
            scan, initial=previous_from_current, initial_uncertainty=uncertainty, preset=args.preset
        )
        elapsed_ms = (time.perf_counter() - start) * 1e3
        if result.usable:
            previous_from_current = result.reference_from_input
        else:
            print(f"sequence.py: {paths[k].name}: {result.termination_type}: {result.message}; keeping the guess", file=sys.stderr)
        world_from_scan.append(world_from_scan[-1] @ previous_from_current)
        t = previous_from_current[:3, 3]
        print(
            f"{paths[k - 1].name} <- {paths[k].name}: {result.termination_type:14s} {result.num_iterations:3d} iterations "
            f"{elapsed_ms:6.1f} ms  t = ({t[0]:.3f}, {t[1]:.3f}, {t[2]:.3f}) m"
        )
        reference_map = mlndt.LayeredMap.build(mlndt.filter_range(scan))

    with open(args.output, "w") as out:
        for pose in world_from_scan:
            out.write(" ".join(f"{v:.9e}" for v in pose[:3].ravel()) + "\n")
    print(f"trajectory of {len(world_from_scan)} scans written to {args.output}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (OSError, ValueError) as error:  # The library's message names the file or option.
        sys.exit(f"sequence.py: {error}")
