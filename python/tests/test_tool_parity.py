"""mlndt.register gives mlndt_align's result on the same inputs and options,
under the same names: both are made from RegistrationSummary's result table
(mlndt/common/result_table.h), mlndt_align's JSON "registration" object by
tools/cli/result_json.cc and the Python properties and todict() by
python/src/result_binding.h.

mlndt_align writes its JSON (docs/json_schema.md) with 17 significant digits
(tools/cli/json_output.h), so each number reads back as the double the
tool computed and is compared for equality, not with a tolerance. Every key
and every value (timings aside) of todict() is compared with the tool's, and
every property with its todict() entry."""

import json
import subprocess

import numpy as np
import pytest

import mlndt
from conftest import KOIDE3_INPUT, KOIDE3_REFERENCE, TOOLS_DIR

ALIGN = TOOLS_DIR / "mlndt_align"


def as_json(value):
    """What mlndt_align writes for a todict() value: numbers as the doubles
    themselves (null when not finite), arrays as nested lists."""
    if isinstance(value, dict):
        return {key: as_json(v) for key, v in value.items()}
    if isinstance(value, np.ndarray):
        return as_json(value.tolist())
    if isinstance(value, list):
        return [as_json(v) for v in value]
    if isinstance(value, float) and not np.isfinite(value):
        return None
    return value


def without_times(value):
    """The same with every wall time (keys ending in time_s) blanked."""
    if isinstance(value, dict):
        return {key: None if key.endswith("time_s") else without_times(v) for key, v in value.items()}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def key_paths(value, prefix=""):
    """Every key of nested dicts (and of the dicts in lists), as dotted paths."""
    paths = []
    if isinstance(value, dict):
        for key, v in value.items():
            paths.append(prefix + key)
            paths += key_paths(v, prefix + key + ".")
    elif isinstance(value, list) and value and isinstance(value[0], dict):
        paths += key_paths(value[0], prefix + "[].")
    return paths


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
        ["--backend=lm", "--gbs_cell_size_m=2", "--loss=huber", "--loss_scale=2.5"],
        {},
        {"backend": {"type": "lm"}, "sampling": {"gbs_cell_size_m": 2.0}, "objective": {"loss": "huber", "loss_scale": 2.5}},
    ),
    "paper": (["--preset=paper"], {}, {"preset": "paper"}),
    "guess_and_grid": (
        [
            "--initial_guess=0.4,0.1,0,0,0,-1",
            "--initial_uncertainty=0.2,2",
            "--finest_cell_size_m=1",
            "--min_eigenvalue_m2=0.002",
            "--coarse_weighting=finest_cells",
            "--seed=7",
            "--max_range_m=40",
            "--yaw_seeds_deg=",
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
        ["--backend=newton", "--start_layer=2", "--iterations_per_layer=4", "--max_final_iterations=12", "--unmatched_policy=zero_residual"],
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

    record = result.todict()

    # Same keys in the same order, nested ones included, and the same values.
    assert key_paths(tool) == key_paths(as_json(record))
    assert without_times(tool) == without_times(as_json(record))
    # Times are the run's own, but in seconds on both sides.
    assert 0 < tool["total_time_s"] < 60 and 0 < result.total_time_s < 60
    # Every field is a property with its todict() value.
    for key, value in record.items():
        assert as_json(getattr(result, key)) == as_json(value), key
    # The names are the C++ fields' (docs/json_schema.md lists the renames).
    for old in ("termination", "iterations", "score", "xi", "points", "map", "time_ms", "covariance_m_deg"):
        assert old not in tool, old
    assert tool["termination_type"] == result.termination_type
    assert (tool["termination_type"] == "CONVERGENCE") == result.converged
    assert tool["num_iterations"] == len(tool["trace"]) > 0
    assert len(tool["reference_from_input"]) == 4 and len(tool["covariance"]) == 6
    # The report's first line (timings aside) is the library's, printed by both.
    report_line = result.report().splitlines()[1]
    assert report_line in stdout.splitlines()
