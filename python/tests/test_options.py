"""Options as keyword arguments: every field reaches the library, presets,
enums as strings, and the ValueErrors of unknown or invalid options."""

import numpy as np
import pytest

import mlndt
from conftest import same_result

TOP_LEVEL = {
    "range_filter",
    "grid",
    "sampling",
    "schedule",
    "objective",
    "backend",
    "num_threads",
    "min_matched_fraction",
    "quality_check",
    "initial_uncertainty",
    "retry",
}


def leaves(options, path=()):
    """(path, value) of every non-dict entry of a nested options dict."""
    for key, value in options.items():
        if isinstance(value, dict):
            yield from leaves(value, path + (key,))
        else:
            yield path + (key,), value


def nested(path, value):
    """{"a": {"b": value}} for path ("a", "b")."""
    for key in reversed(path[1:]):
        value = {key: value}
    return {path[0]: value}


def test_default_options_lists_every_registration_option():
    options = mlndt.default_options()
    assert set(options) == TOP_LEVEL
    assert options["backend"]["type"] == "CERES"
    assert set(options["backend"]) == {"type", "ceres", "newton", "levenberg_marquardt"}
    assert options["initial_uncertainty"]["given"] is False
    # A fresh dict every time.
    options["num_threads"] = 7
    assert mlndt.default_options()["num_threads"] == 1


def test_paper_preset_is_the_papers_configuration():
    paper = mlndt.default_options("paper")
    assert paper["backend"]["type"] == "NEWTON"
    assert paper["schedule"]["start_layer"] == 2
    assert paper["schedule"]["iterations_per_layer"] == 3
    assert paper["schedule"]["max_coarse_point_stride"] == 1
    assert paper["objective"]["loss"] == "NONE"
    assert paper["objective"]["unmatched_policy"] == "ZERO_RESIDUAL"
    assert paper["grid"]["finest_cell_size_m"] == 0.0 and paper["grid"]["num_layers"] == 4
    assert paper["retry"]["yaw_seeds_deg"] == []


def test_default_options_passed_back_give_the_same_result(small_pair):
    assert same_result(mlndt.register(*small_pair), mlndt.register(*small_pair, **mlndt.default_options()))
    paper = mlndt.register(*small_pair, preset="paper")
    assert same_result(paper, mlndt.register(*small_pair, **mlndt.default_options("paper")))
    assert not same_result(paper, mlndt.register(*small_pair))


def test_every_option_field_can_be_set(small_pair):
    """Each leaf of default_options(), given alone with its default value,
    is accepted and changes nothing."""
    baseline = mlndt.register(*small_pair)
    count = 0
    for path, value in leaves(mlndt.default_options()):
        kwargs = nested(path, value)
        if path[0] == "initial_uncertainty":
            result = mlndt.register(*small_pair, initial_uncertainty=kwargs["initial_uncertainty"])
        else:
            result = mlndt.register(*small_pair, **kwargs)
        assert same_result(result, baseline), path
        count += 1
    assert count >= 45


@pytest.mark.parametrize(
    "kwargs, check",
    [
        ({"sampling": {"gbs_cell_size_m": 2.0}}, lambda r, b: r.sampled_points < b.sampled_points),
        ({"sampling": {"method": "random", "random_count": 500}}, lambda r, b: r.sampled_points == 500),
        ({"schedule": {"max_final_iterations": 1}}, lambda r, b: r.iterations_per_layer[-1] == 1),
        ({"schedule": {"start_layer": 0}}, lambda r, b: r.start_layer == r.num_layers),
        ({"grid": {"finest_cell_size_m": 1.0}}, lambda r, b: r.finest_cell_size_m <= 1.0 < b.finest_cell_size_m),
        ({"grid": {"finest_cell_size_m": 0.0, "num_layers": 3}}, lambda r, b: r.num_layers == 3),
        ({"range_filter": {"min_range_m": 5.0}}, lambda r, b: r.range_filtered_points > b.range_filtered_points),
        ({"quality_check": {"min_inlier_fraction": 0.99}}, lambda r, b: r.termination_type == "LOW_QUALITY"),
        ({"min_matched_fraction": 1.0}, lambda r, b: r.termination_type == "FAILURE"),
        ({"backend": {"type": "newton"}}, lambda r, b: r.usable and r.final_score != b.final_score),
        ({"objective": {"loss": "none"}}, lambda r, b: r.final_score != b.final_score),
        ({"num_threads": 2}, lambda r, b: r.usable),
    ],
)
def test_options_reach_the_library(small_pair, kwargs, check):
    baseline = mlndt.register(*small_pair)
    assert check(mlndt.register(*small_pair, **kwargs), baseline)


