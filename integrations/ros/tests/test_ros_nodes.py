"""mlndt_odometry_node and mlndt_localizer_node as real ROS 1 processes (a
master of their own on the loopback, rosbag play, roslaunch), against the
tools on the same bags: the odometry's poses are mlndt_odometry's and the
localiser's are mlndt_localize's, bit for bit (the same clouds decoded by
the same function, the same library calls); tf holds the same transforms; a
bag with a dropped message, a repeated stamp and an empty cloud gets warnings
on /rosout, not a crash; a DEGENERATE result moves nothing.

The bags are written by tools/mlndt_bag.py from the bundled KITTI frames
(data/kitti, every 3rd point). Run through ctest (integrations/ros/tests/CMakeLists.txt sets
MLNDT_TOOLS_DIR and MLNDT_ROS_PREFIX), or by hand with those two set.
"""
import csv
import os
import pathlib
import subprocess

import pytest

from ros_harness import (Processes, Recorder, bus_connections, free_port, ros_environment,
                         wait_for)

SOURCE = pathlib.Path(__file__).resolve().parents[3]
TOOLS = pathlib.Path(os.environ.get("MLNDT_TOOLS_DIR", SOURCE / "build" / "tools"))
PREFIX = pathlib.Path(os.environ.get("MLNDT_ROS_PREFIX", SOURCE / "build" / "ros"))
NODES = PREFIX / "lib" / "mlndt_ros"
KITTI = SOURCE / "data" / "kitti"
TOPIC = "/velodyne_points"
FRAME = "velodyne"
RUN_TIMEOUT_S = 120

pytestmark = pytest.mark.skipif(
    not (NODES / "mlndt_odometry_node").exists() or not (TOOLS / "mlndt_odometry").exists(),
    reason=f"the nodes ({NODES}) or the tools ({TOOLS}) are not built "
           "(configure with -DMLNDT_WITH_ROS=ON; scripts/check_ros.sh)")


# ---------------------------------------------------------------- inputs

SCAN_STRIDE = 3  # Every 3rd point of the KITTI frames: the test runs 3x faster.


def decimated_kitti_scans(folder):
    """The bundled KITTI frames, x/y/z of every SCAN_STRIDE-th point, as
    binary PCD files in `folder` (real scans, smaller)."""
    import importlib.util

    import numpy as np
    spec = importlib.util.spec_from_file_location("mlndt_bag", SOURCE / "tools" / "mlndt_bag.py")
    mlndt_bag = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mlndt_bag)
    paths = []
    for i in range(8):
        points = mlndt_bag.read_pcd(str(KITTI / "pcd" / f"{i:06d}.pcd"))[::SCAN_STRIDE]
        xyz = np.zeros(len(points), dtype=[("x", "<f4"), ("y", "<f4"), ("z", "<f4")])
        for axis in "xyz":
            xyz[axis] = points[axis]
        path = folder / f"{i:06d}.pcd"
        with open(path, "wb") as f:
            f.write(("VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                     f"WIDTH {len(xyz)}\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\n"
                     f"POINTS {len(xyz)}\nDATA binary\n").encode("ascii"))
            f.write(xyz.tobytes())
        paths.append(path)
    return paths


