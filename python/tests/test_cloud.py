"""mlndt.read_cloud, write_cloud and filter_range: the library's readers,
writers and range filter, with its errors as Python exceptions."""

import pathlib

import numpy as np
import pytest

import mlndt
from conftest import KOIDE3_REFERENCE


def test_read_cloud_returns_float64_points(koide3):
    reference, input = koide3
    # mlndt_align prints the same counts for the bundled pair.
    assert reference.shape == (69088, 3) and input.shape == (69792, 3)
    assert reference.dtype == np.float64 and reference.flags.c_contiguous
    assert np.isfinite(reference).all()
    # The array owns the library's points (no copy out of the reader).
    assert reference.base is not None and not reference.flags.owndata
    assert reference.flags.writeable
    again = mlndt.read_cloud(pathlib.Path(KOIDE3_REFERENCE))
    np.testing.assert_array_equal(again, reference)


@pytest.mark.parametrize("extension", ["pcd", "ply"])
def test_write_then_read_keeps_float32_values(tmp_path, koide3, extension):
    points = koide3[0][:1000]
    path = tmp_path / f"cloud.{extension}"
    mlndt.write_cloud(path, points)
    read = mlndt.read_cloud(path)
    np.testing.assert_array_equal(read, points.astype(np.float32).astype(np.float64))


def test_write_accepts_float32_strided_and_empty(tmp_path, koide3):
    points = koide3[0][:500]
    wide = np.hstack([points, np.zeros((500, 1))]).astype(np.float32)
    mlndt.write_cloud(tmp_path / "strided.pcd", wide[::2, :3])
    np.testing.assert_array_equal(
        mlndt.read_cloud(tmp_path / "strided.pcd"), points[::2].astype(np.float32).astype(np.float64)
    )
    mlndt.write_cloud(tmp_path / "empty.pcd", np.empty((0, 3)))
    assert mlndt.read_cloud(tmp_path / "empty.pcd").shape == (0, 3)


def test_reads_kitti_bin_and_xyz(tmp_path):
    records = np.array([[1.0, 2.0, 3.0, 0.5], [4.0, 5.0, 6.0, 0.1], [np.nan, 0.0, 0.0, 0.0]], dtype="<f4")
    records.tofile(tmp_path / "scan.bin")
    np.testing.assert_array_equal(mlndt.read_cloud(tmp_path / "scan.bin"), [[1, 2, 3], [4, 5, 6]])
    (tmp_path / "scan.xyz").write_text("# x y z\n1 2 3\n4,5,6,7\n")
    np.testing.assert_array_equal(mlndt.read_cloud(tmp_path / "scan.xyz"), [[1, 2, 3], [4, 5, 6]])


def test_read_errors(tmp_path):
    with pytest.raises(FileNotFoundError, match=r"missing.pcd: cannot open file"):
        mlndt.read_cloud(tmp_path / "missing.pcd")
    with pytest.raises(ValueError, match=r"unknown extension '.abc'"):
        mlndt.read_cloud(tmp_path / "cloud.abc")
    bad = tmp_path / "bad.pcd"
    bad.write_text("garbage\n")
    with pytest.raises(OSError, match=r"bad.pcd: not a PCD header"):
        mlndt.read_cloud(bad)
    truncated = tmp_path / "truncated.pcd"
    mlndt.write_cloud(truncated, np.ones((100, 3)) * [1.0, 2.0, 3.0])
    truncated.write_bytes(truncated.read_bytes()[:-50])
    with pytest.raises(OSError, match=r"truncated.pcd: .*truncated"):
        mlndt.read_cloud(truncated)
    with pytest.raises(OSError, match="directory"):
        (tmp_path / "folder.pcd").mkdir()
        mlndt.read_cloud(tmp_path / "folder.pcd")
    with pytest.raises(TypeError):
        mlndt.read_cloud(42)


def test_write_errors(tmp_path):
    points = np.ones((10, 3))
    with pytest.raises(ValueError, match=r"cloud.xyz: writing XYZ is not supported"):
        mlndt.write_cloud(tmp_path / "cloud.xyz", points)
    with pytest.raises(FileNotFoundError, match="no_such_folder"):
        mlndt.write_cloud(tmp_path / "no_such_folder" / "cloud.pcd", points)
    with pytest.raises(ValueError, match=r"points: expected an array of shape \(N, 3\)"):
        mlndt.write_cloud(tmp_path / "cloud.pcd", np.ones((10, 2)))
    broken = points.copy()
    broken[3, 0] = np.nan
    with pytest.raises(ValueError, match=r"points: row 3 is not finite"):
        mlndt.write_cloud(tmp_path / "cloud.pcd", broken)
    assert not (tmp_path / "cloud.pcd").exists()


def test_filter_range():
    points = np.array([[0.0, 0.0, 0.0], [0.1, 0.0, 0.0], [1.0, 0.0, 0.0], [10.0, 0.0, 0.0], [50.0, 0.0, 0.0]])
    np.testing.assert_array_equal(mlndt.filter_range(points, saturated_range_fraction=0.0), points[2:])
    np.testing.assert_array_equal(
        mlndt.filter_range(points, min_range_m=0.05, max_range_m=20.0, saturated_range_fraction=0.0), points[1:4]
    )
    assert mlndt.filter_range(np.empty((0, 3))).shape == (0, 3)
    with pytest.raises(ValueError, match=r"invalid option: min_range_m = -1"):
        mlndt.filter_range(points, min_range_m=-1.0)
    with pytest.raises(ValueError, match=r"unknown option min_range \(RangeFilterOptions has:"):
        mlndt.filter_range(points, min_range=1.0)
