#pragma once
// MRPT's holonomic reactive methods driving a diff-drive disc in continuous motion, in process, exactly as
// mrpt_reactive_node drives them through ROS: each control period the laser's returns become distances per
// sector for the robot's body, the goal is put in the robot's frame, the method chooses, and reactiveVelocity()
// makes the command. Shared by the continuous trap tests and the program drawing their pictures.
#include <string>
#include <vector>

#include "map_picture.hpp"
#include "mrpt_reactive_navigator.hpp"
#include "ppp_core/continuous_episode.hpp"
#include "ppp_core/problem.hpp"
#include "robot_frame.hpp"

namespace ppp {
namespace planners {
namespace test {

/// The default continuous robot (docs/reference/continuous-motion.md): diff drive, 0.5 m/s, a 3.5 m laser.
inline MotionOptions continuousDiffDrive() {
  MotionOptions options;
  options.motion = kMotionContinuous;
  options.kinematics = kKinematicsDiffDrive;
  return options;
}

/// A trap of MRPT's holonomic methods found on the grid, drawn ('#' obstacles, S start, G goal, 1 m cells).
struct ReactiveTrap {
  std::string name;
  std::vector<std::string> picture;
};

/// The traps mrpt_reactive_navigator_test replays with one-cell steps, in its order: a goal in the map's corner
/// (VFF, FullEval), a U facing away from the goal (VFF, ND), the pocket of two diagonal cells before the goal
/// (VFF), one obstacle cell diagonal to a goal in the corner (ND).
inline const std::vector<ReactiveTrap>& reactiveTraps() {
  static const std::vector<ReactiveTrap> traps = {
      {"corner", {"S.......", "........", "........", "........", "........", "........", "........", ".......G"}},
      {"u", {"....G....", ".........", "..#####..", "..#...#..", "..#.S.#..", "..#...#..", "........."}},
      {"pocket", {"S.......", "........", "........", "........", ".....#..", "....#...", "......G.", "........"}},
      {"one_cell", {"S.....", "......", "......", "......", "....#.", ".....G"}},
  };
  return traps;
}

/// A drawn map ('#' obstacles, S start, G goal, 1 m cells) as a problem.
inline Problem pictureProblem(const std::vector<std::string>& picture) {
  return problemFromGrid(pictureGrid(picture), markedCell(picture, 'S'), markedCell(picture, 'G'));
}

/// One run of `method` on `problem` for a disc of `radius` metres, at most `periods` control periods, the node's
/// defaults (full speed 1 m/s, turns up to 1.5 rad/s, distances as fractions of the laser's range); `rays`: the
/// nearest ray per sector instead of the disc's travel (~obstacles:=rays). The outcome has every pose.
inline ContinuousOutcome driveReactive(const Problem& problem, const std::string& method, double radius,
                                       long periods, bool rays = false) {
  const MotionOptions options = continuousDiffDrive();
  ContinuousEpisode episode(problem, decodeGrid(problem), options, radius / options.resolution, periods, 1, true);
  MrptReactiveNavigator navigator(method);
  const LaserBeams& beams = episode.beams();
  const double range = options.laser_range;
  std::vector<float> ranges;
  while (!episode.done()) {
    episode.scan(&ranges);
    const LaserRays scan{beams.angle_min, beams.angle_increment, ranges};
    int invalid = 0;
    const std::vector<double> obstacles = radius > 0 && !rays
                                              ? sectorObstaclesForDisc(scan, range, radius, &invalid)
                                              : sectorObstacles(scan, range, &invalid);
    const Pose2D& pose = episode.pose();
    const MapPoint target =
        inRobotFrame(MapPoint{(episode.goal().x - pose.x) / range, (episode.goal().y - pose.y) / range}, pose.theta);
    episode.apply(reactiveVelocity(navigator.navigate(obstacles, target), true, 1.0, 1.5));
  }
  return episode.outcome();
}

}  // namespace test
}  // namespace planners
}  // namespace ppp
