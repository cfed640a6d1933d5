"""Real ROS 1 processes for the tests: a master on the loopback with a port of
its own, the nodes, rosbag play, and recorders in the test process.

Every process is started through Processes, which stops it (SIGINT, then
SIGKILL to its process group after a timeout) when the test ends, failed or
not. Nothing waits by sleeping: wait_for polls a condition (a message count,
a connection reported by a node's own bus information) until a deadline.
"""
import os
import signal
import socket
import subprocess
import threading
import time
import xmlrpc.client

DEFAULT_TIMEOUT_S = 60.0


def wait_for(condition, what, timeout_s=DEFAULT_TIMEOUT_S, alive=()):
    """Polls `condition` until it is true; fails after timeout_s, or as soon
    as one of the processes `alive` (Popen) has exited."""
    deadline = time.monotonic() + timeout_s
    while not condition():
        for process in alive:
            if process.poll() is not None:
                raise AssertionError(f"waiting for {what}: {process.args[0]} exited with "
                                     f"code {process.returncode}")
        if time.monotonic() > deadline:
            raise AssertionError(f"waiting for {what}: not within {timeout_s} s")
        time.sleep(0.05)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Processes:
    """The processes a test started; stop_all() ends every one of them."""

    def __init__(self, env, log_dir):
        self.env = env
        self.log_dir = log_dir
        self.started = []

    def start(self, args, name):
        log = open(os.path.join(self.log_dir, f"{name}.log"), "w")
        process = subprocess.Popen([str(a) for a in args], env=self.env, stdout=log,
                                   stderr=subprocess.STDOUT, start_new_session=True)
        process.log_path = log.name
        log.close()
        self.started.append(process)
        return process

    def stop(self, process, timeout_s=15.0):
        """SIGINT (ROS's shutdown), then SIGKILL to the whole group."""
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGINT)
            try:
                process.wait(timeout=timeout_s)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait(timeout=timeout_s)
        else:
            try:  # Children it left behind (roslaunch's nodes).
                os.killpg(process.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        return process.returncode

    def stop_all(self):
        for process in reversed(self.started):
            self.stop(process)
        self.started = []


def ros_environment(prefix, work_dir, port):
    """The environment of every ROS process of the tests: a master of their
    own on the loopback, logs in work_dir, the build's mlndt_ros package."""
    env = dict(os.environ)
    env.update({
        "ROS_MASTER_URI": f"http://127.0.0.1:{port}",
        "ROS_HOSTNAME": "127.0.0.1",
        "ROS_HOME": os.path.join(work_dir, "ros_home"),
        "ROS_LOG_DIR": os.path.join(work_dir, "ros_log"),
        "ROS_PACKAGE_PATH": os.path.join(prefix, "share"),
        "CMAKE_PREFIX_PATH": prefix,
        "ROSCONSOLE_STDOUT_LINE_BUFFERED": "1",
    })
    env.pop("ROS_IP", None)
    return env


def bus_connections(node_name, topic, direction):
    """Connected connections of a node on `topic` ('o' outbound, 'i'
    inbound), from the node's own getBusInfo (what rosnode info shows)."""
    import rosgraph
    try:
        uri = rosgraph.Master("/mlndt_ros_test").lookupNode(node_name)
        info = xmlrpc.client.ServerProxy(uri).getBusInfo("/mlndt_ros_test")
    except Exception:  # Not registered yet, or shutting down.
        return 0
    return sum(1 for c in info[2] if c[4] == topic and c[2] == direction and c[5])


class Recorder:
    """Every message of a topic received by the test process."""

    def __init__(self, topic, message_type):
        import rospy
        self.topic = topic
        self.messages = []
        self._lock = threading.Lock()
        self._subscriber = rospy.Subscriber(topic, message_type, self._receive,
                                            queue_size=1000, tcp_nodelay=True)

    def _receive(self, message):
        with self._lock:
            self.messages.append(message)

    def count(self):
        with self._lock:
            return len(self.messages)

    def snapshot(self):
        with self._lock:
            return list(self.messages)

    def close(self):
        self._subscriber.unregister()
