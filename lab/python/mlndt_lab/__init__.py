"""The mlndt lab on numpy arrays: what mlndt_eval and mlndt_sequence compute.

A development module, not part of the installed mlndt package: the build of
scripts/test.sh makes it (CMake option MLNDT_BUILD_PYTHON_LAB, ON there and in
CI), `pip install .` does not. It binds lab/ (the evaluation harness), which
the product mlndt must not ship.

Trajectory evaluation (lab/eval): associate, ate, rpe, kitti_segment_errors,
path_distances_m, read_trajectory, write_trajectory. Sequence runs
(lab/runs): ScanStore, run_sequence, chain_trajectory, PairResult. ROS 1
bags (lab/io): RosBag, BagScan, rosbag_supported.

    import numpy as np, mlndt_lab as lab
    truth = lab.read_trajectory("data/kitti/poses_velo.txt")["poses"]
    scans = sorted(glob.glob("data/kitti/pcd/*.pcd"))
    results = lab.run_sequence(scans, truth=truth)
    estimate = lab.chain_trajectory(results)
    print(lab.ate(truth[: len(estimate)], estimate)["rmse_m"])

Poses are (N, 4, 4) world_from_sensor arrays; errors raise exceptions naming
the argument.
"""

# The product first, as when this was the submodule mlndt.lab: the lab takes
# mlndt.register's options (its stubs name mlndt's types).
import mlndt  # noqa: F401

from ._lab import (
    BagScan,
    PairResult,
    RosBag,
    ScanStore,
    __version__,
    associate,
    ate,
    chain_trajectory,
    kitti_segment_errors,
    path_distances_m,
    read_trajectory,
    rosbag_supported,
    rpe,
    run_sequence,
    write_trajectory,
)

__all__ = [
    "BagScan",
    "PairResult",
    "RosBag",
    "ScanStore",
    "__version__",
    "associate",
    "ate",
    "chain_trajectory",
    "kitti_segment_errors",
    "path_distances_m",
    "read_trajectory",
    "rosbag_supported",
    "rpe",
    "run_sequence",
    "write_trajectory",
]

PairResult.__module__ = "mlndt_lab"
ScanStore.__module__ = "mlndt_lab"
BagScan.__module__ = "mlndt_lab"
RosBag.__module__ = "mlndt_lab"
