#include "ppp_msgs/conversions.h"

#include <cmath>
#include <cstddef>
#include <iterator>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/failure_signature.hpp"
#include "ppp_core/map_frame.hpp"
#include "ppp_core/scan_rays.hpp"

namespace ppp_msgs {

namespace {

std::string cellText(int x, int y) { return "(" + std::to_string(x) + ", " + std::to_string(y) + ")"; }

std::string sizeText(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

void checkResolution(double resolution, const char* field) {
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw ppp::InvalidArgument(
        field, "expected a positive, finite number of metres per cell, got " + std::to_string(resolution));
  }
}

/// A map side as an int; uint32 values above the limit (including negatives assigned to it) are rejected here.
int checkedSide(std::uint32_t side, const char* field) {
  if (side < static_cast<std::uint32_t>(ppp::kMinGridSide) || side > static_cast<std::uint32_t>(ppp::kMaxGridSide)) {
    throw ppp::InvalidArgument(field, "expected a number of cells in [" + std::to_string(ppp::kMinGridSide) + ", " +
                                          std::to_string(ppp::kMaxGridSide) + "], got " + std::to_string(side) +
                                          (side > 0x7fffffffu ? " (a negative value wrapped to uint32?)" : ""));
  }
  return static_cast<int>(side);
}

/// The grid cell of a map-frame cell index message; `field` names it when it lies off the map.
ppp::Cell gridCellOf(const ppp_msgs::MapCell& cell, const ppp::MapFrame& frame, const char* field) {
  if (cell.x < 0 || cell.y < 0 || cell.x >= frame.width || cell.y >= frame.height) {
    throw ppp::InvalidArgument(field, "map-frame cell (column, row from the bottom) " + cellText(cell.x, cell.y) +
                                          " is outside the " + sizeText(frame.width, frame.height) + " map");
  }
  return frame.cellOfMapRowColumn(cell.x, cell.y);
}

/// The map-frame cell index message of a grid cell.
ppp_msgs::MapCell mapCellOf(ppp::Cell cell, const ppp::MapFrame& frame) {
  ppp_msgs::MapCell message;
  message.x = cell.x;
  message.y = frame.mapRow(cell);
  return message;
}

}  // namespace

nav_msgs::OccupancyGrid toOccupancyGrid(const ppp::Grid& grid, double resolution, const std::string& frame_id) {
  checkResolution(resolution, "resolution");
  ppp::validateGridSize(grid.width(), grid.height(), "grid");
  std::vector<std::int8_t> cells(grid.cells().size());
  for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = grid.cells()[i] != 0 ? kObstacleValue : kFreeValue;
  return toOccupancyGrid(cells, grid.width(), grid.height(), resolution, frame_id);
}

nav_msgs::OccupancyGrid toOccupancyGrid(const std::vector<std::int8_t>& cells, int width, int height,
                                        double resolution, const std::string& frame_id) {
  checkResolution(resolution, "resolution");
  ppp::validateGridSize(width, height, "grid");
  if (cells.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw ppp::InvalidArgument("cells", "expected " + sizeText(width, height) + " = " +
                                            std::to_string(width * height) + " cells, got " +
                                            std::to_string(cells.size()));
  }
  const ppp::MapFrame frame{width, height, resolution};
  nav_msgs::OccupancyGrid map;
  map.header.frame_id = frame_id;
  map.info.resolution = static_cast<float>(resolution);
  map.info.width = static_cast<std::uint32_t>(width);
  map.info.height = static_cast<std::uint32_t>(height);
  map.info.origin.orientation.w = 1.0;
  map.data.resize(cells.size());
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      map.data[static_cast<std::size_t>(frame.mapIndex(ppp::Cell{x, y}))] = cells[static_cast<std::size_t>(y * width + x)];
    }
  }
  return map;
}

nav_msgs::OccupancyGrid toFinerOccupancyGrid(const std::vector<std::int8_t>& cells, int width, int height,
                                             double resolution, int per_cell, const std::string& frame_id) {
  if (per_cell < 1 || per_cell > 16) {
    throw ppp::InvalidArgument("per_cell", "expected map cells per cell side in [1, 16], got " + std::to_string(per_cell));
  }
  if (per_cell == 1) return toOccupancyGrid(cells, width, height, resolution, frame_id);
  checkResolution(resolution, "resolution");
  ppp::validateGridSize(width, height, "grid");
  if (cells.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw ppp::InvalidArgument("cells", "expected " + sizeText(width, height) + " cells, got " + std::to_string(cells.size()));
  }
  std::vector<std::int8_t> finer(cells.size() * static_cast<std::size_t>(per_cell * per_cell));
  const int fine_width = width * per_cell;
  for (int y = 0; y < height * per_cell; ++y) {
    for (int x = 0; x < fine_width; ++x) {
      finer[static_cast<std::size_t>(y) * fine_width + x] = cells[static_cast<std::size_t>(y / per_cell) * width + x / per_cell];
    }
  }
  return toOccupancyGrid(finer, fine_width, height * per_cell, resolution / per_cell, frame_id);
}

