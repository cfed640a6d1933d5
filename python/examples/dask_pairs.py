"""Registers every pair (i, i+1), (i, i+2), (i, i+3) of a scan folder on Dask
workers and in order here, checks that the poses are identical, and prints
both wall times and the tasks each worker ran (the README's measurement).

    python3 python/examples/dask_pairs.py data/kitti/pcd              # LocalCluster, 2 workers
    python3 python/examples/dask_pairs.py DIR --scheduler tcp://host:8786
"""

import argparse
import sys
import time
from pathlib import Path

import numpy as np

import mlndt.distributed as md


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scans", type=Path, help="folder of .pcd scans")
    parser.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster)")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes")
    arguments = parser.parse_args()

    from distributed import Client, LocalCluster

    paths = sorted(arguments.scans.glob("*.pcd"))
    pairs = [(i, i + k) for k in (1, 2, 3) for i in range(len(paths) - k)]
    if arguments.scheduler:
        client = Client(arguments.scheduler)
    else:
        cluster = LocalCluster(n_workers=arguments.workers, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
    client.run(lambda: None)  # Workers are up before the clock starts.

    start = time.perf_counter()
    sequential = md.register_pairs(paths, pairs)
    sequential_s = time.perf_counter() - start
    start = time.perf_counter()
    fanned_out = md.register_pairs(paths, pairs, client=client)
    dask_s = time.perf_counter() - start

    identical = all(np.array_equal(a.reference_from_input, b.reference_from_input) for a, b in zip(sequential, fanned_out))
    print(f"{len(pairs)} pairs of {len(paths)} scans: sequential {sequential_s:.1f} s, "
          f"Dask {dask_s:.1f} s on {len(client.scheduler_info()['workers'])} workers; identical poses: {identical}")
    for worker, tasks in sorted(md.tasks_per_worker(fanned_out).items()):
        print(f"  {worker}: {tasks} tasks")
    client.close()
    return 0 if identical else 1


if __name__ == "__main__":
    sys.exit(main())
