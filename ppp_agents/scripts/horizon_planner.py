#!/usr/bin/env python3
"""A planner with a classic, rare fault, for hunting (docs/tutorials/hunt-your-planner.md): simple_planner.py with
a fixed search horizon, as planners bound their work: it gives up ("no path") on any route longer than
`~horizon` cells (default 45, a little over the 39 cells of a 20x20 map's corner-to-corner route). It fails
only where what the robot has seen forces a long detour."""
import os
import sys

import rospy

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
import simple_planner  # noqa: E402


def horizon_path(grid, start, goal):
    path = simple_planner.shortest_path(grid, start, goal)
    return path if len(path) <= horizon else []


if __name__ == "__main__":
    horizon = 45
    simple_planner.serve("horizon_planner", horizon_path,
                         lambda: globals().update(horizon=int(rospy.get_param("~horizon", 45))))