def test_enums_are_strings_in_any_case(small_pair):
    lm = mlndt.register(*small_pair, backend={"type": "LEVENBERG_MARQUARDT"})
    assert same_result(lm, mlndt.register(*small_pair, backend={"type": "lm"}))
    assert same_result(lm, mlndt.register(*small_pair, backend={"type": "Levenberg_Marquardt"}))
    gbs = mlndt.register(*small_pair, sampling={"method": "gbs"})
    assert same_result(gbs, mlndt.register(*small_pair))


def test_numbers_of_numpy_types_and_ints_for_floats_are_accepted(small_pair):
    one_metre = mlndt.register(*small_pair, grid={"finest_cell_size_m": 1.0})
    assert same_result(one_metre, mlndt.register(*small_pair, grid={"finest_cell_size_m": 1}))
    assert same_result(one_metre, mlndt.register(*small_pair, grid={"finest_cell_size_m": np.float32(1.0)}))
    threads = mlndt.register(*small_pair, num_threads=np.int64(1), quality_check={"enabled": np.bool_(True)})
    assert same_result(threads, mlndt.register(*small_pair))
    seeds = mlndt.register(*small_pair, retry={"yaw_seeds_deg": np.array([45.0, -45.0])})
    assert same_result(seeds, mlndt.register(*small_pair, retry={"yaw_seeds_deg": (45, -45)}))


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"finest_cell_size_m": 1.0}, r"unknown option finest_cell_size_m \(RegistrationOptions has: range_filter, grid"),
        ({"grid": {"finest_cell_size": 1.0}}, r"unknown option grid.finest_cell_size \(LayeredGridOptions has:"),
        ({"backend": {"ceres": {"solver": "x"}}}, r"unknown option backend.ceres.solver"),
        ({"grid": 1.0}, r"invalid option: grid = 1.0 \(float\); expected a dict of LayeredGridOptions fields"),
        ({"grid": {"finest_cell_size_m": "1"}}, r"invalid option: grid.finest_cell_size_m = '1' \(str\); expected float"),
        ({"grid": {"num_layers": 2.5}}, r"invalid option: grid.num_layers = 2.5 \(float\); expected int"),
        ({"num_threads": True}, r"invalid option: num_threads = True \(bool\); expected int"),
        ({"sampling": {"seed": -1}}, r"invalid option: sampling.seed = -1 \(int\); expected int"),
        ({"quality_check": {"enabled": 1}}, r"invalid option: quality_check.enabled = 1 \(int\); expected bool"),
        ({"retry": {"yaw_seeds_deg": 45}}, r"invalid option: retry.yaw_seeds_deg = 45 \(int\); expected list\[float\]"),
        ({"backend": {"type": "gauss"}}, r"backend.type = 'gauss' \(str\); expected one of CERES \| NEWTON \| LEVENBERG_MARQUARDT"),
        ({"backend": {"type": 1}}, r"backend.type = 1 \(int\); expected one of"),
        ({"backend": {"ceres": {"linear_solver_type": "qr"}}}, r"backend.ceres.linear_solver_type = 'qr'"),
        ({"grid": {"finest_cell_size_m": -1.0}}, r"invalid option: grid.finest_cell_size_m = -1; it must be in \[0.001, 100000\]"),
        ({"grid": {"regularization": {"min_eigenvalue_ratio": 0.0}}}, r"invalid option: grid.regularization.min_eigenvalue_ratio = 0"),
        ({"sampling": {"gbs_cell_size_m": 0.0}}, r"invalid option: sampling.gbs_cell_size_m = 0; it must be in \(0, 10000\]"),
        ({"schedule": {"iterations_per_layer": 0}}, r"invalid option: schedule.iterations_per_layer = 0"),
        ({"objective": {"loss_scale": 0.0}}, r"invalid option: objective.loss_scale = 0"),
        ({"backend": {"newton": {"max_line_search_steps": 0}}}, r"invalid option: backend.newton.max_line_search_steps = 0"),
        ({"quality_check": {"inlier_gate": 100.0}}, r"invalid option: quality_check.inlier_gate = 100"),
        ({"retry": {"yaw_seeds_deg": [200.0]}}, r"invalid option: retry.yaw_seeds_deg\[0\] = 200"),
        ({"num_threads": 0}, r"invalid option: num_threads = 0; it must be in \[1, 256\]"),
        ({"min_matched_fraction": float("nan")}, r"invalid option: min_matched_fraction = nan"),
        ({"preset": "papers"}, r"invalid option: preset = 'papers'; expected \"default\" or \"paper\""),
        ({"preset": 1}, r"invalid option: preset = 1 \(int\)"),
    ],
)
def test_unknown_and_invalid_options_raise_value_error_naming_the_field(small_pair, kwargs, match):
    with pytest.raises(ValueError, match=match):
        mlndt.register(*small_pair, **kwargs)


