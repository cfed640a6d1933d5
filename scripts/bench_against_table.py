#!/usr/bin/env python3
"""The table of scripts/bench_against.sh.

    bench_against_table.py RUN_DIR ROUNDS LABEL

RUN_DIR holds new_<r>.csv and old_<r>.csv (mlndt_bench --output_csv) for
r = 1..ROUNDS. Rows are matched on the method columns both CSVs have; per
row it prints the median over rounds of each one's time_median_ms, the
median over rounds of the per-round ratio old/new, and the success counts
(success_rate x runs, summed over rounds) of both.
"""

import csv
import statistics
import sys

# The columns that name a row (set of pairs and method); those both CSVs have
# are used (an older mlndt_bench may lack some).
KEY_COLUMNS = [
    "pairs", "defaults", "method", "backend", "sampling", "start_layer",
    "linear_solver", "trust_region", "minimizer", "jacobians", "loss",
    "threads",
]
# Shown in the method column when not empty.
LABEL_COLUMNS = ["defaults", "backend", "sampling", "minimizer", "jacobians",
                 "loss", "threads"]


def read_rows(path):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        return list(reader.fieldnames or []), list(reader)


def main(argv):
    if len(argv) != 4:
        sys.exit(__doc__)
    run_dir, rounds, label = argv[1], int(argv[2]), argv[3]
    runs = {"new": [], "old": []}
    columns = {}
    for side in runs:
        for r in range(1, rounds + 1):
            names, rows = read_rows(f"{run_dir}/{side}_{r}.csv")
            columns[side] = names
            runs[side].append(rows)
    keys = [c for c in KEY_COLUMNS if c in columns["new"] and c in columns["old"]]

    def key(row):
        return tuple(row.get(c, "") for c in keys)

    order = [key(row) for row in runs["new"][0]]
    per = {side: {} for side in runs}  # side -> key -> [(time, successes, runs)]
    for side, side_rounds in runs.items():
        for rows in side_rounds:
            for row in rows:
                n = int(row["runs"])
                successes = round(float(row["success_rate"] or 0) * n)
                per[side].setdefault(key(row), []).append(
                    (float(row["time_median_ms"]), successes, n))

    print(f"bench_against: this build (new) against {label} (old), {rounds} "
          "alternating round(s); times: median over rounds of each run's time "
          "med [ms]; old/new: median over rounds of the per-round ratio")
    header = ["pairs", "method", "new [ms]", "old [ms]", "old/new",
              "success new", "success old"]
    table = [header]
    for k in order:
        row = dict(zip(keys, k))
        new, old = per["new"].get(k, []), per["old"].get(k)
        method = " ".join(("t" if c == "threads" else "") + row[c]
                          for c in LABEL_COLUMNS if c in row and row[c])
        if row.get("method", "mlndt") != "mlndt":
            method = row["method"] + " " + row.get("sampling", "")
        if not old or len(old) != len(new):
            table.append([row["pairs"], method, f"{statistics.median(t for t, _, _ in new):.1f}",
                          "-", "-", f"{sum(s for _, s, _ in new)}/{sum(n for _, _, n in new)}", "-"])
            continue
        ratios = [o[0] / n[0] for o, n in zip(old, new) if n[0] > 0]
        table.append([
            row["pairs"], method,
            f"{statistics.median(t for t, _, _ in new):.1f}",
            f"{statistics.median(t for t, _, _ in old):.1f}",
            f"{statistics.median(ratios):.2f}" if ratios else "-",
            f"{sum(s for _, s, _ in new)}/{sum(n for _, _, n in new)}",
            f"{sum(s for _, s, _ in old)}/{sum(n for _, _, n in old)}",
        ])
    missing = [k for k in per["old"] if k not in per["new"]]
    widths = [max(len(r[c]) for r in table) for c in range(len(header))]
    for i, r in enumerate(table):
        print("| " + " | ".join(v.ljust(w) for v, w in zip(r, widths)) + " |")
        if i == 0:
            print("|" + "|".join("-" * (w + 2) for w in widths) + "|")
    for k in missing:
        print(f"- only in old: {' '.join(v for v in k if v)}")


if __name__ == "__main__":
    main(sys.argv)
