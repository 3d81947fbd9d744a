// MRPT's TP-space navigator without ROS (MrptTpSpaceNavigator, what mrpt_tpspace_node runs), configured by the
// shipped config/mrpt_tpspace.ini: driving a diff-drive disc in continuous motion from its laser alone, it reaches
// the goal of an open map; it plays the same run twice alike (its clock is the simulated one); and it refuses a
// point robot, a configuration MRPT rejects and a PTG for another kind of robot, naming each.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mrpt_tpspace_navigator.hpp"
#include "ppp_core/continuous_episode.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/problem.hpp"

namespace ppp {
namespace planners {
namespace {

std::string shippedConfig() {
  std::ifstream in(PPP_TPSPACE_CONFIG);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

MotionOptions diffDrive() {
  MotionOptions options;
  options.motion = kMotionContinuous;
  options.kinematics = kKinematicsDiffDrive;
  return options;
}

TpSpaceRobot robotOf(const MotionOptions& options, double radius) {
  return TpSpaceRobot{radius * options.resolution, options.max_linear_speed, options.max_angular_speed};
}

/// The run's outcome and the commands the navigator gave, on `problem` for a disc of 0.2 m.
struct Drive {
  ContinuousOutcome outcome;
  std::vector<double> commands;  // linear, angular per period
};

Drive drive(MrptTpSpaceNavigator& navigator, const Problem& problem) {
  const Grid grid = decodeGrid(problem);
  const MotionOptions options = diffDrive();
  ContinuousEpisode episode(problem, grid, options, 0.2, 1500, 1);
  navigator.start(episode.goal(), 0.5 * options.goal_tolerance * options.resolution);
  const LaserBeams& beams = episode.beams();
  std::vector<float> ranges;
  Drive result;
  while (!episode.done()) {
    episode.scan(&ranges);
    TpSpaceSensing sensing{episode.time(), episode.pose(), episode.velocity(),
                           laserReturns(ranges, beams.angle_min, beams.angle_increment)};
    const BodyVelocity command = navigator.step(sensing);
    result.commands.push_back(command.forward);
    result.commands.push_back(command.turn);
    episode.apply(command);
  }
  result.outcome = episode.outcome();
  return result;
}

TEST(MrptTpSpaceNavigatorTest, DrivesAcrossAnOpenMapToTheGoal) {
  MrptTpSpaceNavigator navigator(shippedConfig(), "mrpt_tpspace.ini", robotOf(diffDrive(), 0.2));
  const Drive run = drive(navigator, Problem::empty(6, 6, 2));
  EXPECT_TRUE(run.outcome.passed) << run.outcome.reason << " after " << run.outcome.steps << " periods";
  EXPECT_EQ(navigator.error(), "");
}

TEST(MrptTpSpaceNavigatorTest, PlaysARunAgainAlike) {
  Problem problem = Problem::empty(8, 8, 2);
  problem.obstacles.push_back(Obstacle{Shape::VerticalBar, 4, 0, 6, 1});
  MrptTpSpaceNavigator navigator(shippedConfig(), "mrpt_tpspace.ini", robotOf(diffDrive(), 0.2));
  const Drive first = drive(navigator, problem);
  const Drive second = drive(navigator, problem);
  EXPECT_EQ(first.outcome.reason, second.outcome.reason);
  EXPECT_EQ(first.commands, second.commands);
  EXPECT_GT(first.commands.size(), 20u);
}

/// The name and the message of the InvalidArgument thrown by making a navigator, or "" when none is thrown.
std::string refusal(const std::string& config, const TpSpaceRobot& robot, std::string* message = nullptr) {
  try {
    MrptTpSpaceNavigator navigator(config, "nav.ini", robot);
  } catch (const InvalidArgument& e) {
    if (message != nullptr) *message = e.what();
    return e.name();
  }
  return "";
}

TEST(MrptTpSpaceNavigatorTest, RefusesAPointRobotABadConfigurationAndAHolonomicPtg) {
  const TpSpaceRobot robot = robotOf(diffDrive(), 0.2);
  EXPECT_EQ(refusal(shippedConfig(), TpSpaceRobot{0, 0.5, 1.5}), "robot_radius");
  EXPECT_EQ(refusal(shippedConfig(), TpSpaceRobot{0.2, 0, 1.5}), "max_linear_speed");
  std::string unknown = shippedConfig();
  unknown.replace(unknown.find("PTG0_Type = CPTG_DiffDrive_C"), 28, "PTG0_Type = CPTG_Nowhere    ");
  std::string message;
  EXPECT_EQ(refusal(unknown, robot, &message), "nav.ini");
  EXPECT_NE(message.find("CPTG_Nowhere"), std::string::npos) << message;
  EXPECT_EQ(message.find("backtrace"), std::string::npos) << message;  // MRPT's message, not its call stack
  EXPECT_EQ(refusal("[CReactiveNavigationSystem]\n", robot, &message), "nav.ini");
  EXPECT_NE(message.find("PTG_COUNT"), std::string::npos) << message;
  std::string holonomic = shippedConfig();
  holonomic.replace(holonomic.find("PTG0_Type = CPTG_DiffDrive_C"), 28,
                    "PTG0_Type = CPTG_Holo_Blend\nPTG0_T_ramp_max = 0.9");
  EXPECT_EQ(refusal(holonomic, robot, &message), "nav.ini");
  EXPECT_NE(message.find("PTG0 (mrpt::nav::CPTG_Holo_Blend) is not for a differential-drive robot"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace planners
}  // namespace ppp
