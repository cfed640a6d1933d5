"""mlndt.LayeredMap: build, layer facts, cells, save/load, and registering
against a prebuilt map (localisation)."""

import numpy as np
import pytest

import mlndt
from conftest import same_result


@pytest.fixture(scope="module")
def reference_map(koide3):
    """The map register() builds of the koide3 reference: default grid options
    on the range-filtered reference."""
    return mlndt.LayeredMap.build(mlndt.filter_range(koide3[0]))


def test_registering_on_the_map_equals_registering_on_the_cloud(koide3, reference_map):
    on_cloud = mlndt.register(*koide3)
    on_map = reference_map.register(koide3[1])
    assert same_result(on_cloud, on_map)
    assert on_map.map_time_s == 0.0 < on_cloud.map_time_s
    assert on_map.map_bytes == on_cloud.map_bytes == reference_map.bytes


def test_layer_facts(koide3, reference_map):
    points = mlndt.filter_range(koide3[0])
    layers = reference_map.layers
    assert reference_map.num_layers == len(layers) >= 2
    assert [layer["layer"] for layer in layers] == list(range(1, len(layers) + 1))
    sizes = [layer["cell_size_m"] for layer in layers]
    # q = 8: the edge halves from one layer to the next (Table 1).
    np.testing.assert_allclose(np.array(sizes[:-1]) / np.array(sizes[1:]), 2.0, rtol=1e-12)
    assert sizes[-1] <= reference_map.options["finest_cell_size_m"]
    for layer in layers:
        assert len(layer["dims"]) == 3 and min(layer["dims"]) >= 1
        assert 0 < layer["occupied_cells"] <= np.prod(layer["dims"])
    result = reference_map.register(koide3[1])
    assert sum(layer["occupied_cells"] for layer in layers) == result.map_occupied_cells
    np.testing.assert_array_equal(reference_map.bounds, [points.min(axis=0), points.max(axis=0)])
    assert reference_map.num_points == len(points)
    assert reference_map.options == mlndt.default_options()["grid"]
    assert "LayeredMap" in repr(reference_map)


def test_cells(koide3, reference_map):
    for info in reference_map.layers:
        cells = reference_map.cells(info["layer"])
        count = info["occupied_cells"]
        assert cells["means"].shape == (count, 3)
        assert cells["covariances"].shape == (count, 3, 3)
        assert cells["counts"].shape == (count,)
        assert np.all(cells["counts"] >= reference_map.options["min_points_per_cell"])
        np.testing.assert_allclose(cells["covariances"], np.transpose(cells["covariances"], (0, 2, 1)), atol=1e-15)
        assert np.all(np.linalg.eigvalsh(cells["covariances"]) > 0)
    assert reference_map.cells(1)["counts"].sum() == reference_map.num_points
    with pytest.raises(IndexError):
        reference_map.cells(0)
    with pytest.raises(IndexError):
        reference_map.cells(reference_map.num_layers + 1)


def test_build_options(koide3):
    points = koide3[0]
    fine = mlndt.LayeredMap.build(points, finest_cell_size_m=1.0)
    assert fine.layers[-1]["cell_size_m"] <= 1.0
    paper = mlndt.LayeredMap.build(points, preset="paper")
    assert paper.num_layers == 4
    single = mlndt.LayeredMap.build(points, cell_size_m=2.0)
    assert [layer["cell_size_m"] for layer in single.layers] == [2.0]
    regularised = mlndt.LayeredMap.build(points, regularization={"min_eigenvalue_m2": 0.01})
    assert regularised.options["regularization"]["min_eigenvalue_m2"] == 0.01
    threaded = mlndt.LayeredMap.build(points, num_threads=2)
    default = mlndt.LayeredMap.build(points)
    for layer in range(1, default.num_layers + 1):
        np.testing.assert_array_equal(threaded.cells(layer)["means"], default.cells(layer)["means"])


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"finest_cell_size": 1.0}, r"unknown option finest_cell_size \(LayeredGridOptions has:"),
        ({"finest_cell_size_m": -1.0}, r"invalid option: finest_cell_size_m = -1"),
        ({"regularization": {"min_eigenvalue_ratio": 2.0}}, r"invalid option: regularization.min_eigenvalue_ratio = 2"),
        ({"coarse_weighting": "cells"}, r"coarse_weighting = 'cells' \(str\); expected one of POINTS \| FINEST_CELLS"),
        ({"num_threads": 0}, r"num_threads = 0"),
        ({"preset": "fast"}, r"preset = 'fast'"),
    ],
)
def test_build_refuses_bad_options(koide3, kwargs, match):
    with pytest.raises(ValueError, match=match):
        mlndt.LayeredMap.build(koide3[0], **kwargs)


