"""mlndt.register: accuracy on the koide3 pair, the result object, input
dtypes and layouts, and the errors of bad input."""

import numpy as np
import pytest

import mlndt
from conftest import (
    BUNDLED_DATA_DIR,
    KOIDE3_KEY,
    reference_transform,
    rotation_error_deg,
    same_result,
    translation_error_m,
)

REFERENCE_PAIRS = BUNDLED_DATA_DIR / "koide3" / "reference_pairs.json"


def test_koide3_translation_within_2cm_and_rotation_within_reference_spread(koide3_result):
    expected, entry = reference_transform(REFERENCE_PAIRS, KOIDE3_KEY)
    result = koide3_result
    assert result.termination_type == "CONVERGENCE", result.message
    assert translation_error_m(expected, result.reference_from_input) < 0.02
    # The five peers behind the reference spread 0.48 deg in rotation.
    assert rotation_error_deg(expected, result.reference_from_input) < entry["spread_deg"]


@pytest.mark.xfail(strict=False, reason="the defaults end 0.43 deg from the consensus (its spread: 0.48 deg); tuning")
def test_koide3_rotation_within_0_3_deg(koide3_result):
    expected, _ = reference_transform(REFERENCE_PAIRS, KOIDE3_KEY)
    assert rotation_error_deg(expected, koide3_result.reference_from_input) < 0.3


def test_result_fields_are_consistent(koide3, koide3_result):
    result = koide3_result
    reference, input = koide3
    pose = result.reference_from_input
    assert pose.shape == (4, 4) and pose.dtype == np.float64
    np.testing.assert_array_equal(pose[3], [0, 0, 0, 1])
    np.testing.assert_allclose(pose[:3, :3].T @ pose[:3, :3], np.eye(3), atol=1e-12)
    np.testing.assert_allclose(mlndt.pose_from_xi(result.reference_from_input_xi), pose, atol=1e-12)
    assert result.converged == (result.termination_type == "CONVERGENCE")
    assert result.usable
    assert result.message
    assert result.final_score < result.initial_score
    assert result.num_iterations == len(result.trace) == sum(result.iterations_per_layer)
    assert result.attempts >= 1
    assert 1 <= result.start_layer <= result.num_layers == len(result.iterations_per_layer)
    assert result.input_points == len(input)
    assert result.matched_points + result.unmatched_points == result.sampled_points
    assert 0 < result.sampled_points < len(input)
    assert set(result.quality) == {
        "points",
        "own_cell_fraction",
        "inlier_fraction",
        "mean_score",
        "median_distance",
    }
    assert set(result.constraints) == {
        "constraint_ratio",
        "localizability",
        "least_localizable_direction",
        "unlocalizable_directions",
        "degenerate_directions",
        "flatness",
        "probe_evidence",
        "flattest_direction",
        "flat_directions",
        "weakest_translations",
    }
    assert result.quality["points"] == result.sampled_points
    assert 0 < result.quality["inlier_fraction"] <= 1
    assert result.constraints["degenerate_directions"].shape == (0, 6)
    assert result.constraints["weakest_translations"].shape == (3, 3)
    covariance = result.covariance
    assert covariance.shape == (6, 6)
    np.testing.assert_allclose(covariance, covariance.T, rtol=1e-9, atol=1e-18)
    assert np.all(np.linalg.eigvalsh(covariance) > 0)
    # Translations in m, angles in rad: millimetres and hundredths of a degree here.
    assert np.all(np.sqrt(np.diag(covariance)[:3]) < 0.01)
    assert np.all(np.degrees(np.sqrt(np.diag(covariance)[3:])) < 0.1)
    assert result.hessian.shape == (6, 6)
    record = result.trace[-1]
    assert set(record) == {
        "iteration",
        "layer",
        "score",
        "step_norm",
        "step_is_successful",
        "reference_from_input_xi",
        "time_s",
    }
    assert record["iteration"] == result.num_iterations and record["layer"] == result.num_layers
    assert record["reference_from_input_xi"].shape == (6,)
    assert result.total_time_s >= result.map_time_s + result.sampling_time_s > 0
    assert result.map_bytes > 0 and result.map_occupied_cells > 0
    report = result.report()
    assert report.startswith("ML-NDT registration: CONVERGENCE")
    assert "pose xi:" in report and "sigma (cov):" in report
    assert result.brief_report() in repr(result)


def test_initial_guess_and_uncertainty_are_passed(koide3, koide3_result):
    reference, input = koide3
    guess = mlndt.pose_from_xi([0.5, 0.1, 0.0, 0.0, 0.0, -1.0], degrees=True)
    result = mlndt.register(reference, input, initial=guess, initial_uncertainty=(0.1, 1.0))
    np.testing.assert_allclose(result.initial_reference_from_input_xi, mlndt.xi_from_pose(guess), atol=1e-15)
    # A good guess starts on a finer layer than the schedule's layer 1.
    assert result.start_layer > koide3_result.start_layer
    assert result.usable
    assert translation_error_m(result.reference_from_input, koide3_result.reference_from_input) < 0.01
    # A 3x4 guess is the same guess.
    same = mlndt.register(reference, input, initial=guess[:3], initial_uncertainty=(0.1, 1.0))
    assert same_result(result, same)


def test_float32_is_converted_once_exactly(koide3):
    reference, input = koide3
    reference32, input32 = reference.astype(np.float32), input.astype(np.float32)
    from32 = mlndt.register(reference32, input32)
    from64 = mlndt.register(reference32.astype(np.float64), input32.astype(np.float64))
    assert same_result(from32, from64)
    full = mlndt.register(reference, input)
    assert translation_error_m(from32.reference_from_input, full.reference_from_input) < 1e-3


