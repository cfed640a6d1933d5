"""mlndt.Localizer: the bundled KITTI frames 0-7 localised against the map of
frame 0 give mlndt_localize's poses on the same map file, number for number
(its trajectory_kitti.txt has 17 significant digits), land within the
reference pairs' tolerance, and bad arguments raise errors naming them."""

import csv
import json

import numpy as np
import pytest

import mlndt
from conftest import (
    KITTI_PAIRS,
    KITTI_SCANS,
    read_kitti_lines,
    reference_transform,
    rotation_error_deg,
    run_tool,
    translation_error_m,
)


@pytest.fixture(scope="module")
def kitti_map(tmp_path_factory):
    """Frame 0's map (range-filtered as register filters a reference), saved."""
    layered_map = mlndt.LayeredMap.build(mlndt.filter_range(mlndt.read_cloud(KITTI_SCANS[0])))
    path = tmp_path_factory.mktemp("map") / "frame0.mlndt"
    layered_map.save(path)
    return mlndt.LayeredMap.load(path), path


@pytest.fixture(scope="module")
def localized(kitti_map):
    localizer = mlndt.Localizer(kitti_map[0])
    return [localizer.localize(mlndt.read_cloud(path)) for path in KITTI_SCANS]


def test_poses_equal_mlndt_localize(tmp_path, kitti_map, localized):
    completed = run_tool(
        "mlndt_localize",
        f"--map={kitti_map[1]}",
        f"--scans={KITTI_SCANS[0].parent}",
        f"--output_dir={tmp_path}",
        "--plots=false",
    )
    assert completed.returncode == 0, completed.stderr
    tool_poses = read_kitti_lines(tmp_path / "trajectory_kitti.txt")
    assert len(tool_poses) == len(localized) == 8
    for k, result in enumerate(localized):
        assert result.index == k
        assert np.array_equal(tool_poses[k], result.map_from_scan), k
    with open(tmp_path / "scans.csv") as rows:
        table = list(csv.DictReader(rows))
    assert [row["termination"] for row in table] == [r.termination for r in localized]
    assert [int(row["iterations"]) for row in table] == [r.iterations for r in localized]
    assert [int(row["sampled_points"]) for row in table] == [r.sampled_points for r in localized]


@pytest.mark.parametrize("k", [1, 2, 3, 5])
def test_poses_match_the_reference_pairs(localized, k):
    expected, _ = reference_transform(KITTI_PAIRS, f"0_{k}")
    result = localized[k]
    assert result.termination == "CONVERGENCE", result.message
    assert translation_error_m(expected, result.map_from_scan) < 0.1
    assert rotation_error_deg(expected, result.map_from_scan) < 0.2


def test_constant_velocity_prediction(localized, kitti_map):
    # Scan k starts from pose_{k-1} moved by the last motion pose_{k-2}^-1 pose_{k-1}.
    for k in range(2, len(localized)):
        previous, before = localized[k - 1].map_from_scan, localized[k - 2].map_from_scan
        expected = previous @ np.linalg.inv(before) @ previous
        np.testing.assert_allclose(localized[k].predicted_map_from_scan, expected, atol=1e-12)
    localizer = mlndt.Localizer(kitti_map[0], motion_model="constant_pose")
    first = localizer.localize(mlndt.read_cloud(KITTI_SCANS[1]))
    assert localizer.num_localized == 1
    np.testing.assert_array_equal(localizer.predict_next(), first.map_from_scan)


def test_options_reach_the_registration(kitti_map):
    """A 2-iteration cap on the last layer shows in every scan's result."""
    localizer = mlndt.Localizer(kitti_map[0], schedule={"max_final_iterations": 2})
    result = localizer.localize(mlndt.read_cloud(KITTI_SCANS[1]))
    default = mlndt.Localizer(kitti_map[0]).localize(mlndt.read_cloud(KITTI_SCANS[1]))
    assert result.iterations < default.iterations


@pytest.mark.parametrize(
    "arguments, exception, text",
    [
        ({"motion_model": "teleport"}, ValueError, "motion_model = 'teleport'"),
        ({"grid": {"finest_cell_size_m": 1.0}}, ValueError, "grid does not apply to Localizer"),
        ({"sampling": {"random_fraction": 2.0}}, ValueError, r"invalid option: sampling.random_fraction = 2; it must be in \(0, 1\]"),
        ({"first_map_from_scan": np.diag([2.0, 1, 1, 1])}, ValueError, "first_map_from_scan: not a rigid transform"),
        ({"no_such_option": 1}, ValueError, "no_such_option"),
    ],
)
def test_bad_arguments_name_the_field(kitti_map, arguments, exception, text):
    with pytest.raises(exception, match=text):
        mlndt.Localizer(kitti_map[0], **arguments)


def test_bad_scan_names_the_argument(kitti_map):
    localizer = mlndt.Localizer(kitti_map[0])
    with pytest.raises(ValueError, match="scan"):
        localizer.localize(np.zeros((5, 2)))
    assert localizer.num_localized == 0
