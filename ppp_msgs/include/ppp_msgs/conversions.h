#pragma once

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <sensor_msgs/LaserScan.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ppp_core/grid.hpp"
#include "ppp_core/kinematics.hpp"
#include "ppp_core/laser.hpp"
#include "ppp_core/map_frame.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_msgs/Obstacle.h"
#include "ppp_msgs/Problem.h"
#include "ppp_msgs/ProblemEvaluation.h"
#include "ppp_msgs/ProblemSet.h"

/// Conversions between the ROS-free ppp_core model and the PPP Lab messages.
/// The y-flip between the grid (y down, row 0 at the top) and the ROS map frame (y up, row 0 at the
/// bottom) is done here, only through ppp::MapFrame.
namespace ppp_msgs {

/// OccupancyGrid value of a free cell.
constexpr std::int8_t kFreeValue = 0;
/// OccupancyGrid value of an obstacle cell.
constexpr std::int8_t kObstacleValue = 100;
/// Smallest OccupancyGrid value read as an obstacle by fromOccupancyGrid().
constexpr std::int8_t kObstacleThreshold = 50;

/// The grid as a map-frame occupancy grid: 0 free, 100 obstacle, origin (0,0) with identity
/// orientation, grid cell (x,y) at data[MapFrame::mapIndex(x,y)] (the grid's top row is the last map row).
/// The header stamp is left zero for the caller to set.
/// @throws ppp::InvalidArgument naming "resolution" when it is not a positive finite number,
///         or "grid" when the grid is empty.
nav_msgs::OccupancyGrid toOccupancyGrid(const ppp::Grid& grid, double resolution, const std::string& frame_id = "map");

/// The grid of a map-frame occupancy grid: values 50..100 are obstacles, 0..49 free, and -1 (unknown)
/// is treated as an obstacle (a planner must not be offered cells nobody has seen as free).
/// Origin and orientation are ignored; the map is taken as axis-aligned with row 0 at the bottom.
/// @throws ppp::InvalidArgument naming the field (map.info.width, map.info.height, map.info.resolution,
///         map.data, map.data[i]) for sides outside [kMinGridSide, kMaxGridSide], a non-positive
///         resolution, a data size other than width*height, or a value outside [-1, 100].
ppp::Grid fromOccupancyGrid(const nav_msgs::OccupancyGrid& map);

/// An OccupancyGrid of cells already holding its values (-1 unknown, 0 free, 100 obstacle: the kScan* values),
/// row-major in the grid convention (y down) as a robot's memory keeps them; the rows are flipped as for
/// toOccupancyGrid. @throws ppp::InvalidArgument naming "resolution" or "cells" (not width x height of them).
nav_msgs::OccupancyGrid toOccupancyGrid(const std::vector<std::int8_t>& cells, int width, int height,
                                        double resolution, const std::string& frame_id);

/// toOccupancyGrid() with each cell drawn as `per_cell` x `per_cell` map cells of resolution / per_cell metres
/// (the same metres: a cell's centre is where it was). @throws ppp::InvalidArgument as toOccupancyGrid(), and
/// naming "per_cell" unless it is in [1, 16].
nav_msgs::OccupancyGrid toFinerOccupancyGrid(const std::vector<std::int8_t>& cells, int width, int height,
                                             double resolution, int per_cell, const std::string& frame_id);

/// The transform `parent` -> `child` placing `child` on the centre of `cell` (identity rotation), unstamped.
geometry_msgs::TransformStamped cellTransform(const ppp::MapFrame& frame, ppp::Cell cell, const std::string& parent,
                                              const std::string& child);

/// The transform `parent` -> `child` placing `child` at `pose` (a map-frame pose in metres, its heading a rotation
/// about z), unstamped.
geometry_msgs::TransformStamped poseTransform(const ppp::Pose2D& pose, const std::string& parent,
                                              const std::string& child);

/// A laser's ranges (ppp::scanLaser's, +inf for no return) as a sensor_msgs/LaserScan in `frame_id`: the beams'
/// angles, range_min 0 and range_max as `beams` says, no scan or time increments (a scan is one instant). The header
/// stamp is left zero for the caller to set.
sensor_msgs::LaserScan toLaserScan(const std::vector<float>& ranges, const ppp::LaserBeams& beams,
                                   const std::string& frame_id);

/// Rays of the laser scans made by toLaserScan (one every 5 degrees).
constexpr int kLaserRays = 72;

/// A scan window (ppp::SensorModel's cells, `range` its radius) as the range sensor standard ROS consumers
/// expect: kLaserRays rays from ppp::windowRanges, in metres at `resolution` metres per cell, in `frame_id` (the
/// agent's base_link). The header stamp is left zero for the caller to set.
sensor_msgs::LaserScan toLaserScan(const std::int8_t* window, int range, double resolution,
                                   const std::string& frame_id);

/// The descriptor as a message; coordinates stay in the genotype's grid convention (y down).
ppp_msgs::Obstacle toMessage(const ppp::Obstacle& obstacle);

/// The descriptor of a message. @throws ppp::InvalidArgument naming `what` for an unknown shape.
ppp::Obstacle fromMessage(const ppp_msgs::Obstacle& message, const std::string& what = "obstacle.shape");

/// The problem as a message: decoded map in the map frame, start and goal as map-frame cell indices,
/// genotype and metadata unchanged. The header stamp is left zero for the caller to set.
/// @throws ppp::InvalidArgument naming the field when the problem is invalid (ppp::validateProblem)
///         or the resolution is not a positive finite number.
ppp_msgs::Problem toMessage(const ppp::Problem& problem, const std::string& id, double resolution);

/// A set of problems as one message: `name`, frame "map", stamped now, problem i with id ids[i].
/// @throws ppp::InvalidArgument as toMessage() does, or when the counts differ.
ppp_msgs::ProblemSet toSetMessage(const std::string& name, const std::vector<ppp::Problem>& problems,
                                  const std::vector<std::string>& ids, double resolution);

/// The problem of a message, rebuilt from its genotype: size from map.info, start and goal converted
/// back from map-frame indices, then the decoded genotype compared cell by cell with the map.
/// The map resolution and the id are not part of ppp::Problem and are dropped.
/// @throws ppp::InvalidArgument naming the field for a malformed map (see fromOccupancyGrid), a start or
///         goal off the map, an invalid problem (ppp::validateProblem), or a map that disagrees with the
///         decoded genotype (naming the first differing cell in grid row-major order, as map.data[i] and in
///         both grid and map coordinates).
ppp::Problem fromMessage(const ppp_msgs::Problem& message);

/// The failed and soft-failed runs per failure signature of an evaluation (its signatures and signature_counts).
/// @throws ppp::IoError naming `source` (the service that answered) for lists of different lengths or a
///         malformed signature.
std::map<std::string, int> signatureCounts(const ppp_msgs::ProblemEvaluation& evaluation, const std::string& source);

}  // namespace ppp_msgs
