#!/usr/bin/env python3
"""Aligns two point-cloud files with ML-NDT and prints the 4x4 transform.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/align.py REFERENCE INPUT \
        [--initial-guess tx,ty,tz,alpha,beta,gamma] [--initial-uncertainty metres,degrees] \
        [--preset default|paper] [--backend ceres|newton|lm]

Without files it aligns the koide3 Velodyne pair bundled in data/. The matrix
maps input points into the reference frame (reference_from_input); the
library's report goes to stderr. Exits 1 when the result is not usable
(FAILURE, LOW_QUALITY, DEGENERATE).
"""

import argparse
import sys
from pathlib import Path

import numpy as np

import mlndt

BUNDLED = Path(__file__).resolve().parents[2] / "data" / "koide3"


def numbers(text, count, name):
    values = [float(v) for v in text.split(",")]
    if len(values) != count:
        raise SystemExit(f"align.py: {name} needs {count} comma-separated numbers")
    return values


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("reference", nargs="?", default=str(BUNDLED / "251370668.pcd"))
    parser.add_argument("input", nargs="?", default=str(BUNDLED / "251371071.pcd"))
    parser.add_argument("--initial-guess", help="tx,ty,tz,alpha,beta,gamma [m, deg], R = Rx Ry Rz")
    parser.add_argument("--initial-uncertainty", help="how far the guess may be off: metres,degrees")
    parser.add_argument("--preset", default="default", choices=["default", "paper"])
    parser.add_argument("--backend", help="ceres | newton | lm (default: the preset's)")
    args = parser.parse_args()

    reference = mlndt.read_cloud(args.reference)
    input = mlndt.read_cloud(args.input)
    initial = None
    if args.initial_guess:
        initial = mlndt.pose_from_xi(numbers(args.initial_guess, 6, "--initial-guess"), degrees=True)
    uncertainty = None
    if args.initial_uncertainty:
        uncertainty = numbers(args.initial_uncertainty, 2, "--initial-uncertainty")
    options = {"preset": args.preset}
    if args.backend:
        options["backend"] = {"type": args.backend}

    result = mlndt.register(reference, input, initial=initial, initial_uncertainty=uncertainty, **options)
    print(result.report(), file=sys.stderr, end="")
    print(f"{result.termination_type}: {result.message}")
    np.savetxt(sys.stdout, result.reference_from_input, fmt="%12.8f")
    return 0 if result.usable else 1


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (OSError, ValueError) as error:  # The library's message names the file or option.
        sys.exit(f"align.py: {error}")