def test_build_refuses_bad_points():
    with pytest.raises(ValueError, match=r"points: no points"):
        mlndt.LayeredMap.build(np.empty((0, 3)))
    with pytest.raises(ValueError, match=r"points: row 1 is not finite"):
        mlndt.LayeredMap.build([[0.0, 0.0, 0.0], [np.nan, 0.0, 0.0]])
    with pytest.raises(ValueError, match=r"LayeredMap.build: all reference points coincide"):
        mlndt.LayeredMap.build(np.ones((100, 3)))


def test_register_on_a_map_refuses_grid_options(koide3, reference_map):
    with pytest.raises(ValueError, match="grid does not apply to LayeredMap.register"):
        reference_map.register(koide3[1], grid={"finest_cell_size_m": 1.0})
    with pytest.raises(ValueError, match="unknown option foo"):
        reference_map.register(koide3[1], foo=1)
    with pytest.raises(ValueError, match="input: no points"):
        reference_map.register(np.empty((0, 3)))


def test_save_and_load(tmp_path, koide3, reference_map):
    path = tmp_path / "koide3.mlndtmap"
    reference_map.save(path)  # os.PathLike
    loaded = mlndt.LayeredMap.load(str(path))
    # The file keeps the occupied cells, not the counts of sparse ones.
    kept = ("layer", "cell_size_m", "dims", "occupied_cells")
    assert [{k: layer[k] for k in kept} for layer in loaded.layers] == [
        {k: layer[k] for k in kept} for layer in reference_map.layers
    ]
    # The file keeps q, n, the cell minimum and the regularisation (n as a
    # number: a finest cell size is resolved).
    for key in ("division_constant", "min_points_per_cell", "regularization"):
        assert loaded.options[key] == reference_map.options[key], key
    assert loaded.options["num_layers"] == reference_map.num_layers
    np.testing.assert_array_equal(loaded.bounds, reference_map.bounds)
    assert loaded.num_points == reference_map.num_points
    for layer in range(1, loaded.num_layers + 1):
        np.testing.assert_array_equal(loaded.cells(layer)["means"], reference_map.cells(layer)["means"])
        np.testing.assert_array_equal(loaded.cells(layer)["counts"], reference_map.cells(layer)["counts"])
    on_loaded = loaded.register(koide3[1])
    on_built = reference_map.register(koide3[1])
    assert on_loaded.termination_type == on_built.termination_type
    np.testing.assert_allclose(on_loaded.reference_from_input, on_built.reference_from_input, atol=1e-9)


def test_load_and_save_errors(tmp_path, reference_map):
    with pytest.raises(FileNotFoundError, match="missing.mlndtmap"):
        mlndt.LayeredMap.load(tmp_path / "missing.mlndtmap")
    garbage = tmp_path / "garbage.mlndtmap"
    garbage.write_bytes(b"not a map at all")
    with pytest.raises(OSError, match="garbage.mlndtmap"):
        mlndt.LayeredMap.load(garbage)
    good = tmp_path / "good.mlndtmap"
    reference_map.save(good)
    truncated = tmp_path / "truncated.mlndtmap"
    truncated.write_bytes(good.read_bytes()[:-100])
    with pytest.raises(OSError, match="truncated.mlndtmap"):
        mlndt.LayeredMap.load(truncated)
    with pytest.raises(FileNotFoundError, match="no_such_folder"):
        reference_map.save(tmp_path / "no_such_folder" / "map.mlndtmap")
    with pytest.raises(TypeError):
        reference_map.save(42)


def test_build_refuses_a_map_over_its_memory_limit(koide3):
    """The build's memory is estimated first, as mlndt_map's --max_memory_gb:
    over the limit a MemoryError names the amounts; 0 is no limit."""
    points = koide3[0]
    with pytest.raises(MemoryError, match=r"LayeredMap.build: .*exceeds the memory limit of 1.0 kB"):
        mlndt.LayeredMap.build(points, max_memory_gb=1e-6)
    with pytest.raises(ValueError, match=r"max_memory_gb"):
        mlndt.LayeredMap.build(points, max_memory_gb=-1.0)
    assert mlndt.LayeredMap.build(points, max_memory_gb=0).num_layers == \
        mlndt.LayeredMap.build(points).num_layers


def test_build_refuses_a_map_that_cannot_be_used(koide3, tmp_path):
    """Issue 27 item 3: a 1e300 point (the map's cells would be infinite) or
    too few points for one cell give no map, instead of one save writes and
    load refuses."""
    points = np.vstack([koide3[0], [[1e300, 0.0, 0.0]]])
    with pytest.raises(ValueError, match=r"LayeredMap.build: the map is not usable: .*beyond 1e\+08 m"):
        mlndt.LayeredMap.build(points)
    five = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 1.0]]
    with pytest.raises(ValueError, match=r"LayeredMap.build: the map is not usable: the map has 0 occupied cells"):
        mlndt.LayeredMap.build(five)
    assert list(tmp_path.iterdir()) == []
