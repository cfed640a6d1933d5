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
from result_files import assert_files_agree_with_python


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


@pytest.fixture(scope="module")
def tool_run(tmp_path_factory, kitti_map):
    """mlndt_localize on the same map and scans: its output folder."""
    out = tmp_path_factory.mktemp("localize")
    completed = run_tool(
        "mlndt_localize",
        f"--map={kitti_map[1]}",
        f"--scans={KITTI_SCANS[0].parent}",
        f"--output_dir={out}",
        "--plots=false",
    )
    assert completed.returncode == 0, completed.stderr
    return out


def test_poses_equal_mlndt_localize(tool_run, localized):
    tool_poses = read_kitti_lines(tool_run / "trajectory_kitti.txt")
    assert len(tool_poses) == len(localized) == 8
    for k, result in enumerate(localized):
        assert result.index == k
        assert np.array_equal(tool_poses[k], result.map_from_scan), k
    with open(tool_run / "scans.csv") as rows:
        table = list(csv.DictReader(rows))
    assert [row["registration.termination_type"] for row in table] == [
        r.registration.termination_type for r in localized
    ]
    assert [int(row["registration.num_iterations"]) for row in table] == [
        r.registration.num_iterations for r in localized
    ]


def test_scans_csv_json_and_python_agree(tool_run, localized):
    """Issue 46: one scan's result in scans.csv, scans.json and Python has the
    same keys and values (LocalizationResultTable; the files leave the trace
    out). The tool and Python ran separately, so their wall times differ:
    those keys are compared only."""
    with open(tool_run / "scans.csv") as rows:
        table = list(csv.DictReader(rows))
    scans = json.loads((tool_run / "scans.json").read_text())["scans"]
    assert len(table) == len(scans) == len(localized) == 8
    for k, result in enumerate(localized):
        python = result.todict()
        row, scan = table[k], scans[k]
        assert scan.pop("file") == row.pop("file") == KITTI_SCANS[k].name
        # Keys: JSON = CSV = Python flattened; the registration's trace is
        # Python's only (too large for a file of every scan).
        assert len(python["registration"]["trace"]) == python["registration"]["num_iterations"] > 0
        assert "registration.quality.inlier_fraction" in row
        assert_files_agree_with_python(row, scan, python, skip_times=True)
        # The property is the RegistrationResult of the same registration.
        assert isinstance(result.registration, mlndt.RegistrationResult)
        assert result.registration.num_iterations == python["registration"]["num_iterations"]


@pytest.mark.parametrize("k", [1, 2, 3, 5])
def test_poses_match_the_reference_pairs(localized, k):
    expected, _ = reference_transform(KITTI_PAIRS, f"0_{k}")
    result = localized[k]
    assert result.registration.termination_type == "CONVERGENCE", result.registration.message
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
    assert result.registration.num_iterations < default.registration.num_iterations


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
