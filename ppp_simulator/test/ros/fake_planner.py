#!/usr/bin/python3
"""A misbehaving planner for the planner bridge's fault tests (docs/reference/planner-interface.md).

~mode  silent    subscribes to the goal and advertises the plan, but never publishes a path
       straight  answers every goal with the straight line from the robot to the goal (through any wall)
       unstamped answers every goal with simple_planner.py's path, but leaves the path's stamp 0
       die_once  a breadth-first planner (simple_planner.py's search), except that the first instance ever (no
                 ~marker file yet) SIGKILLs itself on its second goal: a planner killed mid-episode
~marker  file that records the death in die_once mode (required there)
~answer  path (default) or cmd_vel: a local planner answering each goal with a geometry_msgs/TwistStamped on
         cmd_vel stamped with the goal's stamp, in modes silent, straight (the velocity points at the goal),
         follow (towards the next cell of simple_planner.py's path), nan (linear.x NaN), fast (5,000 m/s) and
         give_up (an actionlib_msgs/GoalStatus ABORTED on planner_status instead of a command)
"""
import math
import os
import signal
import sys

import rospkg
import rospy
from actionlib_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped, TwistStamped
from nav_msgs.msg import OccupancyGrid, Odometry, Path

sys.path.insert(0, os.path.join(rospkg.RosPack().get_path("ppp_agents"), "scripts"))
from simple_planner import shortest_path  # noqa: E402 (the example planner's search)


class FakePlanner:
    def __init__(self):
        self.mode = rospy.get_param("~mode")
        self.answer = rospy.get_param("~answer", "path")
        modes = {"path": ("silent", "straight", "unstamped", "die_once"),
                 "cmd_vel": ("silent", "straight", "follow", "nan", "fast", "give_up")}
        if self.answer not in modes:
            raise SystemExit("~answer: expected path or cmd_vel, got %r" % self.answer)
        if self.mode not in modes[self.answer]:
            raise SystemExit("~mode: expected one of %s, got %r" % (", ".join(modes[self.answer]), self.mode))
        self.marker = rospy.get_param("~marker", "")
        if self.mode == "die_once" and not self.marker:
            raise SystemExit("~marker: required in die_once mode")
        self.doomed = self.mode == "die_once" and not os.path.exists(self.marker)
        self.answered = 0
        self.odom = None
        self.map = None
        if self.answer == "cmd_vel":
            self.command = rospy.Publisher("cmd_vel", TwistStamped, queue_size=10)
            self.status = rospy.Publisher("planner_status", GoalStatus, queue_size=10)
        else:
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
        if self.answer == "cmd_vel" and self.mode == "give_up":
            status = GoalStatus(status=GoalStatus.ABORTED, text="no way through")
            status.goal_id.stamp = goal.header.stamp
            self.status.publish(status)
            return
        if self.answer == "cmd_vel":
            self.command.publish(self.velocity(goal, pose))
            return
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

    def velocity(self, goal, pose):
        """The command answering `goal` with the robot at `pose`, as the mode says."""
        command = TwistStamped()
        command.header.stamp = goal.header.stamp
        if self.mode == "nan":
            command.twist.linear.x = math.nan
        elif self.mode == "fast":
            command.twist.linear.x = 5000.0
        elif self.mode == "straight":
            command.twist.linear.x = goal.pose.position.x - pose.position.x
            command.twist.linear.y = goal.pose.position.y - pose.position.y
        else:
            cell = lambda p: (int(p.x), int(p.y))  # 1 m cells, origin (0, 0)
            path = shortest_path(self.map, cell(pose.position), cell(goal.pose.position))
            if len(path) > 1:
                command.twist.linear.x = path[1][0] + 0.5 - pose.position.x
                command.twist.linear.y = path[1][1] + 0.5 - pose.position.y
        return command

    def ready(self, stamp):
        return (self.odom is not None and self.odom.header.stamp >= stamp and self.map is not None
                and self.map.header.stamp >= stamp)


if __name__ == "__main__":
    rospy.init_node("fake_planner")
    FakePlanner()
    rospy.spin()