@pytest.mark.parametrize(
    "uncertainty, match",
    [
        ((1.0,), r"initial_uncertainty = \(1.0,\) \(tuple\); expected \(translation_m, rotation_deg\)"),
        ("0.5,5", r"initial_uncertainty = '0.5,5' \(str\)"),
        ((-1.0, 5.0), r"invalid option: initial_uncertainty.translation_m = -1"),
        ((0.5, 500.0), r"invalid option: initial_uncertainty.rotation_deg = 500"),
        ({"translation": 1.0}, r"unknown option initial_uncertainty.translation "),
    ],
)
def test_bad_initial_uncertainty_raises_value_error(small_pair, uncertainty, match):
    with pytest.raises(ValueError, match=match):
        mlndt.register(*small_pair, initial_uncertainty=uncertainty)


def test_initial_uncertainty_as_tuple_or_dict_is_the_same(small_pair):
    as_tuple = mlndt.register(*small_pair, initial_uncertainty=(0.05, 0.5))
    as_dict = mlndt.register(
        *small_pair, initial_uncertainty={"given": True, "translation_m": 0.05, "rotation_deg": 0.5}
    )
    assert same_result(as_tuple, as_dict)
    assert not same_result(as_tuple, mlndt.register(*small_pair))


def test_invalid_options_raise_before_any_work(small_pair):
    """Options are checked before the clouds: a bad option with a bad cloud
    names the option."""
    with pytest.raises(ValueError, match="unknown option"):
        mlndt.register(np.zeros((0, 3)), np.zeros((0, 3)), bogus=1)


def test_resolve_options_is_what_register_uses():
    resolved = mlndt.resolve_options((0.2, 2.0), preset="paper", grid={"finest_cell_size_m": 1.5})
    paper = mlndt.default_options("paper")
    assert resolved["grid"]["finest_cell_size_m"] == 1.5
    assert resolved["grid"]["num_layers"] == paper["grid"]["num_layers"]
    assert resolved["initial_uncertainty"]["given"] and resolved["initial_uncertainty"]["translation_m"] == 0.2
    assert resolved["sampling"] == paper["sampling"]
    with pytest.raises(ValueError, match=r"invalid option: sampling.random_fraction = 3; it must be in \(0, 1\]"):
        mlndt.resolve_options(sampling={"random_fraction": 3.0})
    with pytest.raises(ValueError, match="no_such_option"):
        mlndt.resolve_options(no_such_option=1)
