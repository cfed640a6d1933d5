"""mlndt.distributed on a distributed.LocalCluster of 2 worker processes (one
thread each): every pair of the bundled KITTI frames registered, and frames
1-7 localised against the saved map of frame 0, give exactly the sequential
run's poses, scores and verdicts, with both workers busy. Skips only when
Dask is not importable."""

import numpy as np
import pytest

import mlndt
import mlndt.distributed as md
from conftest import KITTI_PAIRS, KITTI_SCANS, reference_transform, translation_error_m

distributed = pytest.importorskip("distributed", reason="Dask distributed is not installed (python3-distributed)")

# Consecutive pairs, skips of 2 and 3 frames: 18 registrations, 8 references.
PAIRS = [(i, i + 1) for i in range(7)] + [(i, i + 2) for i in range(6)] + [(i, i + 3) for i in range(5)]


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=40
    )
    with distributed.Client(cluster) as c:
        yield c
    cluster.close()


def same(a, b, pose):
    return (
        np.array_equal(getattr(a, pose), getattr(b, pose))
        and a.score == b.score
        and a.termination == b.termination
        and a.iterations == b.iterations
    )


def test_pairs_on_two_workers_equal_the_sequential_run(client):
    sequential = md.register_pairs(KITTI_SCANS, PAIRS)
    fanned_out = md.register_pairs(KITTI_SCANS, PAIRS, client=client)
    assert [(r.reference, r.input) for r in fanned_out] == PAIRS
    assert all(same(a, b, "reference_from_input") for a, b in zip(sequential, fanned_out))
    assert {r.worker for r in sequential} == {"local"}
    busy = md.tasks_per_worker(fanned_out)
    assert len(busy) == 2 and set(busy) == set(client.scheduler_info()["workers"]), busy
    # The same as mlndt.register on the two clouds, and right.
    first = mlndt.register(mlndt.read_cloud(KITTI_SCANS[0]), mlndt.read_cloud(KITTI_SCANS[1]))
    assert np.array_equal(first.reference_from_input, fanned_out[0].reference_from_input)
    for r in fanned_out:
        expected, _ = reference_transform(KITTI_PAIRS, f"{r.reference}_{r.input}")
        assert translation_error_m(expected, r.reference_from_input) < 0.15, (r.reference, r.input)


def test_scans_against_a_saved_map_equal_the_sequential_run(client, tmp_path):
    map_path = tmp_path / "frame0.mlndt"
    mlndt.LayeredMap.build(mlndt.filter_range(mlndt.read_cloud(KITTI_SCANS[0]))).save(map_path)
    # Guesses 0.3 m and 1 deg off the reference poses (odometry-like).
    error = mlndt.pose_from_xi([0.3, -0.2, 0.05, 0.0, 0.0, 1.0], degrees=True)
    truths = [reference_transform(KITTI_PAIRS, f"0_{k}")[0] for k in (1, 2, 3, 5)]
    guesses = np.array([t @ error for t in truths])
    scans = [KITTI_SCANS[k] for k in (1, 2, 3, 5)]
    sequential = md.localize_scans(map_path, scans, guesses)
    fanned_out = md.localize_scans(map_path, scans, guesses, client=client)
    assert all(same(a, b, "map_from_scan") for a, b in zip(sequential, fanned_out))
    assert [r.index for r in fanned_out] == [0, 1, 2, 3]
    for r, t in zip(fanned_out, truths):
        assert r.termination == "CONVERGENCE" and translation_error_m(t, r.map_from_scan) < 0.1


def test_bad_options_raise_before_any_task(client):
    with pytest.raises(ValueError, match="no_such_option"):
        md.register_pairs(KITTI_SCANS, PAIRS, client=client, no_such_option=1)
    with pytest.raises(ValueError, match=r"pairs\[0\] = \(0, 9\)"):
        md.register_pairs(KITTI_SCANS, [(0, 9)], client=client)
    with pytest.raises(ValueError, match=r"initial: expected \(2, 4, 4\)"):
        md.localize_scans("map.mlndt", KITTI_SCANS[:2], np.eye(4), client=client)


def test_a_file_rewritten_at_the_same_path_is_read_again(client, tmp_path):
    """The per-process caches are keyed by path, size and modification time:
    after a scan or a map file is rewritten, the new file's answer comes back,
    here and on the workers (the pair repeated so both workers have cached
    the old file)."""
    import shutil

    scan = tmp_path / "reference.pcd"
    pairs = [(0, 1)] * 4

    def pose_onto(frame, client=None):
        shutil.copyfile(KITTI_SCANS[frame], scan)
        results = md.register_pairs([scan, KITTI_SCANS[1]], pairs, client=client)
        return [r.reference_from_input for r in results]

    fresh = md.register_pairs([KITTI_SCANS[3], KITTI_SCANS[1]], [(0, 1)])[0].reference_from_input
    for c in (None, client):
        assert not np.array_equal(pose_onto(0, c)[0], fresh)
        again = pose_onto(3, c)
        assert all(np.array_equal(p, fresh) for p in again), c

    map_path = tmp_path / "map.mlndt"
    scans = [KITTI_SCANS[2]] * 4

    def localize_on(frame, client=None):
        mlndt.LayeredMap.build(mlndt.filter_range(mlndt.read_cloud(KITTI_SCANS[frame]))).save(map_path)
        return [r.map_from_scan for r in md.localize_scans(map_path, scans, client=client)]

    fresh_map = tmp_path / "fresh.mlndt"
    mlndt.LayeredMap.build(mlndt.filter_range(mlndt.read_cloud(KITTI_SCANS[3]))).save(fresh_map)
    expected = md.localize_scans(fresh_map, scans[:1])[0].map_from_scan
    for c in (None, client):
        old = localize_on(0, c)
        new = localize_on(3, c)
        assert not np.array_equal(old[0], expected)
        assert all(np.array_equal(p, expected) for p in new), c