geometry_msgs::TransformStamped cellTransform(const ppp::MapFrame& frame, ppp::Cell cell, const std::string& parent,
                                              const std::string& child) {
  geometry_msgs::TransformStamped transform;
  transform.header.frame_id = parent;
  transform.child_frame_id = child;
  transform.transform.translation.x = frame.centreX(cell);
  transform.transform.translation.y = frame.centreY(cell);
  transform.transform.rotation.w = 1.0;
  return transform;
}

geometry_msgs::TransformStamped poseTransform(const ppp::Pose2D& pose, const std::string& parent,
                                              const std::string& child) {
  geometry_msgs::TransformStamped transform;
  transform.header.frame_id = parent;
  transform.child_frame_id = child;
  transform.transform.translation.x = pose.x;
  transform.transform.translation.y = pose.y;
  transform.transform.rotation.z = std::sin(pose.theta / 2);
  transform.transform.rotation.w = std::cos(pose.theta / 2);
  return transform;
}

sensor_msgs::LaserScan toLaserScan(const std::vector<float>& ranges, const ppp::LaserBeams& beams,
                                   const std::string& frame_id) {
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = frame_id;
  scan.angle_min = static_cast<float>(beams.angle_min);
  scan.angle_increment = static_cast<float>(beams.angle_increment);
  scan.angle_max = static_cast<float>(beams.angle_min + (beams.count - 1) * beams.angle_increment);
  scan.range_min = 0;
  scan.range_max = static_cast<float>(beams.range_max);
  scan.ranges = ranges;
  return scan;
}

ppp::Grid fromOccupancyGrid(const nav_msgs::OccupancyGrid& map) {
  const int width = checkedSide(map.info.width, "map.info.width");
  const int height = checkedSide(map.info.height, "map.info.height");
  checkResolution(map.info.resolution, "map.info.resolution");
  const std::size_t expected = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (map.data.size() != expected) {
    throw ppp::InvalidArgument("map.data", "expected width*height = " + std::to_string(expected) + " values for the " +
                                               sizeText(width, height) + " map, got " +
                                               std::to_string(map.data.size()));
  }

  const ppp::MapFrame frame{width, height, map.info.resolution};
  ppp::Grid grid(width, height);
  for (std::size_t i = 0; i < expected; ++i) {
    const int value = map.data[i];
    if (value < -1 || value > kObstacleValue) {
      throw ppp::InvalidArgument("map.data[" + std::to_string(i) + "]",
                                 "expected -1 (unknown) or an occupancy in [0, 100], got " + std::to_string(value));
    }
    const int column = static_cast<int>(i % static_cast<std::size_t>(width));
    const int row = static_cast<int>(i / static_cast<std::size_t>(width));
    grid.setObstacle(frame.cellOfMapRowColumn(column, row), value == -1 || value >= kObstacleThreshold);
  }
  return grid;
}

ppp_msgs::Obstacle toMessage(const ppp::Obstacle& obstacle) {
  ppp_msgs::Obstacle message;
  message.shape = static_cast<std::uint8_t>(obstacle.shape);
  message.x = obstacle.x;
  message.y = obstacle.y;
  message.length = obstacle.length;
  message.height = obstacle.height;
  return message;
}

ppp::Obstacle fromMessage(const ppp_msgs::Obstacle& message, const std::string& what) {
  if (message.shape >= std::size(ppp::kAllShapes)) {
    throw ppp::InvalidArgument(what, "expected a shape in [0, " + std::to_string(std::size(ppp::kAllShapes) - 1) +
                                         "] (HBAR, VBAR, DIAG_DOWN, DIAG_UP, BLOCK), got " +
                                         std::to_string(message.shape));
  }
  ppp::Obstacle obstacle;
  obstacle.shape = ppp::kAllShapes[message.shape];
  obstacle.x = message.x;
  obstacle.y = message.y;
  obstacle.length = message.length;
  obstacle.height = message.height;
  return obstacle;
}

ppp_msgs::Problem toMessage(const ppp::Problem& problem, const std::string& id, double resolution) {
  ppp::validateProblem(problem);
  checkResolution(resolution, "resolution");
  const ppp::MapFrame frame{problem.width, problem.height, resolution};

  ppp_msgs::Problem message;
  message.id = id;
  message.map = toOccupancyGrid(ppp::decodeGrid(problem), resolution);
  message.start = mapCellOf(problem.start, frame);
  message.goal = mapCellOf(problem.goal, frame);
  message.max_obstacles = static_cast<std::uint32_t>(problem.max_obstacles);
  message.obstacles.reserve(problem.obstacles.size());
  for (const ppp::Obstacle& obstacle : problem.obstacles) message.obstacles.push_back(toMessage(obstacle));
  message.metadata.reserve(problem.metadata.size());
  for (const auto& entry : problem.metadata) {
    diagnostic_msgs::KeyValue key_value;
    key_value.key = entry.first;
    key_value.value = entry.second;
    message.metadata.push_back(key_value);
  }
  return message;
}