@pytest.mark.parametrize(
    "layout",
    ["fortran", "column_slice", "row_step", "reversed", "float32_fortran", "list", "int"],
)
def test_any_layout_gives_the_contiguous_result(small_pair, layout):
    reference, input = small_pair
    if layout == "fortran":
        strided = np.asfortranarray(input)
        expected = input
    elif layout == "column_slice":  # (N, 4) with intensity, x y z taken as a view.
        wide = np.hstack([input, np.ones((len(input), 1))])
        strided = wide[:, :3]
        expected = input
    elif layout == "row_step":
        strided = input[::2]
        expected = np.ascontiguousarray(input[::2])
    elif layout == "reversed":
        strided = input[::-1]
        expected = np.ascontiguousarray(input[::-1])
    elif layout == "float32_fortran":
        strided = np.asfortranarray(input.astype(np.float32))
        expected = input.astype(np.float32).astype(np.float64)
    elif layout == "list":
        strided = input.tolist()
        expected = input
    else:  # Integer coordinates (decimetres as metres): converted to float64.
        strided = np.round(input * 10).astype(np.int32)
        expected = strided.astype(np.float64)
    assert layout in ("list",) or not strided.flags.c_contiguous or strided.dtype != np.float64
    assert same_result(mlndt.register(reference, strided), mlndt.register(reference, expected))


def test_inputs_are_not_modified(small_pair):
    reference, input = small_pair
    before = (reference.copy(), input.copy())
    mlndt.register(reference, input)
    np.testing.assert_array_equal(reference, before[0])
    np.testing.assert_array_equal(input, before[1])


def test_read_only_arrays_are_accepted(small_pair):
    reference, input = (a.copy() for a in small_pair)
    reference.flags.writeable = False
    input.flags.writeable = False
    assert mlndt.register(reference, input).termination_type != "FAILURE"


@pytest.mark.parametrize(
    "points, match",
    [
        (np.zeros((10, 2)), r"input: expected an array of shape \(N, 3\), got shape \(10, 2\)"),
        (np.zeros((10, 4)), r"shape \(10, 4\) \(x, y, z first\? pass points\[:, :3\]\)"),
        (np.zeros((3, 10)), r"shape \(3, 10\) \(one point per column\? pass points.T\)"),
        (np.zeros(30), r"got shape \(30,\)"),
        (np.zeros((10, 3, 1)), r"got shape \(10, 3, 1\)"),
        (np.zeros((0, 3)), r"input: no points"),
        ([], r"input: expected an array of shape \(N, 3\), got shape \(0,\)"),
    ],
)
def test_wrong_shapes_and_empty_arrays_raise_value_error(small_pair, points, match):
    with pytest.raises(ValueError, match=match):
        mlndt.register(small_pair[0], points)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_rows_raise_value_error_naming_the_row(small_pair, bad):
    reference, input = small_pair
    broken = input.copy()
    broken[17, 1] = bad
    with pytest.raises(ValueError, match=r"input: row 17 is not finite"):
        mlndt.register(reference, broken)
    with pytest.raises(ValueError, match=r"reference: row 17 is not finite"):
        mlndt.register(broken, input)


def test_empty_reference_raises_value_error(small_pair):
    with pytest.raises(ValueError, match="reference: no points"):
        mlndt.register(np.empty((0, 3)), small_pair[1])


@pytest.mark.parametrize("points", [np.array([["a", "b", "c"]]), np.zeros((4, 3), dtype=complex), None])
def test_non_numeric_arrays_raise_type_error(small_pair, points):
    with pytest.raises(TypeError, match="input"):
        mlndt.register(small_pair[0], points)


@pytest.mark.parametrize(
    "initial, match",
    [
        (np.eye(3), r"initial: expected a 4x4 \(or 3x4\) rigid transform, got shape \(3, 3\)"),
        (2 * np.eye(4), r"initial: the last row"),
        (np.diag([2.0, 1.0, 1.0, 1.0]), r"initial: not a rigid transform"),
        (np.diag([-1.0, 1.0, 1.0, 1.0]), r"initial: not a rigid transform .*det R = -1"),
        (np.full((4, 4), np.nan), r"initial: has non-finite entries"),
    ],
)
def test_bad_initial_guesses_raise_value_error(small_pair, initial, match):
    with pytest.raises(ValueError, match=match):
        mlndt.register(*small_pair, initial=initial)


def test_a_registration_that_fails_is_a_result_not_an_exception(small_pair):
    reference, _ = small_pair
    # Every input point at one spot: the range filter drops them all (a
    # saturated maximum range).
    result = mlndt.register(reference, np.tile([1.0, 2.0, 3.0], (50, 1)))
    assert result.termination_type == "FAILURE"
    assert not result.usable and not result.converged
    assert "range filter" in result.message


def test_initial_written_with_six_digits_is_accepted(small_pair):
    """Issue 27 item 4: the 6-digit matrix of data/koide3 (|R^T R - I| = 1.2e-6)
    is a rigid transform for initial=, as for every pose reader (tolerance
    1e-3, re-orthonormalised); it was refused above 1e-6."""
    initial = np.loadtxt(BUNDLED_DATA_DIR / "koide3" / "T_target_source.txt")
    rotation = initial[:3, :3]
    assert np.linalg.norm(rotation.T @ rotation - np.eye(3)) > 1e-6
    result = mlndt.register(*small_pair, initial=initial)
    assert result.usable, result.message
    assert np.linalg.norm(result.reference_from_input[:3, 3] - initial[:3, 3]) < 0.2
