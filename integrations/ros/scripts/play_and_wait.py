#!/usr/bin/python3
"""Resumes a bag started paused by play_bag.launch once the odometry node
publishes its verdicts to this process, and returns when it has published
N of them (or fails after TIMEOUT s): play_and_wait.py N TIMEOUT"""
import sys
import time

import rospy
from diagnostic_msgs.msg import DiagnosticArray
from std_srvs.srv import SetBool


def main(count, timeout_s):
    rospy.init_node("mlndt_play_and_wait", anonymous=True)
    seen = []
    subscriber = rospy.Subscriber("/diagnostics", DiagnosticArray, seen.append, queue_size=1000)
    deadline = time.monotonic() + timeout_s

    def wait(condition, what):
        while not condition():
            if time.monotonic() > deadline or rospy.is_shutdown():
                sys.exit(f"play_and_wait: no {what} within {timeout_s} s")
            time.sleep(0.05)
    wait(lambda: subscriber.get_num_connections() > 0, "odometry node")
    rospy.wait_for_service("/rosbag_play/pause_playback", timeout=timeout_s)
    rospy.ServiceProxy("/rosbag_play/pause_playback", SetBool)(False)
    wait(lambda: len(seen) >= count, f"{count} verdicts")
    print(f"play_and_wait: {len(seen)} verdicts")


if __name__ == "__main__":
    main(int(sys.argv[1]), float(sys.argv[2]))