ppp_msgs::ProblemSet toSetMessage(const std::string& name, const std::vector<ppp::Problem>& problems,
                                  const std::vector<std::string>& ids, double resolution) {
  if (problems.size() != ids.size()) throw ppp::InvalidArgument("ids", "expected one id per problem");
  ppp_msgs::ProblemSet m;
  m.header.stamp = ros::Time::now();
  m.header.frame_id = "map";
  m.name = name;
  for (std::size_t i = 0; i < problems.size(); ++i) m.problems.push_back(toMessage(problems[i], ids[i], resolution));
  return m;
}

ppp::Problem fromMessage(const ppp_msgs::Problem& message) {
  const ppp::Grid map_grid = fromOccupancyGrid(message.map);
  const ppp::MapFrame frame{map_grid.width(), map_grid.height(), message.map.info.resolution};

  ppp::Problem problem;
  problem.width = map_grid.width();
  problem.height = map_grid.height();
  problem.start = gridCellOf(message.start, frame, "start");
  problem.goal = gridCellOf(message.goal, frame, "goal");
  if (message.max_obstacles > static_cast<std::uint32_t>(ppp::kMaxObstacleBudget)) {
    throw ppp::InvalidArgument("max_obstacles", "expected an integer in [0, " +
                                                    std::to_string(ppp::kMaxObstacleBudget) + "], got " +
                                                    std::to_string(message.max_obstacles));
  }
  problem.max_obstacles = static_cast<int>(message.max_obstacles);
  problem.obstacles.reserve(message.obstacles.size());
  for (std::size_t i = 0; i < message.obstacles.size(); ++i) {
    const std::string field = "obstacles[" + std::to_string(i) + "]";
    problem.obstacles.push_back(fromMessage(message.obstacles[i], field + ".shape"));
    ppp::validateObstacle(problem.obstacles.back(), problem.width, problem.height, field);
  }
  problem.metadata.reserve(message.metadata.size());
  for (const diagnostic_msgs::KeyValue& entry : message.metadata) problem.metadata.emplace_back(entry.key, entry.value);
  ppp::validateProblem(problem);

  const ppp::Grid decoded = ppp::decodeGrid(problem);
  for (int i = 0; i < decoded.size(); ++i) {
    const ppp::Cell cell = decoded.cellAt(i);
    if (decoded.isObstacle(cell) == map_grid.isObstacle(cell)) continue;
    const int map_index = frame.mapIndex(cell);
    throw ppp::InvalidArgument("map.data[" + std::to_string(map_index) + "]",
                               "map cell (column, row from the bottom) " + cellText(cell.x, frame.mapRow(cell)) +
                                   " = grid cell " + cellText(cell.x, cell.y) + " holds " +
                                   std::to_string(message.map.data[static_cast<std::size_t>(map_index)]) + " (" +
                                   (map_grid.isObstacle(cell) ? "obstacle" : "free") +
                                   ") but the genotype decodes it as " +
                                   (decoded.isObstacle(cell) ? "obstacle" : "free"));
  }
  return problem;
}

sensor_msgs::LaserScan toLaserScan(const std::int8_t* window, int range, double resolution,
                                   const std::string& frame_id) {
  sensor_msgs::LaserScan laser;
  laser.header.frame_id = frame_id;
  laser.angle_min = 0.0f;
  laser.angle_increment = static_cast<float>(2.0 * M_PI / kLaserRays);
  laser.angle_max = laser.angle_increment * (kLaserRays - 1);
  laser.range_min = 0.0f;
  laser.range_max = static_cast<float>((range + 0.5) * std::sqrt(2.0) * resolution);
  for (float r : ppp::windowRanges(window, range, kLaserRays)) {
    laser.ranges.push_back(std::isinf(r) ? r : r * static_cast<float>(resolution));
  }
  return laser;
}

std::map<std::string, int> signatureCounts(const ppp_msgs::ProblemEvaluation& evaluation, const std::string& source) {
  if (evaluation.signatures.size() != evaluation.signature_counts.size()) {
    throw ppp::IoError(source, "answered " + std::to_string(evaluation.signatures.size()) + " failure signatures and " +
                                   std::to_string(evaluation.signature_counts.size()) + " counts");
  }
  std::map<std::string, int> counts;
  for (std::size_t i = 0; i < evaluation.signatures.size(); ++i) {
    if (!ppp::isWellFormedSignature(evaluation.signatures[i])) {
      throw ppp::IoError(source, "answered a malformed failure signature '" + evaluation.signatures[i] + "'");
    }
    counts[evaluation.signatures[i]] += static_cast<int>(evaluation.signature_counts[i]);
  }
  return counts;
}

}  // namespace ppp_msgs
