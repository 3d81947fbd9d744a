#pragma once
// MRPT's holonomic reactive methods driving a diff-drive disc in continuous motion, in process, exactly as
// mrpt_reactive_node drives them through ROS: each control period the laser's returns become distances per
// sector for the robot's body, the goal is put in the robot's frame, the method chooses and its choice becomes a
// command (ReactiveSteering, the node's own steering). Shared by the continuous trap tests and the program drawing
// their pictures.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "map_picture.hpp"
#include "reactive_traps.hpp"
#include "ppp_core/continuous_episode.hpp"
#include "ppp_core/problem.hpp"
#include "reactive_steering.hpp"

namespace ppp {
namespace planners {
namespace test {

/// The traps' robot: a disc of 0.2 m, driven for 300 s.
constexpr double kTrapRadius = 0.2;
constexpr long kTrapPeriods = 3000;

/// The default continuous robot (docs/reference/continuous-motion.md): diff drive, 0.5 m/s, a 3.5 m laser.
inline MotionOptions continuousDiffDrive() {
  MotionOptions options;
  options.motion = kMotionContinuous;
  options.kinematics = kKinematicsDiffDrive;
  return options;
}

/// A drawn map ('#' obstacles, S start, G goal, 1 m cells) as a problem.
inline Problem pictureProblem(const std::vector<std::string>& picture) {
  return problemFromGrid(pictureGrid(picture), markedCell(picture, 'S'), markedCell(picture, 'G'));
}

/// One run of `method` on `problem` for a disc of `radius` metres, at most `periods` control periods, with
/// mrpt_reactive_node's steering and its defaults (full speed 1 m/s, turns up to 1.5 rad/s, distances as fractions
/// of the laser's range); `obstacles` as its ~obstacles, `kinematics` as the robot's. The outcome has every pose.
inline ContinuousOutcome driveReactive(const Problem& problem, const std::string& method, double radius,
                                       long periods, const std::string& obstacles = kObstaclesFromScan,
                                       const std::string& kinematics = kKinematicsDiffDrive) {
  MotionOptions options = continuousDiffDrive();
  options.kinematics = kinematics;
  ContinuousEpisode episode(problem, decodeGrid(problem), options, radius / options.resolution, periods, 1, true);
  ReactiveNodeParameters parameters;
  parameters.method = method;
  parameters.obstacles = obstacles;
  parameters.robot_radius = radius;
  parameters.kinematics = options.kinematics;
  ReactiveSteering steering(parameters);
  const LaserBeams& beams = episode.beams();
  std::vector<float> ranges;
  while (!episode.done()) {
    episode.scan(&ranges);
    const LaserRays scan{beams.angle_min, beams.angle_increment, ranges};
    ReactiveView view;
    view.goal = MapPoint{episode.goal().x - episode.pose().x, episode.goal().y - episode.pose().y};
    view.heading = episode.pose().theta;
    view.range = options.laser_range;
    view.scan = &scan;
    int invalid = 0;
    episode.apply(steering.command(view, &invalid));
  }
  return episode.outcome();
}

/// The box a run's robot centre stayed in.
struct Box {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  double extent() const { return std::max(x1 - x0, y1 - y0); }
};

/// The box the robot's centre stayed in over the run's last 1,000 periods (100 s; `outcome` has its poses).
inline Box lastBox(const ContinuousOutcome& outcome) {
  constexpr std::size_t kLastPeriods = 1000;
  Box box;
  for (std::size_t i = outcome.poses.size() - std::min(kLastPeriods, outcome.poses.size()); i < outcome.poses.size();
       ++i) {
    box.x0 = std::min(box.x0, outcome.poses[i].x);
    box.x1 = std::max(box.x1, outcome.poses[i].x);
    box.y0 = std::min(box.y0, outcome.poses[i].y);
    box.y1 = std::max(box.y1, outcome.poses[i].y);
  }
  return box;
}

}  // namespace test
}  // namespace planners
}  // namespace ppp