def write_floor_pcd(path):
    """A flat floor 20 m x 20 m at the road's height below the sensor: a
    scan that constrains no translation along it (DEGENERATE)."""
    points = [(0.25 * a, 0.25 * b, -1.73) for a in range(-40, 41) for b in range(-40, 41)]
    with open(path, "w") as f:
        f.write("VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                f"WIDTH {len(points)}\nHEIGHT 1\nPOINTS {len(points)}\nDATA ascii\n")
        f.writelines(f"{x} {y} {z}\n" for x, y, z in points)
    return path


def write_empty_pcd(path):
    with open(path, "w") as f:
        f.write("VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                "WIDTH 0\nHEIGHT 1\nPOINTS 0\nDATA ascii\n")
    return path


def make_bag(path, scans, stamps, point_times="none"):
    times = f"{path}.times"
    with open(times, "w") as f:
        f.writelines(f"{s!r}\n" for s in stamps)
    done = subprocess.run(
        ["/usr/bin/python3", SOURCE / "tools" / "mlndt_bag.py", f"--output={path}",
         f"--times={times}", f"--topic={TOPIC}", f"--frame_id={FRAME}",
         f"--point_times={point_times}", *scans],
        capture_output=True, text=True, timeout=RUN_TIMEOUT_S)
    assert done.returncode == 0, done.stderr
    return path


def run_tool(name, *args):
    done = subprocess.run([TOOLS / name, *[str(a) for a in args]], capture_output=True,
                          text=True, timeout=RUN_TIMEOUT_S)
    assert done.returncode in (0, 1), f"{name}: {done.stderr}"
    return done


def read_tum(path):
    with open(path) as f:
        return [[float(v) for v in line.split()] for line in f if not line.startswith("#")]


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


_TOOL_RUNS = {}


def tool_odometry(work, bag, name, *flags):
    """mlndt_odometry's trajectory and scans.csv (each run once per module)."""
    key = ("mlndt_odometry", str(bag), flags)
    if key in _TOOL_RUNS:
        return _TOOL_RUNS[key]
    out = work / name
    run_tool("mlndt_odometry", f"--bag={bag}", f"--topic={TOPIC}", f"--output_dir={out}",
             "--plots=false", *flags)
    _TOOL_RUNS[key] = read_tum(out / "trajectory_tum.txt"), read_csv(out / "scans.csv")
    return _TOOL_RUNS[key]


def tool_localize(work, bag, name, map_path, guess):
    """mlndt_localize's trajectory and scans.csv (each run once per module)."""
    key = ("mlndt_localize", str(bag), str(map_path), guess)
    if key in _TOOL_RUNS:
        return _TOOL_RUNS[key]
    out = work / name
    run_tool("mlndt_localize", f"--map={map_path}", f"--bag={bag}", f"--topic={TOPIC}",
             f"--output_dir={out}", "--plots=false", f"--initial_guess={guess}")
    _TOOL_RUNS[key] = read_tum(out / "trajectory_tum.txt"), read_csv(out / "scans.csv")
    return _TOOL_RUNS[key]


@pytest.fixture(scope="module")
def work(tmp_path_factory):
    return tmp_path_factory.mktemp("mlndt_ros")


@pytest.fixture(scope="module")
def scans(work):
    folder = work / "scans"
    folder.mkdir()
    return decimated_kitti_scans(folder)


@pytest.fixture(scope="module")
def bags(work, scans):
    """clean: frames 0-7 at 10 Hz with a per-point time ramp (deskewed).
    faulty: the same with frame 4 dropped, frame 1 again with its stamp and
    an empty cloud; faulty_reference: what the odometry should use of it.
    floor: frames 0-6 with frame 3 replaced by a flat floor."""
    stamps = [1000.0 + 0.1 * k for k in range(8)]
    floor = write_floor_pcd(work / "floor.pcd")
    empty = write_empty_pcd(work / "empty.pcd")
    kept = [0, 1, 2, 3, 5, 6, 7]
    return {
        "clean": make_bag(work / "clean.bag", [scans[k] for k in range(8)], stamps,
                          "step:1e-6"),
        "faulty": make_bag(
            work / "faulty.bag",
            [scans[k] for k in (0, 1, 1)] + [empty] + [scans[k] for k in kept[2:]],
            stamps[:2] + [stamps[1], stamps[1] + 0.05] + [stamps[k] for k in kept[2:]],
            "step:1e-6"),
        "faulty_reference": make_bag(work / "faulty_reference.bag",
                                     [scans[k] for k in kept], [stamps[k] for k in kept],
                                     "step:1e-6"),
        "floor": make_bag(work / "floor.bag",
                          [scans[k] for k in (0, 1, 2)] + [floor] +
                          [scans[k] for k in (4, 5, 6)], stamps[:7]),
    }


@pytest.fixture(scope="module")
def kitti_map(work, scans):
    path = work / "kitti.mlndt"
    run_tool("mlndt_map", f"--scans={scans[0].parent}", f"--poses={KITTI / 'poses_velo.txt'}",
             f"--output={path}")
    return path


# ---------------------------------------------------------------- ROS

class Ros:
    def __init__(self, env, work):
        self.env = env
        self.work = work


@pytest.fixture(scope="module")
def ros(work):
    """A master (roscore) of the module's own; the test process is a ROS node."""
    env = ros_environment(str(PREFIX), str(work), free_port())
    processes = Processes(env, str(work))
    master = processes.start(["roscore", "-p", env["ROS_MASTER_URI"].rsplit(":", 1)[1]],
                             "roscore")
    try:
        for key in ("ROS_MASTER_URI", "ROS_HOSTNAME", "ROS_HOME", "ROS_LOG_DIR"):
            os.environ[key] = env[key]
        import rosgraph
        wait_for(rosgraph.is_master_online, "the master", 30, alive=[master])
        wait_for(lambda: _node_registered("/rosout"), "rosout", 30, alive=[master])
        import rospy
        rospy.init_node("mlndt_ros_test", anonymous=True, disable_signals=True)
        yield Ros(env, work)
        rospy.signal_shutdown("tests done")
    finally:
        processes.stop_all()


def _node_registered(name):
    import rosgraph
    try:
        rosgraph.Master("/mlndt_ros_test").lookupNode(name)
        return True
    except Exception:
        return False


@pytest.fixture
def processes(ros, request):
    log_dir = ros.work / request.node.name
    log_dir.mkdir(exist_ok=True)
    started = Processes(ros.env, str(log_dir))
    yield started
    started.stop_all()


@pytest.fixture
def recorders():
    made = []

    def record(topic, message_type):
        made.append(Recorder(topic, message_type))
        return made[-1]
    yield record
    for r in made:
        r.close()


def start_node(processes, executable, name, **parameters):
    import rospy
    for key, value in parameters.items():
        rospy.set_param(f"/{name}/{key}", value)
    return processes.start([NODES / executable, f"__name:={name}", f"points:={TOPIC}"], name)


def play(processes, bag, name, subscribers, outputs, alive):
    """rosbag play, started paused and resumed only when every node in
    `subscribers` is connected to it and every (node, topic, n) in `outputs`
    has n subscribers connected (the test process and, for /rosout, the
    rosout node; for /tf, other nodes' tf listeners)."""
    import rospy
    from std_srvs.srv import SetBool
    player = processes.start(["rosbag", "play", "--pause", "--wait-for-subscribers", bag,
                              f"__name:={name}"], name)
    alive = list(alive) + [player]
    for node, topic, n in outputs:
        wait_for(lambda: bus_connections(f"/{node}", topic, "o") >= n,
                 f"{n} subscribers of {node} on {topic}", alive=alive)
    wait_for(lambda: bus_connections(f"/{name}", TOPIC, "o") >= len(subscribers),
             f"{subscribers} subscribed to {name}", alive=alive)
    rospy.wait_for_service(f"/{name}/pause_playback", timeout=30)
    rospy.ServiceProxy(f"/{name}/pause_playback", SetBool)(False)
    return player


def stamp_s(stamp):
    """ros::Time::toSec's arithmetic, so stamps compare exactly."""
    return float(stamp.secs) + 1e-9 * float(stamp.nsecs)


def pose_row(stamp, position, orientation):
    return [stamp_s(stamp), position.x, position.y, position.z,
            orientation.x, orientation.y, orientation.z, orientation.w]


def transform_rows(tf_recorder, parent, child):
    rows = []
    for message in tf_recorder.snapshot():
        for t in message.transforms:
            if t.header.frame_id == parent and t.child_frame_id == child:
                rows.append(pose_row(t.header.stamp, t.transform.translation,
                                     t.transform.rotation))
    return rows


def node_warnings(log_recorder, node):
    from rosgraph_msgs.msg import Log
    return [m.msg for m in log_recorder.snapshot() if m.name == f"/{node}" and m.level == Log.WARN]


def verdicts(diagnostic_recorder, node_name):
    found = []
    for message in diagnostic_recorder.snapshot():
        for status in message.status:
            if status.name == node_name:
                values = {v.key: v.value for v in status.values}
                found.append((float(values["stamp_s"]), values["termination_type"], status.level))
    return found


# ---------------------------------------------------------------- tests

def test_odometry_node_gives_mlndt_odometrys_poses_and_tf(ros, bags, work, processes, recorders):
    """Non-default parameters under the tools' flag names, on both sides."""
    from diagnostic_msgs.msg import DiagnosticArray
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import PointCloud2
    from tf2_msgs.msg import TFMessage
    expected, scans = tool_odometry(work, bags["clean"], "tool_clean",
                                    "--local_map_max_keyframes=3", "--gate_factor=4")
    default, _ = tool_odometry(work, bags["clean"], "tool_clean_default")
    assert expected[-1][1:4] != default[-1][1:4], "the flags changed nothing"

    odom = recorders("/odom", Odometry)
    tf = recorders("/tf", TFMessage)
    diagnostics = recorders("/diagnostics", DiagnosticArray)
    local_map = recorders("/local_map", PointCloud2)
    node = start_node(processes, "mlndt_odometry_node", "odometry_a", queue_size=100,
                      local_map_max_keyframes=3, gate_factor=4.0, local_map_period_s=0.3)
    play(processes, bags["clean"], "player_a", ["odometry_a"],
         [("odometry_a", "/odom", 1), ("odometry_a", "/tf", 1),
          ("odometry_a", "/diagnostics", 1)],
         alive=[node])
    wait_for(lambda: odom.count() == len(expected), "8 odometry messages", alive=[node])
    wait_for(lambda: len(transform_rows(tf, "odom", FRAME)) == len(expected), "8 transforms",
             alive=[node])

    messages = odom.snapshot()
    assert [pose_row(m.header.stamp, m.pose.pose.position, m.pose.pose.orientation)
            for m in messages] == expected
    assert all(m.header.frame_id == "odom" and m.child_frame_id == FRAME for m in messages)
    # A registered pose has no covariance in the report yet: marked
    # unknown (element 0 = -1) as ROS marks one.
    assert all(m.pose.covariance[0] == -1.0 for m in messages)
    assert transform_rows(tf, "odom", FRAME) == expected
    assert [(s, v) for s, v, _ in verdicts(diagnostics, "mlndt_odometry: scan verdict")] == \
        [(round(float(r["stamp_s"]), 9), r["termination_type"]) for r in scans]
    maps = local_map.snapshot()
    assert 2 <= len(maps) <= 4 and all(m.header.frame_id == "odom" for m in maps)
    assert maps[-1].width > 1000
    assert node.poll() is None


def test_roslaunch_odometry_launch_plays_a_bag(ros, bags, work, processes, recorders):
    """roslaunch mlndt_ros odometry.launch bag:=... as docs/ros.md gives it;
    the latched path of every pose is mlndt_odometry's trajectory."""
    import rospy
    from nav_msgs.msg import Path
    from std_srvs.srv import SetBool
    expected, _ = tool_odometry(work, bags["clean"], "tool_clean_default")
    params = work / "launch_params.yaml"
    params.write_text("local_map_period_s: 0\nqueue_size: 100\n")
    path = recorders("/path", Path)
    launch = processes.start(["roslaunch", "mlndt_ros", "odometry.launch", f"bag:={bags['clean']}",
                              f"points:={TOPIC}", f"params:={params}", "paused:=true"],
                             "roslaunch")
    wait_for(lambda: bus_connections("/mlndt_odometry", "/path", "o") >= 1,
             "the node's path to the test", alive=[launch])
    wait_for(lambda: bus_connections("/rosbag_play", TOPIC, "o") >= 1,
             "the node subscribed to the bag", alive=[launch])
    rospy.wait_for_service("/rosbag_play/pause_playback", timeout=30)
    rospy.ServiceProxy("/rosbag_play/pause_playback", SetBool)(False)
    wait_for(lambda: path.count() > 0 and len(path.snapshot()[-1].poses) == len(expected),
             "a path of 8 poses", alive=[launch])
    poses = path.snapshot()[-1].poses
    assert [pose_row(p.header.stamp, p.pose.position, p.pose.orientation)
            for p in poses] == expected
    assert processes.stop(launch) == 0


def test_odometry_node_warns_on_a_faulty_bag(ros, bags, work, processes, recorders):
    """Dropped frame 4, frame 1 repeated with its stamp, an empty cloud:
    three warnings, one diagnostic per message, and the poses of
    mlndt_odometry on the frames the node could use."""
    from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
    from nav_msgs.msg import Odometry
    from rosgraph_msgs.msg import Log
    expected, _ = tool_odometry(work, bags["faulty_reference"], "tool_faulty")
    failed = subprocess.run([TOOLS / "mlndt_odometry", f"--bag={bags['faulty']}",
                             f"--topic={TOPIC}", f"--output_dir={work / 'tool_faulty_fails'}",
                             "--plots=false"], capture_output=True, text=True,
                            timeout=RUN_TIMEOUT_S)
    assert failed.returncode == 2, "the tool refuses the repeated stamp before any work"

    odom = recorders("/odom", Odometry)
    diagnostics = recorders("/diagnostics", DiagnosticArray)
    logs = recorders("/rosout", Log)
    node = start_node(processes, "mlndt_odometry_node", "odometry_f", queue_size=100)
    play(processes, bags["faulty"], "player_f", ["odometry_f"],
         [("odometry_f", "/odom", 1), ("odometry_f", "/diagnostics", 1),
          ("odometry_f", "/rosout", 2)],
         alive=[node])
    wait_for(lambda: len(verdicts(diagnostics, "mlndt_odometry: scan verdict")) == 9,
             "a diagnostic per message", alive=[node])
    wait_for(lambda: len(node_warnings(logs, "odometry_f")) >= 3, "3 warnings", alive=[node])

    assert [pose_row(m.header.stamp, m.pose.pose.position, m.pose.pose.orientation)
            for m in odom.snapshot()] == expected
    found = verdicts(diagnostics, "mlndt_odometry: scan verdict")
    assert [v for _, v, _ in found].count("REFUSED") == 2
    assert [level for _, v, level in found if v == "REFUSED"] == [DiagnosticStatus.ERROR] * 2
    warnings = "\n".join(node_warnings(logs, "odometry_f"))
    assert "not after the last scan's" in warnings
    assert "no finite points" in warnings
    assert "gap of 0.200000 s" in warnings
    assert node.poll() is None, "the node is still running"


def test_localizer_with_odometry_gives_mlndt_localizes_poses(ros, bags, work, kitti_map,
                                                             processes, recorders):
    """The localiser and the odometry together: /pose is mlndt_localize's
    trajectory, and tf's map -> odom -> sensor composes to it."""
    from geometry_msgs.msg import PoseWithCovarianceStamped
    from tf2_msgs.msg import TFMessage
    guess = "0.1,0,0,0,0,1"
    expected, _ = tool_localize(work, bags["clean"], "tool_localize", kitti_map, guess)
    pose = recorders("/pose", PoseWithCovarianceStamped)
    tf = recorders("/tf", TFMessage)
    odometry = start_node(processes, "mlndt_odometry_node", "odometry_l", queue_size=100)
    localizer = start_node(processes, "mlndt_localizer_node", "localizer_l", queue_size=100,
                           map=str(kitti_map), initial_guess=guess, tf_timeout_s=60.0)
    alive = [odometry, localizer]
    play(processes, bags["clean"], "player_l", ["odometry_l", "localizer_l"],
         [("localizer_l", "/pose", 1), ("localizer_l", "/tf", 1), ("odometry_l", "/tf", 2)],
         alive)
    wait_for(lambda: pose.count() == len(expected), "8 poses", alive=alive)
    wait_for(lambda: len(transform_rows(tf, "map", "odom")) == len(expected),
             "8 map -> odom", alive=alive)

    messages = pose.snapshot()
    assert [pose_row(m.header.stamp, m.pose.pose.position, m.pose.pose.orientation)
            for m in messages] == expected
    assert all(m.header.frame_id == "map" and m.pose.covariance[0] > 0 for m in messages)
    map_odom = {r[0]: r for r in transform_rows(tf, "map", "odom")}
    odom_sensor = {r[0]: r for r in transform_rows(tf, "odom", FRAME)}
    for row in expected:
        composed = _compose(map_odom[row[0]], odom_sensor[row[0]])
        assert _distance(composed, row) < 1e-9, (row, composed)


def test_localizer_alone_refuses_to_jump_and_takes_the_initial_pose(ros, bags, work,
                                                                    kitti_map, processes,
                                                                    recorders):
    """Without ~initial_guess the localiser waits for /initialpose; the flat
    floor scan is DEGENERATE: no pose, no map -> sensor, a warning and the
    diagnostic; every other scan is mlndt_localize's."""
    import rospy
    from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
    from geometry_msgs.msg import PoseWithCovarianceStamped
    from rosgraph_msgs.msg import Log
    from tf2_msgs.msg import TFMessage
    expected, scans = tool_localize(work, bags["floor"], "tool_floor", kitti_map, "0,0,0,0,0,0")
    assert [r["registration.termination_type"] for r in scans].count("DEGENERATE") == 1
    usable = [row for row, r in zip(expected, scans)
              if r["registration.termination_type"] in ("CONVERGENCE", "NO_CONVERGENCE")]
    assert len(usable) == len(expected) - 1

    pose = recorders("/pose", PoseWithCovarianceStamped)
    tf = recorders("/tf", TFMessage)
    diagnostics = recorders("/diagnostics", DiagnosticArray)
    logs = recorders("/rosout", Log)
    localizer = start_node(processes, "mlndt_localizer_node", "localizer_f", queue_size=100,
                           map=str(kitti_map), odom_frame="")
    initial = rospy.Publisher("/initialpose", PoseWithCovarianceStamped, queue_size=1)
    wait_for(lambda: bus_connections("/localizer_f", "/initialpose", "i") >= 1 and
             bus_connections("/localizer_f", "/rosout", "o") >= 2,
             "the localiser connected to the test", alive=[localizer])
    start = PoseWithCovarianceStamped()
    start.header.frame_id = "map"
    start.pose.pose.orientation.w = 1.0
    initial.publish(start)
    wait_for(lambda: any("localising from the initial pose" in m.msg
                         for m in logs.snapshot() if m.name == "/localizer_f"),
             "the initial pose taken", alive=[localizer])
    play(processes, bags["floor"], "player_fl", ["localizer_f"],
         [("localizer_f", "/pose", 1), ("localizer_f", "/tf", 1),
          ("localizer_f", "/diagnostics", 1), ("localizer_f", "/rosout", 2)],
         alive=[localizer])
    name = "mlndt_localizer: scan verdict"
    wait_for(lambda: len(verdicts(diagnostics, name)) == len(expected), "7 diagnostics",
             alive=[localizer])
    wait_for(lambda: pose.count() == len(usable), "6 poses", alive=[localizer])
    # /pose and /tf are two topics: the last transform may arrive after the
    # last pose.
    wait_for(lambda: len(transform_rows(tf, "map", FRAME)) == len(usable),
             "6 map -> sensor", alive=[localizer])
    initial.unregister()

    assert [pose_row(m.header.stamp, m.pose.pose.position, m.pose.pose.orientation)
            for m in pose.snapshot()] == usable
    assert transform_rows(tf, "map", FRAME) == usable
    found = verdicts(diagnostics, name)
    assert [v for _, v, _ in found] == [r["registration.termination_type"] for r in scans]
    assert [level for _, v, level in found if v == "DEGENERATE"] == [DiagnosticStatus.WARN]
    warnings = node_warnings(logs, "localizer_f")
    assert any("DEGENERATE" in w and "no jump: map -> sensor not updated" in w
               for w in warnings), warnings


def test_roslaunch_localizer_launch_plays_a_bag(ros, bags, work, kitti_map, processes,
                                               recorders):
    """roslaunch mlndt_ros localizer.launch map:=... bag:=... as docs/ros.md
    gives it (the odometry too): /pose is mlndt_localize's trajectory."""
    import rospy
    from geometry_msgs.msg import PoseWithCovarianceStamped
    from std_srvs.srv import SetBool
    guess = "0.1,0,0,0,0,1"
    expected, _ = tool_localize(work, bags["clean"], "tool_localize", kitti_map, guess)
    pose = recorders("/pose", PoseWithCovarianceStamped)
    launch = processes.start(["roslaunch", "mlndt_ros", "localizer.launch", f"map:={kitti_map}",
                              f"bag:={bags['clean']}", f"points:={TOPIC}",
                              f"initial_guess:={guess}", "queue_size:=100", "paused:=true"],
                             "roslaunch")
    wait_for(lambda: bus_connections("/mlndt_localizer", "/pose", "o") >= 1,
             "the localiser's pose to the test", alive=[launch])
    wait_for(lambda: bus_connections("/rosbag_play", TOPIC, "o") >= 2,
             "both nodes subscribed to the bag", alive=[launch])
    rospy.wait_for_service("/rosbag_play/pause_playback", timeout=30)
    rospy.ServiceProxy("/rosbag_play/pause_playback", SetBool)(False)
    wait_for(lambda: pose.count() == len(expected), "8 poses", alive=[launch])
    assert [pose_row(m.header.stamp, m.pose.pose.position, m.pose.pose.orientation)
            for m in pose.snapshot()] == expected
    assert processes.stop(launch) == 0


def _compose(a_row, b_row):
    """TUM-like rows [t, x, y, z, qx, qy, qz, qw]: a * b."""
    import numpy as np

    def matrix(row):
        x, y, z, w = row[4:8]
        r = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                      [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                      [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
        m = np.eye(4)
        m[:3, :3] = r
        m[:3, 3] = row[1:4]
        return m
    return matrix(a_row) @ matrix(b_row)


def _distance(composed, row):
    """Largest difference of translation [m] and rotation matrix entries."""
    import numpy as np
    target = _compose(row, [0, 0, 0, 0, 0, 0, 0, 1])
    return float(np.abs(composed - target).max())
