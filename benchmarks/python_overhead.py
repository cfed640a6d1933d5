#!/usr/bin/env python3
"""What registering through Python costs over mlndt_align, on one pair.

    PYTHONPATH=build/python /usr/bin/python3 benchmarks/python_overhead.py [--repetitions 21]
        [--reference A.pcd --input B.pcd] [--tool build/tools/mlndt_align] [-- TOOL FLAGS...]

Each repetition, in turn:
  tool    mlndt_align in a new process: its in-process time, registration.time_ms.total of
          its JSON (map, sampling and solve: what mlndt::Register measures);
  cold    a new Python process that reads the clouds with mlndt.read_cloud
          and times mlndt.register(reference, input) with perf_counter: the
          wall time of the Python call (options, array conversion, the
          library, the result object), the first call of the process as the
          tool's is;
  warm    the same call in this process (after the first repetition).
Printed: the medians, and cold / tool - 1 (the figure the issue bounds at
5 %), and, per call, the wall time of the Python call minus the library's own
total_time_s of that same call (the binding's share, immune to machine
noise between calls).
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import mlndt

ROOT = Path(__file__).resolve().parents[1]

COLD = """
import json, sys, time, mlndt
reference = mlndt.read_cloud(sys.argv[1])
input = mlndt.read_cloud(sys.argv[2])
start = time.perf_counter()
result = mlndt.register(reference, input)
wall = time.perf_counter() - start
print(json.dumps({"wall_s": wall, "library_s": result.total_time_s, "termination": result.termination_type}))
"""


def run_tool(tool, reference, input, flags, output):
    command = [str(tool), f"--reference={reference}", f"--input={input}", f"--output_json={output}", *flags]
    completed = subprocess.run(command, capture_output=True, text=True)
    if not Path(output).exists():
        raise SystemExit(f"python_overhead.py: {tool} failed: {completed.stderr}")
    return json.loads(Path(output).read_text())["registration"]["total_time_s"]


def run_cold(reference, input):
    completed = subprocess.run(
        [sys.executable, "-c", COLD, str(reference), str(input)], capture_output=True, text=True, env=os.environ
    )
    if completed.returncode != 0:
        raise SystemExit(f"python_overhead.py: the Python run failed: {completed.stderr}")
    return json.loads(completed.stdout)


def ms(seconds):
    return f"{seconds * 1e3:7.2f} ms"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repetitions", type=int, default=21)
    parser.add_argument("--reference", default=str(ROOT / "data" / "koide3" / "251370668.pcd"))
    parser.add_argument("--input", default=str(ROOT / "data" / "koide3" / "251371071.pcd"))
    parser.add_argument("--tool", default=str(ROOT / "build" / "tools" / "mlndt_align"))
    parser.add_argument("tool_flags", nargs="*", help="more mlndt_align flags (default options otherwise)")
    args = parser.parse_args()
    if args.tool_flags:
        raise SystemExit("python_overhead.py: the Python side runs the default options; give no tool flags")

    reference, input = mlndt.read_cloud(args.reference), mlndt.read_cloud(args.input)
    tool_s, cold_s, warm_s, binding_cold_s, binding_warm_s = [], [], [], [], []
    with tempfile.TemporaryDirectory() as folder:
        output = Path(folder) / "align.json"
        for repetition in range(args.repetitions):
            tool_s.append(run_tool(args.tool, args.reference, args.input, args.tool_flags, output))
            cold = run_cold(args.reference, args.input)
            cold_s.append(cold["wall_s"])
            binding_cold_s.append(cold["wall_s"] - cold["library_s"])
            start = time.perf_counter()
            result = mlndt.register(reference, input)
            wall = time.perf_counter() - start
            if repetition > 0:  # The first in-process call is the cold one.
                warm_s.append(wall)
                binding_warm_s.append(wall - result.total_time_s)

    median = statistics.median
    print(f"pair: {args.reference} <- {args.input} ({len(reference)} / {len(input)} points)")
    print(f"{args.repetitions} repetitions, medians (min-max):")
    for name, values in [
        ("mlndt_align registration.time_ms.total", tool_s),
        ("Python, new process      ", cold_s),
        ("Python, same process     ", warm_s),
    ]:
        print(f"  {name}  {ms(median(values))}  ({ms(min(values)).strip()} - {ms(max(values)).strip()})")
    print(f"  binding's own time per call (wall - result.total_time_s): new process {ms(median(binding_cold_s))}, "
          f"same process {ms(median(binding_warm_s))}")
    overhead = median(cold_s) / median(tool_s) - 1.0
    print(f"overhead: Python (new process) / mlndt_align - 1 = {overhead * 100:+.1f} %")
    print(f"overhead: binding's own time / mlndt_align = {median(binding_cold_s) / median(tool_s) * 100:+.1f} %")


if __name__ == "__main__":
    main()
