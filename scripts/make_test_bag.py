#!/usr/bin/python3
"""Writes a small bag shaped like the simulator node's experiment.bag, for testing rviz and the screenshot script
without running an experiment: a 20 x 20 PPP on /map (latched), start/goal markers on /ppp/markers (latched),
tf map -> NAME/base_link, /NAME/path and /NAME/scan for two agents walking along the map, 3 s at 10 Hz.

Usage: scripts/make_test_bag.py OUT.bag
"""
import math
import sys

import rosbag
import rospy
from geometry_msgs.msg import PoseStamped, TransformStamped
from nav_msgs.msg import OccupancyGrid, Path
from sensor_msgs.msg import LaserScan
from tf2_msgs.msg import TFMessage
from visualization_msgs.msg import Marker, MarkerArray

SIDE = 20


def latched(msg):
    """A connection header that makes `rosbag play` latch the topic (a custom header must be complete)."""
    return {'callerid': '/simulator', 'latching': '1', 'type': msg._type, 'md5sum': msg._md5sum,
            'message_definition': msg._full_text}


def ppp_map(stamp):
    """A PPP in the map frame: row 0 at the bottom, 0 free, 100 obstacle."""
    grid = OccupancyGrid()
    grid.header.frame_id = 'map'
    grid.header.stamp = stamp
    grid.info.resolution = 1.0
    grid.info.width = grid.info.height = SIDE
    grid.info.origin.orientation.w = 1.0
    data = [0] * (SIDE * SIDE)
    obstacles = [(x, 14) for x in range(2, 14)] + [(9, y) for y in range(3, 12)] + \
                [(x, y) for x in range(14, 18) for y in range(4, 8)]
    for x, y in obstacles:
        data[y * SIDE + x] = 100
    grid.data = data
    return grid


def marker(stamp, ident, ns, x, y, rgb):
    m = Marker()
    m.header.frame_id = 'map'
    m.header.stamp = stamp
    m.ns, m.id, m.type, m.action = ns, ident, Marker.CUBE, Marker.ADD
    m.pose.position.x, m.pose.position.y, m.pose.position.z = x, y, 0.1
    m.pose.orientation.w = 1.0
    m.scale.x = m.scale.y = 0.8
    m.scale.z = 0.2
    m.color.r, m.color.g, m.color.b = rgb
    m.color.a = 1.0
    return m


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    t0 = rospy.Time(1000)
    agents = {
        'explorer': [(0.5 + min(i, 19), 19.5 - max(0, i - 19)) for i in range(30)],
        'wall_follower_left': [(0.5 + max(0, i - 19), 19.5 - min(i, 19)) for i in range(30)],
    }
    with rosbag.Bag(sys.argv[1], 'w') as bag:
        grid = ppp_map(t0)
        bag.write('/map', grid, t0, connection_header=latched(grid))
        markers = MarkerArray(markers=[marker(t0, 0, 'start', 0.5, 19.5, (0.1, 0.8, 0.1)),
                                       marker(t0, 1, 'goal', 19.5, 0.5, (0.9, 0.1, 0.1))])
        bag.write('/ppp/markers', markers, t0, connection_header=latched(markers))
        paths = {name: Path() for name in agents}
        for step in range(30):
            stamp = t0 + rospy.Duration(0.1 * step)
            tf = TFMessage()
            for name, cells in agents.items():
                x, y = cells[step]
                transform = TransformStamped()
                transform.header.stamp = stamp
                transform.header.frame_id = 'map'
                transform.child_frame_id = name + '/base_link'
                transform.transform.translation.x, transform.transform.translation.y = x, y
                transform.transform.rotation.w = 1.0
                tf.transforms.append(transform)
                pose = PoseStamped()
                pose.header = transform.header
                pose.pose.position.x, pose.pose.position.y = x, y
                pose.pose.orientation.w = 1.0
                paths[name].header.frame_id = 'map'
                paths[name].header.stamp = stamp
                paths[name].poses.append(pose)
                bag.write('/%s/path' % name, paths[name], stamp)
                scan = LaserScan()
                scan.header.stamp = stamp
                scan.header.frame_id = name + '/base_link'
                scan.angle_increment = 2 * math.pi / 72
                scan.angle_max = scan.angle_increment * 71
                scan.range_max = 3.6
                scan.ranges = [1.5 + 0.5 * math.cos(4 * scan.angle_increment * i) for i in range(72)]
                bag.write('/%s/scan' % name, scan, stamp)
            bag.write('/tf', tf, stamp)


if __name__ == '__main__':
    main()
