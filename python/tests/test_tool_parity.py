"""mlndt.register gives mlndt_align's result on the same inputs and options.

mlndt_align writes its JSON (docs/json_schema.md) with 17 significant digits
(tools/common/json_output.h), so each number reads back as the double the
tool computed and is compared for equality, not with a tolerance. Pose,
scores, covariance, every trace score and the fit measures together leave no
room for a different computation."""

import json
import subprocess

import numpy as np
import pytest

import mlndt
from conftest import KOIDE3_INPUT, KOIDE3_REFERENCE, TOOLS_DIR

ALIGN = TOOLS_DIR / "mlndt_align"


def as_json_number(value):
    """What mlndt_align writes for `value` (the double itself; null for inf/nan)."""
    return None if not np.isfinite(value) else float(value)


def run_align(tmp_path, flags):
    if not ALIGN.exists():
        pytest.fail(f"{ALIGN} is not built (MLNDT_BUILD_TOOLS=ON builds it)")
    output = tmp_path / "align.json"
    command = [str(ALIGN), f"--reference={KOIDE3_REFERENCE}", f"--input={KOIDE3_INPUT}", f"--output_json={output}"]
    completed = subprocess.run(command + flags, capture_output=True, text=True)
    # Exit code 1 with the JSON written: a result that is not to be trusted.
    assert completed.returncode in (0, 1), completed.stderr
    return json.loads(output.read_text())["registration"], completed.stdout


CASES = {
    "defaults": ([], {}, {}),
    "lm_2m_gbs": (
        ["--backend=lm", "--gbs_cell_size=2", "--loss=huber", "--loss_scale=2.5"],
        {},
        {"backend": {"type": "lm"}, "sampling": {"gbs_cell_size_m": 2.0}, "objective": {"loss": "huber", "loss_scale": 2.5}},
    ),
    "paper": (["--preset=paper"], {}, {"preset": "paper"}),
    "guess_and_grid": (
        [
            "--initial_guess=0.4,0.1,0,0,0,-1",
            "--initial_uncertainty=0.2,2",
            "--finest_cell_size=1",
            "--min_eigenvalue=0.002",
            "--coarse_weighting=finest_cells",
            "--seed=7",
            "--max_range=40",
            "--retry_yaw_seeds=",
        ],
        {"initial": mlndt.pose_from_xi([0.4, 0.1, 0, 0, 0, -1], degrees=True), "initial_uncertainty": (0.2, 2.0)},
        {
            "grid": {"finest_cell_size_m": 1.0, "regularization": {"min_eigenvalue_m2": 0.002}, "coarse_weighting": "finest_cells"},
            "sampling": {"seed": 7},
            "range_filter": {"max_range_m": 40.0},
            "retry": {"yaw_seeds_deg": []},
        },
    ),
    "newton_schedule": (
        ["--backend=newton", "--start_layer=2", "--iterations_per_layer=4", "--max_iterations=12", "--unmatched=zero_residual"],
        {},
        {
            "backend": {"type": "newton"},
            "schedule": {"start_layer": 2, "iterations_per_layer": 4, "max_final_iterations": 12},
            "objective": {"unmatched_policy": "zero_residual"},
        },
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_register_matches_mlndt_align(tmp_path, koide3, case):
    flags, arguments, options = CASES[case]
    tool, stdout = run_align(tmp_path, flags)
    result = mlndt.register(*koide3, **arguments, **options)

    assert tool["termination"] == result.termination
    assert (tool["termination"] == "CONVERGENCE") == result.converged
    assert tool["message"] == result.message
    assert tool["iterations"] == result.iterations
    assert tool["iterations_per_layer"] == result.iterations_per_layer
    assert tool["start_layer"] == result.start_layer and tool["num_layers"] == result.num_layers
    assert tool["points"]["sampled"] == result.sampled_points
    assert tool["points"]["matched"] == result.matched_points
    assert tool["map"]["occupied_cells"] == result.map_occupied_cells
    assert tool["map"]["memory_bytes"] == result.map_bytes
    # 4 rows of 4 numbers.
    assert tool["reference_from_input"] == [[as_json_number(v) for v in row] for row in result.reference_from_input]
    assert tool["score"]["final"] == as_json_number(result.score)
    assert tool["score"]["initial"] == as_json_number(result.initial_score)
    # The covariance with its angles in degrees: S C S, S = diag(1, 1, 1, k, k, k).
    scale = np.array([1.0, 1.0, 1.0] + [180.0 / np.pi] * 3)
    covariance_deg = scale[:, None] * result.covariance * scale[None, :]
    printed = np.array([[np.nan if v is None else v for v in row] for row in tool["covariance_m_deg"]["matrix"]])
    np.testing.assert_allclose(printed, covariance_deg, rtol=1e-14, atol=0)
    assert [r["score"] for r in tool["trace"]] == [as_json_number(r["score"]) for r in result.trace]
    assert [r["layer"] for r in tool["trace"]] == [r["layer"] for r in result.trace]
    for name in ("own_cell_fraction", "inlier_fraction", "mean_score", "median_distance", "constraint_ratio"):
        assert tool["quality"][name] == as_json_number(result.quality[name]), name
    assert tool["quality"]["median_distance_m"] == tool["quality"]["median_distance"]  # deprecated name
    # The report's first line (timings aside) is the library's, printed by both.
    report_line = result.report().splitlines()[1]
    assert report_line in stdout.splitlines()
