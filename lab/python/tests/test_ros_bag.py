"""mlndt_lab.RosBag: a ROS 1 bag written at test time by the real
python3-rosbag (tests/testing/write_test_bag.py, as the C++ reader's test
does) reads point for point as the PCD files it was made from, with the header
stamps and the per-point time field; the odometry on the bag's scans (deskewed
with those times) gives mlndt_odometry --bag's poses; bad paths and topics
raise errors naming what the bag has."""

import csv
import subprocess

import numpy as np
import pytest

import mlndt
from conftest import KITTI_SCANS, SOURCE_DIR, import_lab, read_kitti_lines, run_tool

lab = import_lab()

WRITE_BAG = SOURCE_DIR / "tests" / "testing" / "write_test_bag.py"

pytestmark = pytest.mark.skipif(
    not lab.rosbag_supported(),
    reason="built without ROS bag support (MLNDT_WITH_ROSBAG=OFF; scripts/install_deps.sh installs the packages)",
)


def write_bag(path, topic, scans, *options):
    completed = subprocess.run(
        ["/usr/bin/python3", str(WRITE_BAG), str(path), topic, *options, *[str(s) for s in scans]],
        capture_output=True,
        text=True,
    )
    assert completed.returncode == 0, f"write_test_bag.py (python3-rosbag installed?): {completed.stderr}"
    return path


@pytest.fixture(scope="module")
def kitti_bag(tmp_path_factory):
    bag = tmp_path_factory.mktemp("bag") / "kitti.bag"
    return write_bag(bag, "/velodyne_points", KITTI_SCANS, "--point_time", "--other_topic=/note")


def test_bag_reads_point_for_point_as_the_pcd_files(kitti_bag):
    bag = lab.RosBag(kitti_bag, "/velodyne_points")
    assert len(bag) == len(KITTI_SCANS) == 8
    assert bag.topic == "/velodyne_points" and bag.path == str(kitti_bag)
    for i, path in enumerate(KITTI_SCANS):
        scan = bag[i]
        pcd = mlndt.read_cloud(path)
        assert scan.points.shape == pcd.shape
        assert np.array_equal(scan.points, pcd), i
        assert scan.stamp_s == pytest.approx(1000.0 + 0.1 * i, abs=1e-6)
        assert scan.frame_id == "lidar" and scan.time_field == "time"
        ramp = (np.arange(len(pcd)) * 1e-6).astype(np.float32).astype(np.float64)
        assert np.array_equal(scan.point_times, ramp), i
    assert np.array_equal(bag[-1].points, mlndt.read_cloud(KITTI_SCANS[-1]))
    assert [s.stamp_s for s in bag] == [bag[i].stamp_s for i in range(8)]  # Iterable.
    with pytest.raises(IndexError, match="message 8 of a topic with 8 messages"):
        bag[8]


def test_bag_without_time_field_has_no_point_times(tmp_path):
    bag = lab.RosBag(write_bag(tmp_path / "plain.bag", "/points", KITTI_SCANS[:1]), "/points")
    assert bag[0].point_times is None and bag[0].time_field == ""


def test_odometry_on_the_bag_equals_mlndt_odometry_bag(tmp_path, kitti_bag):
    completed = run_tool(
        "mlndt_odometry",
        f"--bag={kitti_bag}",
        "--topic=/velodyne_points",
        f"--output_dir={tmp_path}",
        "--plots=false",
    )
    assert completed.returncode == 0, completed.stderr
    bag = lab.RosBag(kitti_bag, "/velodyne_points")
    scans = list(bag)
    results = mlndt.run_odometry(
        [s.points for s in scans], stamps=[s.stamp_s for s in scans], point_times=[s.point_times for s in scans]
    )
    poses = read_kitti_lines(tmp_path / "trajectory_kitti.txt")
    with open(tmp_path / "scans.csv") as rows:
        table = list(csv.DictReader(rows))
    # Deskewed from the third scan on (the velocity needs two poses).
    assert [r.deskewed for r in results] == [False, False] + [True] * 6
    assert [row["deskewed"] == "true" for row in table] == [r.deskewed for r in results]
    assert [row["termination_type"] for row in table] == [r.termination_type for r in results]
    for k, result in enumerate(results):
        assert np.array_equal(poses[k], result.world_from_sensor), k


def test_bad_bag_arguments_raise_naming_them(tmp_path, kitti_bag):
    with pytest.raises(FileNotFoundError, match="missing.bag"):
        lab.RosBag(tmp_path / "missing.bag", "/points")
    with pytest.raises(ValueError, match=r"no messages on topic '/lidar'.*/velodyne_points \(sensor_msgs/PointCloud2\)"):
        lab.RosBag(kitti_bag, "/lidar")
    with pytest.raises(ValueError, match="topic /note is std_msgs/String, not sensor_msgs/PointCloud2"):
        lab.RosBag(kitti_bag, "/note")
    not_a_bag = tmp_path / "scan.bag"
    not_a_bag.write_bytes(KITTI_SCANS[0].read_bytes())
    with pytest.raises(ValueError, match="scan.bag"):
        lab.RosBag(not_a_bag, "/points")
