#!/usr/bin/env python3
"""Where one registration's CPU time goes, as shares of mlndt::Register.

  scripts/profile_shares.py [--runs=N] [--perf=perf] -- MLNDT_ALIGN REF IN [flags]

Runs the mlndt_align command N times (default 10) under `perf record
--call-graph dwarf` and prints, for each part of a registration, the share
of the CPU samples inside mlndt::Register that fall in it (a function and
everything it calls; perf report --children). The shares come from samples
of this process only, so they hold on a loaded machine where times do not.
Parts whose functions a revision does not have show as "-".

Then it runs the command up to 5 times with --output_json and splits the solve
by layer stage from the trace's per-iteration times (the guess check and
the yaw retries are the solve's time after the last traced iteration).
Exit 1 when perf or the command fails.
"""

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

# Label, then the symbols whose inclusive share it is (first one found).
PARTS = [
    ("map: range filter of the reference", ["mlndt::internal::FilterReference"]),
    ("map: layered grid build", ["mlndt::LayeredGrid::Build"]),
    ("sampling (range filter + GBS)", ["mlndt::internal::SampleInput"]),
    ("solve: all attempts", ["mlndt::internal::SolveAttempts"]),
    ("solve: layer schedules", ["mlndt::RunLayerSchedule"]),
    ("solve: Ceres Solver::Solve", ["ceres::Solver::Solve"]),
    ("solve: residual blocks (Ceres)", ["ceres::internal::ResidualBlock::Evaluate"]),
    ("solve: cell lookup (MatchCell)", ["mlndt::MatchCell"]),
    ("verdict (JudgeSolution)", ["mlndt::JudgeSolution"]),
    ("final score and Hessian", ["mlndt::EvaluateScore"]),
]


def perf_shares(perf, command, runs, workdir):
    data = os.path.join(workdir, "perf.data")
    script = os.path.join(workdir, "runs.sh")
    with open(script, "w") as f:
        for _ in range(runs):
            f.write(" ".join(f"'{a}'" for a in command) + " > /dev/null 2>&1\n")
    subprocess.run([perf, "record", "-q", "--call-graph", "dwarf,16384", "-o",
                    data, "--", "bash", script], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    report = subprocess.run(
        [perf, "report", "-i", data, "--children", "--stdio", "-g", "none",
         "--percent-limit", "0.01", "--comm", os.path.basename(command[0])],
        check=True, capture_output=True, text=True).stdout
    children = {}
    for line in report.splitlines():
        m = re.match(r"\s*([\d.]+)%\s+[\d.]+%.*?\[\.\]\s+(.*)$", line)
        if m:
            name = m.group(2).strip()
            children.setdefault(name, float(m.group(1)))
    return children


def find(children, symbols):
    for symbol in symbols:
        for name, share in children.items():
            if name == symbol or name.startswith(symbol + "("):
                return share
    return None


def stage_times(command, workdir):
    """One run's solve time [ms], its time per layer stage and after them."""
    out = os.path.join(workdir, "result.json")
    subprocess.run(command + [f"--output_json={out}"], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    registration = json.load(open(out))["registration"]
    # Trace times count from the registration's start: the solve starts
    # after the map and the sampling.
    # (RegistrationSummary's fields, in seconds; reported in ms.)
    ms = {k: registration[k + "_time_s"] * 1e3 for k in ("map", "sampling", "solve", "total")}
    per_stage, previous = {}, ms["map"] + ms["sampling"]
    for record in registration["trace"]:
        layer = f"layer {record['layer']}"
        per_stage[layer] = per_stage.get(layer, 0.0) + record["time_s"] * 1e3 - previous
        previous = record["time_s"] * 1e3
    per_stage["after the reported attempt (guess check, retries, verdict)"] = (
        ms["total"] - previous)
    return ms["solve"], per_stage


def main():
    parser = argparse.ArgumentParser(usage=__doc__)
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--perf", default="perf")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = [a for a in args.command if a != "--"]
    if not command or args.runs < 1:
        parser.error("give --runs >= 1 and the mlndt_align command after --")
    with tempfile.TemporaryDirectory() as workdir:
        try:
            children = perf_shares(args.perf, command, args.runs, workdir)
            stages = [stage_times(command, workdir)
                      for _ in range(min(args.runs, 5))]
        except (subprocess.CalledProcessError, OSError) as error:
            print(f"profile_shares: {error}", file=sys.stderr)
            return 1
    register = find(children, ["mlndt::Register"])
    if not register:
        print("profile_shares: no samples in mlndt::Register", file=sys.stderr)
        return 1
    print(f"| part ({args.runs} runs, perf --children) | share of Register |")
    print("|---|---|")
    for label, symbols in PARTS:
        share = find(children, symbols)
        text = "-" if share is None else f"{100.0 * share / register:.1f} %"
        print(f"| {label} | {text} |")
    print(f"\nThe solve by stage ({len(stages)} runs with --output_json, "
          "mean shares of each run's solve, from its trace):")
    for stage in stages[0][1]:
        shares = [per_stage.get(stage, 0.0) / solve for solve, per_stage in stages]
        print(f"  {stage}: {100.0 * sum(shares) / len(shares):.1f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main())
