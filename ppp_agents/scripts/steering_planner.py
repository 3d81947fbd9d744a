#!/usr/bin/env python3
"""A local planner on simulated time for the PPP Lab planner bridge in continuous motion
(docs/tutorials/a-local-planner-on-simulated-time.md).

It steers a differential-drive robot towards its goal and away from what its laser sees: ten times a second of the
robot's time (rospy.Rate, with /use_sim_time set, so the bridge's clock drives it) it turns towards the goal, and
towards the more open side when something is nearer than `~clearance` metres ahead, and publishes the command on
`cmd_vel` (geometry_msgs/TwistStamped: linear.x and angular.z in the robot's frame), stamped with the time of the
odometry it acted on. Start it in the robot's namespace with its clock there:
`rosrun ppp_agents steering_planner.py __ns:=/G/robot /clock:=/G/robot/clock`.
"""
import math
import threading

import rospy
from geometry_msgs.msg import PoseStamped, TwistStamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

newest = {"odom": None, "scan": None, "goal": None}  # the last message of each kind
arrived = threading.Condition()  # notified when a message arrives (each subscription has its own thread)


def keep(kind, message):
    """Stores the newest message of a kind and wakes the control loop waiting for it."""
    with arrived:
        newest[kind] = message
        arrived.notify_all()


def sensing_at(now):
    """The odometry, scan and goal of one control period no older than `now`, once all three of that period have
    come (the bridge sends them before its clock ticks, but on other connections, and again while it waits: acting
    on an odometry of one period and a scan of the last would depend on timing); None when shutting down."""
    def ready():
        if any(newest[k] is None for k in ("odom", "scan", "goal")):
            return False
        stamps = {newest[k].header.stamp for k in ("odom", "scan", "goal")}
        return len(stamps) == 1 and stamps.pop() >= now
    with arrived:
        while not arrived.wait_for(ready, timeout=0.5):
            if rospy.is_shutdown():
                return None
        return newest["odom"], newest["scan"], newest["goal"]


def heading_of(odom):
    q = odom.pose.pose.orientation
    return 2 * math.atan2(q.z, q.w)


def nearest_within(scan, low, high):
    """The nearest return among the beams between the angles `low` and `high` (radians from the heading)."""
    nearest = math.inf
    for i, r in enumerate(scan.ranges):
        angle = scan.angle_min + i * scan.angle_increment
        if low <= angle <= high and r < nearest:
            nearest = r
    return nearest


def command(odom, scan, goal, clearance, top_speed, top_turn):
    """linear.x and angular.z for the robot at `odom` seeing `scan`, bound for `goal`."""
    x, y = odom.pose.pose.position.x, odom.pose.pose.position.y
    error = math.atan2(goal.pose.position.y - y, goal.pose.position.x - x) - heading_of(odom)
    error = math.atan2(math.sin(error), math.cos(error))
    if nearest_within(scan, -0.5, 0.5) < clearance:  # blocked ahead: turn towards the more open side
        left, right = nearest_within(scan, 0.5, 2.0), nearest_within(scan, -2.0, -0.5)
        return 0.0, top_turn if left >= right else -top_turn
    turn = max(-top_turn, min(top_turn, 2.0 * error))
    return top_speed * max(0.0, math.cos(error)), turn


def main():
    rospy.init_node("steering_planner")
    clearance = rospy.get_param("~clearance", 0.45)
    top_speed = rospy.get_param("~top_speed", 0.4)
    top_turn = rospy.get_param("~top_turn", 1.2)
    commands = rospy.Publisher("cmd_vel", TwistStamped, queue_size=10)
    rospy.Subscriber("odom", Odometry, lambda m: keep("odom", m), queue_size=10)
    rospy.Subscriber("scan", LaserScan, lambda m: keep("scan", m), queue_size=10)
    rospy.Subscriber("move_base_simple/goal", PoseStamped, lambda m: keep("goal", m), queue_size=10)
    rate = rospy.Rate(10)  # ten commands a second of the robot's time
    while not rospy.is_shutdown():
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            return
        now = rospy.Time.now()
        sensing = sensing_at(now)
        if sensing is None:
            return
        odom, scan, goal = sensing
        out = TwistStamped()
        out.header.stamp = odom.header.stamp
        out.twist.linear.x, out.twist.angular.z = command(odom, scan, goal, clearance, top_speed, top_turn)
        commands.publish(out)


if __name__ == "__main__":
    main()
