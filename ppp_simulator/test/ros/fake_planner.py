#!/usr/bin/python3
"""A misbehaving planner for the planner bridge's fault tests (docs/reference/planner-interface.md).

~mode  silent    subscribes to the goal and advertises the plan, but never publishes a path
       straight  answers every goal with the straight line from the robot to the goal (through any wall)
       unstamped answers every goal with simple_planner.py's path, but leaves the path's stamp 0
       die_once  a breadth-first planner (simple_planner.py's search), except that the first instance ever (no
                 ~marker file yet) SIGKILLs itself on its second goal: a planner killed mid-episode
~marker  file that records the death in die_once mode (required there)
"""
import os
import signal
import sys

import rospkg
import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import OccupancyGrid, Odometry, Path

sys.path.insert(0, os.path.join(rospkg.RosPack().get_path("ppp_agents"), "scripts"))
from simple_planner import shortest_path  # noqa: E402 (the example planner's search)


class FakePlanner:
    def __init__(self):
        self.mode = rospy.get_param("~mode")
        if self.mode not in ("silent", "straight", "unstamped", "die_once"):
            raise SystemExit("~mode: expected silent, straight, unstamped or die_once, got %r" % self.mode)
        self.marker = rospy.get_param("~marker", "")
        if self.mode == "die_once" and not self.marker:
            raise SystemExit("~marker: required in die_once mode")
        self.doomed = self.mode == "die_once" and not os.path.exists(self.marker)
        self.answered = 0
        self.odom = None
        self.map = None
        self.plan = rospy.Publisher("plan", Path, queue_size=10)
        rospy.Subscriber("odom", Odometry, self.on_odom, tcp_nodelay=True)
        rospy.Subscriber("map", OccupancyGrid, self.on_map, tcp_nodelay=True)
        rospy.Subscriber("move_base_simple/goal", PoseStamped, self.on_goal, tcp_nodelay=True)

    def on_odom(self, odom):
        self.odom = odom

    def on_map(self, grid):
        self.map = grid

    def on_goal(self, goal):
        if self.mode == "silent":
            return
        if self.doomed and self.answered == 1:
            open(self.marker, "w").close()
            os.kill(os.getpid(), signal.SIGKILL)
        # The goal, the map and the pose are published with the same stamp; wait for them.
        deadline = rospy.Time.now() + rospy.Duration(1.0)
        while not self.ready(goal.header.stamp) and rospy.Time.now() < deadline:
            rospy.sleep(0.01)
        if not self.ready(goal.header.stamp):
            return
        pose = self.odom.pose.pose
        path = Path()
        path.header = goal.header
        start = PoseStamped(header=goal.header)
        start.pose = pose
        if self.mode == "straight":
            path.poses = [start, goal]
        else:
            cell = lambda p: (int(p.x), int(p.y))  # 1 m cells, origin (0, 0)
            for column, row in shortest_path(self.map, cell(pose.position), cell(goal.pose.position)):
                waypoint = PoseStamped(header=goal.header)
                waypoint.pose.position.x, waypoint.pose.position.y = column + 0.5, row + 0.5
                path.poses.append(waypoint)
        if self.mode == "unstamped":
            path.header.stamp = rospy.Time(0)
        self.answered += 1
        self.plan.publish(path)

    def ready(self, stamp):
        return (self.odom is not None and self.odom.header.stamp >= stamp and self.map is not None
                and self.map.header.stamp >= stamp)


if __name__ == "__main__":
    rospy.init_node("fake_planner")
    FakePlanner()
    rospy.spin()
