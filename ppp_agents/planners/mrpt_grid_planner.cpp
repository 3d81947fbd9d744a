#include "mrpt_grid_planner.hpp"

#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <deque>
#include <exception>
#include <mutex>
#include <string>

#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {

mrpt::maps::COccupancyGridMap2D mrptGridOf(const GridMap& map) {
  const MapFrame& frame = map.frame();
  const auto resolution = static_cast<float>(frame.resolution);
  mrpt::maps::COccupancyGridMap2D grid(0.0f, static_cast<float>(frame.width * frame.resolution), 0.0f,
                                       static_cast<float>(frame.height * frame.resolution), resolution);
  if (static_cast<int>(grid.getSizeX()) != frame.width || static_cast<int>(grid.getSizeY()) != frame.height) {
    throw Error("MRPT made a " + std::to_string(grid.getSizeX()) + "x" + std::to_string(grid.getSizeY()) +
                " grid of a " + std::to_string(frame.width) + "x" + std::to_string(frame.height) + " map");
  }
  for (int y = 0; y < frame.height; ++y) {
    for (int x = 0; x < frame.width; ++x) {
      const Cell cell{x, y};
      const MapPoint centre = map.centre(cell);
      grid.setCell(grid.x2idx(centre.x), grid.y2idx(centre.y), map.passable(cell) ? 1.0f : 0.0f);
    }
  }
  return grid;
}

MrptGridPlanner::MrptGridPlanner(double robot_radius) : robot_radius_(robot_radius) {
  if (!(robot_radius >= 0) || !std::isfinite(robot_radius)) {
    throw InvalidArgument("robot_radius",
                          "expected a finite number of map cells, at least 0, got " + std::to_string(robot_radius));
  }
}

std::vector<MapPoint> MrptGridPlanner::plan(const GridMap& map, Cell start, Cell goal) const {
  if (!map.contains(start) || !map.passable(goal)) return {};
  const MapPoint from = map.centre(start);
  const MapPoint to = map.centre(goal);
  mrpt::nav::PlannerSimple2D planner;
  planner.robotRadius = static_cast<float>(robot_radius_ * map.frame().resolution);
  std::deque<mrpt::math::TPoint2D> path;
  bool not_found = true;
  // computePath keeps the step of its trace toward the target in function-static variables: two threads tracing at
  // once walk each other's steps, and one may never reach the target while its path grows without bound
  // (mrpt_threads_test). One plan at a time in the process, however many planners it holds (nodelets of a manager).
  static std::mutex mrpt_planning;
  try {
    const mrpt::maps::COccupancyGridMap2D grid = mrptGridOf(map);
    const std::lock_guard<std::mutex> one_at_a_time(mrpt_planning);
    planner.computePath(grid, mrpt::poses::CPose2D(from.x, from.y, 0), mrpt::poses::CPose2D(to.x, to.y, 0),
                        path, not_found);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(std::string("MRPT PlannerSimple2D: ") + e.what());
  }
  if (not_found) return {};
  std::vector<MapPoint> waypoints{from};
  for (const mrpt::math::TPoint2D& point : path) waypoints.push_back(MapPoint{point.x, point.y});
  return waypoints;
}

}  // namespace planners
}  // namespace ppp
