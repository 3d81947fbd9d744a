#!/usr/bin/env python3
"""A minimal planner for the PPP Lab planner bridge (docs/reference/planner-interface.md).

On each goal it searches the map breadth-first for a shortest path of 4-connected cells, treating
unknown cells as free, and publishes the centre of every cell of it on `plan` (an empty Path when
there is none). Start it in the robot's namespace, e.g. `rosrun ppp_agents simple_planner.py __ns:=/G/robot`.
"""
from collections import deque
import threading

import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import OccupancyGrid, Odometry, Path

newest = {"map": None, "odom": None}  # the last message of each kind
arrived = threading.Condition()  # notified when a map or odometry arrives (each subscription has its own thread)


def keep(kind, message):
    """Stores the newest message of a kind and wakes a goal waiting for it."""
    with arrived:
        newest[kind] = message
        arrived.notify_all()


def wait_for(kind, stamp):
    """The newest message of a kind once it is stamped no earlier than `stamp` (or after 1 s, the newest)."""
    with arrived:
        arrived.wait_for(lambda: newest[kind] is not None and newest[kind].header.stamp >= stamp, timeout=1.0)
        return newest[kind]


def path_to(came_from, cell):
    """The cells from the search's start to `cell`, following `came_from` (each cell's predecessor) back."""
    path = []
    while cell is not None:
        path.append(cell)
        cell = came_from[cell]
    return path[::-1]


def shortest_path(grid, start, goal, neighbours=None):
    """Breadth-first search: the (column, row) cells from start to goal, or [] when the goal is walled off.
    Row 0 is the bottom row; cells of occupancy 50 or more are obstacles, unknown (-1) counts as free.
    `neighbours(cell)` gives the cells a step may reach (default: the four beside it on the map)."""
    width, height = grid.info.width, grid.info.height
    if neighbours is None:
        neighbours = lambda cell: [(c, r) for c, r in ((cell[0] + 1, cell[1]), (cell[0] - 1, cell[1]),
                                                       (cell[0], cell[1] + 1), (cell[0], cell[1] - 1))
                                   if 0 <= c < width and 0 <= r < height]
    came_from = {start: None}
    queue = deque([start])
    while queue:
        cell = queue.popleft()
        if cell == goal:
            return path_to(came_from, goal)
        for c, r in neighbours(cell):
            if (c, r) not in came_from and grid.data[r * width + c] < 50:
                came_from[(c, r)] = cell
                queue.append((c, r))
    return []


def on_goal(goal, search=shortest_path):
    """Answers a goal with the path `search(grid, start, goal)` gives on the newest map."""
    grid = wait_for("map", goal.header.stamp)
    odom = wait_for("odom", goal.header.stamp)
    if grid is None or odom is None:
        rospy.logwarn("no map or no odometry yet: not planning")
        return
    size = grid.info.resolution  # metres per cell; the map's origin is (0, 0)

    def cell_of(position):
        return (int(position.x // size), int(position.y // size))

    path = Path()
    path.header.frame_id = "map"
    path.header.stamp = max(goal.header.stamp, grid.header.stamp)
    for column, row in search(grid, cell_of(odom.pose.pose.position), cell_of(goal.pose.position)):
        pose = PoseStamped()
        pose.header = path.header
        pose.pose.position.x = (column + 0.5) * size
        pose.pose.position.y = (row + 0.5) * size
        pose.pose.orientation.w = 1.0
        path.poses.append(pose)
    plan_publisher.publish(path)


def serve(name, search=shortest_path, read_parameters=lambda: None):
    """Runs the node `name`, answering every goal with `search`, until ROS shuts down; `read_parameters` runs
    once the node is up, to read its `~` parameters."""
    global plan_publisher
    rospy.init_node(name)
    read_parameters()
    plan_publisher = rospy.Publisher("plan", Path, queue_size=1)
    # tcp_nodelay: without it TCP may hold each small message back for 40 ms.
    rospy.Subscriber("map", OccupancyGrid, lambda message: keep("map", message), tcp_nodelay=True)
    rospy.Subscriber("odom", Odometry, lambda message: keep("odom", message), tcp_nodelay=True)
    rospy.Subscriber("move_base_simple/goal", PoseStamped, lambda goal: on_goal(goal, search), tcp_nodelay=True)
    rospy.spin()


if __name__ == "__main__":
    serve("simple_planner")
