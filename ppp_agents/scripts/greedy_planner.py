#!/usr/bin/env python3
"""A planner with a classic, rare fault, for hunting (docs/tutorials/hunt-your-planner.md): simple_planner.py's
search made greedy, always expanding the cell nearest the goal first (greedy best-first, a common shortcut for
speed). It always finds a path when there is one, but not the shortest: it fails only where its detours outgrow
the budget (with a relative budget, `budget_factor`)."""
import heapq
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
import simple_planner  # noqa: E402


def greedy_path(grid, start, goal):
    width, height = grid.info.width, grid.info.height
    came_from = {start: None}
    frontier = [(0, start)]
    while frontier:
        _, cell = heapq.heappop(frontier)
        if cell == goal:
            return simple_planner.path_to(came_from, goal)
        column, row = cell
        for c, r in ((column + 1, row), (column - 1, row), (column, row + 1), (column, row - 1)):
            if 0 <= c < width and 0 <= r < height and (c, r) not in came_from and grid.data[r * width + c] < 50:
                came_from[(c, r)] = cell
                heapq.heappush(frontier, (abs(goal[0] - c) + abs(goal[1] - r), (c, r)))
    return []


if __name__ == "__main__":
    simple_planner.serve("greedy_planner", greedy_path)
