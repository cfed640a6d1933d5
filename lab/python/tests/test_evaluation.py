"""mlndt_lab's evaluation gives mlndt_eval's numbers: the same trajectory
files (a drifting, offset and, for Sim3, scaled copy of the bundled KITTI
poses), the same association, ATE, RPE and KITTI segment errors, compared for
equality (its JSON has 17 significant digits). Also: an exact estimate has
zero error, and bad arguments raise errors naming them."""

import json

import numpy as np
import pytest

import mlndt
from conftest import KITTI_POSES, import_lab, run_tool

lab = import_lab()

# (file format, alignment, scale of the estimate's translations)
CASES = {"kitti_se3": ("kitti", "se3", 1.0), "tum_sim3": ("tum", "sim3", 1.1), "kitti_first_pose": ("kitti", "first_pose", 1.0)}


def drifting_estimate(truth, scale):
    """Offset by a rigid transform, drifting 2 cm, 0.1 deg a frame, translations scaled."""
    offset = mlndt.pose_from_xi([5.0, -3.0, 1.0, 0.0, 0.0, 40.0], degrees=True)
    estimate = []
    for k, pose in enumerate(truth):
        drift = mlndt.pose_from_xi([0.02 * k, -0.01 * k, 0.005 * k, 0.05 * k, 0.0, 0.1 * k], degrees=True)
        moved = offset @ pose @ drift
        moved[:3, 3] *= scale
        estimate.append(moved)
    return np.array(estimate)


def write_files(tmp_path, file_format, scale):
    truth = lab.read_trajectory(KITTI_POSES)["poses"]
    estimate = drifting_estimate(truth, scale)
    if file_format == "kitti":
        reference_path, estimate_path = tmp_path / "reference.kitti", tmp_path / "estimate.kitti"
        lab.write_trajectory(reference_path, truth)
        lab.write_trajectory(estimate_path, estimate)
    else:  # TUM: 10 Hz, the estimate 5 ms late and missing frame 3.
        reference_path, estimate_path = tmp_path / "reference.tum", tmp_path / "estimate.tum"
        keep = [k for k in range(len(estimate)) if k != 3]
        lab.write_trajectory(reference_path, truth, np.arange(len(truth)) * 0.1, format="tum")
        lab.write_trajectory(estimate_path, estimate[keep], np.array(keep) * 0.1 + 0.005, format="tum")
    return reference_path, estimate_path


def evaluate(reference_path, estimate_path, alignment):
    reference = lab.read_trajectory(reference_path)
    estimate = lab.read_trajectory(estimate_path)
    if reference["format"] == "TUM":
        pairs = lab.associate(reference["poses"], estimate["poses"], reference["timestamps"], estimate["timestamps"])
    else:
        pairs = lab.associate(reference["poses"], estimate["poses"])
    return (
        pairs,
        lab.ate(pairs["reference"], pairs["estimate"], alignment),
        lab.rpe(pairs["reference"], pairs["estimate"], delta=2),
        lab.kitti_segment_errors(pairs["reference"], pairs["estimate"], lengths_m=[2.0, 4.0], first_frame_step=1),
    )


@pytest.mark.parametrize("case", sorted(CASES))
def test_evaluation_matches_mlndt_eval(tmp_path, case):
    file_format, alignment, scale = CASES[case]
    reference_path, estimate_path = write_files(tmp_path, file_format, scale)
    output = tmp_path / "eval.json"
    completed = run_tool(
        "mlndt_eval",
        f"--reference={reference_path}",
        f"--estimate={estimate_path}",
        f"--alignment={alignment}",
        "--delta=2",
        "--segments_lengths_m=2,4",
        "--segments_first_frame_step=1",
        f"--output_json={output}",
    )
    assert completed.returncode == 0, completed.stderr
    tool = json.loads(output.read_text())["estimates"][0]
    pairs, ate, rpe, kitti = evaluate(reference_path, estimate_path, alignment)

    assert tool["pairs"] == len(pairs["reference"]) == (7 if file_format == "tum" else 8)
    assert tool["association"] == ("timestamp" if file_format == "tum" else "index")
    assert tool["path_length_m"] == lab.path_distances_m(pairs["reference"])[-1]
    assert tool["ate"] == {
        "rmse_m": ate["rmse_m"],
        "mean_m": ate["stats_m"]["mean"],
        "median_m": ate["stats_m"]["median"],
        "max_m": ate["stats_m"]["max"],
        "scale": ate["scale"],
    }
    assert tool["rpe"]["pairs"] == rpe["translation_m"]["count"]
    assert tool["rpe"]["translation_rmse_m"] == rpe["translation_rmse_m"]
    assert tool["rpe"]["translation_max_m"] == rpe["translation_m"]["max"]
    assert tool["rpe"]["rotation_rmse_deg"] == rpe["rotation_rmse_deg"]
    assert tool["rpe"]["rotation_mean_deg"] == rpe["rotation_deg"]["mean"]
    assert tool["kitti"]["segments"] == len(kitti["segments"]) > 0
    assert tool["kitti"]["translation_error_percent"] == kitti["translation_error_percent"]
    assert tool["kitti"]["rotation_error_deg_per_m"] == kitti["rotation_error_deg_per_m"]
    assert tool["kitti"]["lengths"] == kitti["lengths"]
    # The drift is real: a wrong implementation returning zeros fails here.
    # (Sim3 absorbs most of the drift into the scale: its ATE is 0.2 mm.)
    assert ate["rmse_m"] > 1e-4 and rpe["translation_rmse_m"] > 0.01 and rpe["rotation_rmse_deg"] > 0.1
    if alignment == "sim3":
        assert abs(ate["scale"] - 1 / scale) < 0.05


def test_exact_estimate_has_no_error():
    truth = lab.read_trajectory(KITTI_POSES)["poses"]
    ate = lab.ate(truth, truth)
    assert ate["rmse_m"] < 1e-9
    assert lab.rpe(truth, truth)["translation_rmse_m"] < 1e-12
    assert lab.kitti_segment_errors(truth, truth, [2.0], 1)["translation_error_percent"] < 1e-9


@pytest.mark.parametrize(
    "call, exception, text",
    [
        (lambda t: lab.ate(t, t[:5]), ValueError, "ate: "),
        (lambda t: lab.ate(t, t, "affine"), ValueError, "alignment = 'affine'"),
        (lambda t: lab.rpe(t, t, delta=0), ValueError, "rpe: "),
        (lambda t: lab.kitti_segment_errors(t, t, [2.0, -1.0]), ValueError, "kitti_segment_errors: "),
        (lambda t: lab.ate(t[:, :3, :3], t), ValueError, r"reference\[0\]: expected a 4x4"),
        (lambda t: lab.associate(t, t, np.arange(8.0), None), ValueError, "give both"),
        (lambda t: lab.associate(t, t, np.zeros(8), np.zeros(8)), ValueError, r"reference_timestamps\[1\]"),
        (lambda t: lab.write_trajectory("/nonexistent/x.txt", t), FileNotFoundError, "/nonexistent/x.txt"),
        (lambda t: lab.read_trajectory("/nonexistent/x.txt"), FileNotFoundError, "/nonexistent/x.txt"),
    ],
)
def test_bad_arguments_name_the_field(call, exception, text):
    truth = lab.read_trajectory(KITTI_POSES)["poses"]
    with pytest.raises(exception, match=text):
        call(truth)
