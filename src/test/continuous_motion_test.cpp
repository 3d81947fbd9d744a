// The continuous motion model: kinematics against closed forms and fine Euler integration, the laser against a
// brute-force march along each beam, collisions at the instant of contact, and how a run ends.

#include "ppp_core/continuous_episode.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ppp_core/diagnosis.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/random_problem.hpp"

namespace ppp {
namespace {

constexpr double kPi = 3.14159265358979323846;

Grid gridOf(const std::vector<std::string>& rows) {
  Grid grid(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()));
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) grid.setObstacle(Cell{x, y}, rows[y][x] == '#');
  }
  return grid;
}

/// The PPP whose decoded grid is `grid`, from `start` to `goal`.
Problem problemOf(const Grid& grid, Cell start, Cell goal) {
  return problemFromGrid(grid, start, goal);
}

TEST(KinematicsTest, ADiffDriveArcIsTheClosedFormCircle) {
  // 0.5 m/s at 0.5 rad/s: a circle of radius 1 about (1, 2); after 2 s the robot has turned 1 rad.
  const Pose2D after = integrate(Pose2D{1, 1, 0}, BodyVelocity{0.5, 0, 0.5}, 2);
  EXPECT_NEAR(after.x, 1 + std::sin(1.0), 1e-12);
  EXPECT_NEAR(after.y, 2 - std::cos(1.0), 1e-12);
  EXPECT_NEAR(after.theta, 1, 1e-12);
}

TEST(KinematicsTest, ATurnInPlaceOnlyTurns) {
  const Pose2D after = integrate(Pose2D{3, 4, 3}, BodyVelocity{0, 0, 1}, 0.5);
  EXPECT_DOUBLE_EQ(after.x, 3);
  EXPECT_DOUBLE_EQ(after.y, 4);
  EXPECT_NEAR(after.theta, 3.5 - 2 * kPi, 1e-12);  // wrapped into (-pi, pi]
}

TEST(KinematicsTest, AHolonomicDiagonalIsAStraightLineInTheRobotsFrame) {
  const Pose2D east = integrate(Pose2D{0, 0, 0}, BodyVelocity{0.3, 0.4, 0}, 2);
  EXPECT_NEAR(east.x, 0.6, 1e-12);
  EXPECT_NEAR(east.y, 0.8, 1e-12);
  const Pose2D north = integrate(Pose2D{0, 0, kPi / 2}, BodyVelocity{0.3, 0.4, 0}, 2);
  EXPECT_NEAR(north.x, -0.8, 1e-12);
  EXPECT_NEAR(north.y, 0.6, 1e-12);
}

TEST(KinematicsTest, AnyConstantVelocityMatchesFineEulerIntegration) {
  for (const BodyVelocity v : {BodyVelocity{0.4, 0.1, -0.7}, BodyVelocity{-0.2, 0.3, 2.5}, BodyVelocity{0.5, 0, 1e-12}}) {
    Pose2D euler{1, 2, 0.3};
    const int steps = 1000000;
    const double dt = 1.5 / steps;
    for (int i = 0; i < steps; ++i) {
      euler.x += (std::cos(euler.theta) * v.forward - std::sin(euler.theta) * v.left) * dt;
      euler.y += (std::sin(euler.theta) * v.forward + std::cos(euler.theta) * v.left) * dt;
      euler.theta += v.turn * dt;
    }
    const Pose2D exact = integrate(Pose2D{1, 2, 0.3}, v, 1.5);
    EXPECT_NEAR(exact.x, euler.x, 1e-5);
    EXPECT_NEAR(exact.y, euler.y, 1e-5);
    EXPECT_NEAR(exact.theta, wrapAngle(euler.theta), 1e-9);
  }
}

TEST(KinematicsTest, CommandsAreClampedToSpeedsThenAccelerations) {
  KinematicLimits limits;  // 0.5 m/s, 1.5 rad/s, 1 m/s^2, 3 rad/s^2
  const BodyVelocity moving{0.5, 0, 0};
  // Too fast, and sideways on a diff drive: the sideways part is dropped, the rest capped.
  BodyVelocity held = limitVelocity(BodyVelocity{9, 4, 9}, moving, limits, 0.1);
  EXPECT_DOUBLE_EQ(held.forward, 0.5);
  EXPECT_DOUBLE_EQ(held.left, 0);
  EXPECT_NEAR(held.turn, 0.3, 1e-12);  // 3 rad/s^2 x 0.1 s from rest
  // A holonomic robot keeps the direction of a command too fast: (0.6, 0.8) scaled to 0.5 m/s, then 0.1 m/s of
  // change from rest along it.
  limits.holonomic = true;
  held = limitVelocity(BodyVelocity{0.6, 0.8, 0}, BodyVelocity{}, limits, 0.1);
  EXPECT_NEAR(held.forward, 0.06, 1e-12);
  EXPECT_NEAR(held.left, 0.08, 1e-12);
}

TEST(SquareWorldTest, RaysStopAtSquaresAndTheBorderExactly) {
  const Grid grid = gridOf({"....", "..#.", "...."});
  const SquareWorld world(grid, 1.0);
  // Map frame: y up, so grid row 1 is map row 1; the obstacle is the square [2, 3] x [1, 2].
  EXPECT_NEAR(world.castRay(0.5, 1.5, 0, 10), 1.5, 1e-12);
  EXPECT_NEAR(world.castRay(0.5, 0.5, 0, 10), 3.5, 1e-12);          // under it, to the border
  EXPECT_NEAR(world.castRay(0.5, 0.5, kPi / 2, 10), 2.5, 1e-12);     // up to the top border
  EXPECT_NEAR(world.castRay(0.5, 0.5, kPi / 4, 10), 1.5 * std::sqrt(2.0), 1e-12);  // corner (2, 2) of the square
  EXPECT_EQ(world.castRay(0.5, 1.5, 0, 1.4), std::numeric_limits<double>::infinity());
  EXPECT_EQ(world.castRay(2.5, 1.5, 0, 10), 0);  // inside the obstacle
}

TEST(SquareWorldTest, RaysAgreeWithABruteForceMarchOnRandomMaps) {
  Rng rng(7);
  for (int map = 0; map < 5; ++map) {
    const Problem problem = randomProblem(rng, Problem::empty(12, 9, 8), 8);
    const Grid grid = decodeGrid(problem);
    const SquareWorld world(grid, 0.7);
    for (int ray = 0; ray < 200; ++ray) {
      const double x = rng.uniform01() * world.widthMetres(), y = rng.uniform01() * world.heightMetres();
      const Cell cell = world.cellAt(x, y);
      if (!grid.isFree(cell)) continue;
      const double angle = rng.uniform01() * 2 * kPi;
      const double exact = world.castRay(x, y, angle, 100);
      const double step = 1e-4;
      double marched = 0;
      while (grid.isFree(world.cellAt(x + marched * std::cos(angle), y + marched * std::sin(angle))) &&
             marched < 100) {
        marched += step;
      }
      EXPECT_LE(exact, marched + 1e-9) << map << " " << ray;
      EXPECT_GT(exact, marched - step - 1e-9) << map << " " << ray;
    }
  }
}

TEST(SquareWorldTest, ClearanceIsTheDistanceToTheNearestSquareOrBorder) {
  const Grid grid = gridOf({"....", "..#.", "...."});
  const SquareWorld world(grid, 1.0);
  EXPECT_NEAR(world.clearance(1.5, 1.5, 10), 0.5, 1e-12);
  EXPECT_NEAR(world.clearance(1.2, 0.9, 10), std::hypot(0.8, 0.1), 1e-12);  // the square's corner (2, 1)
  EXPECT_NEAR(world.clearance(0.1, 1.5, 10), 0.1, 1e-12);                    // the left border
  EXPECT_DOUBLE_EQ(world.clearance(1.5, 1.5, 0.2), 0.2);                     // capped
  EXPECT_TRUE(world.collides(1.5, 1.5, 0.5));                                // contact collides
  EXPECT_FALSE(world.collides(1.5, 1.5, 0.5 - 1e-12));
}

TEST(LaserTest, AFullCircleHasNoDuplicateBeamAndNoiseIsSeeded) {
  MotionOptions options;
  const LaserBeams beams = LaserBeams::of(options);
  EXPECT_EQ(beams.count, 360);
  EXPECT_DOUBLE_EQ(beams.angle_min, -kPi);
  EXPECT_NEAR(beams.angle_min + 359 * beams.angle_increment, kPi - kPi / 180, 1e-12);
  options.laser_field_of_view = 90;
  options.laser_beams = 3;
  const LaserBeams narrow = LaserBeams::of(options);
  EXPECT_DOUBLE_EQ(narrow.angle_min, -kPi / 4);
  EXPECT_DOUBLE_EQ(narrow.angle_increment, kPi / 4);

  const Grid grid = gridOf({"....", "....", "...."});
  const SquareWorld world(grid, 1.0);
  LaserBeams noisy = beams;
  noisy.noise = 0.05;
  std::vector<float> a, b, clean;
  Rng first(3), second(3);
  scanLaser(world, Pose2D{1.5, 1.5, 0}, noisy, &first, &a);
  scanLaser(world, Pose2D{1.5, 1.5, 0}, noisy, &second, &b);
  scanLaser(world, Pose2D{1.5, 1.5, 0}, beams, nullptr, &clean);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, clean);
  EXPECT_FLOAT_EQ(clean[180], 2.5f);  // beam 180 points ahead (east): 2.5 m to the right border
}

TEST(ContinuousEpisodeTest, ACollisionStopsTheRobotAtTheInstantOfContact) {
  // A corridor, the wall square at x in [2, 3]: a disc of 0.23 m driven east from (0.5, 1.5) touches it when
  // its centre reaches x = 1.77. Accelerating at 1 m/s^2 in 0.1 s periods it covers 0.01, 0.02, ... 0.05 m in
  // the first five periods (0.15 m), then 0.05 m each: 1.27 m is reached 22.4 periods later, in period 28.
  const Grid grid = gridOf({"####", "..#.", "####"});
  const Problem problem = problemOf(grid, Cell{0, 1}, Cell{3, 1});
  MotionOptions options;
  options.motion = kMotionContinuous;
  ContinuousEpisode run(problem, grid, options, 0.23, 1000, 1);
  while (!run.done()) run.apply(BodyVelocity{0.5, 0, 0});
  EXPECT_STREQ(run.outcome().reason, reason::kCollision);
  EXPECT_EQ(run.outcome().steps, 28);
  EXPECT_NEAR(run.pose().x, 1.77, 1e-8);
  EXPECT_NEAR(run.outcome().distance, 1.27, 1e-8);
}

TEST(ContinuousEpisodeTest, ARobotGrazingAWallWithoutTouchingItPasses) {
  const Grid grid = gridOf({"########", "........", "########"});
  const Problem problem = problemOf(grid, Cell{0, 1}, Cell{7, 1});
  MotionOptions options;
  options.kinematics = kKinematicsHolonomic;
  // Along the corridor's centre line a disc just under half its width never touches the borders.
  ContinuousEpisode wide(problem, grid, options, 0.5 - 1e-6, 1000, 1);
  while (!wide.done()) wide.apply(BodyVelocity{0.5, 0, 0});
  EXPECT_STREQ(wide.outcome().reason, reason::kGoalReached);
  EXPECT_NEAR(wide.pose().y, 1.5, 1e-12);
}

TEST(ContinuousEpisodeTest, RunsEndOnTheGoalTheBudgetOrAnInvalidCommand) {
  const Grid grid = gridOf({"#####", ".....", "#####"});
  const Problem problem = problemOf(grid, Cell{0, 1}, Cell{4, 1});
  MotionOptions options;
  // 4 moves of 1 m at 0.5 m/s: 8 s; time_factor 4: 32 s, 320 periods.
  EXPECT_EQ(continuousStepBudget(options, 4), 320);
  ContinuousEpisode still(problem, grid, options, 0.2, 5, 1);
  while (!still.done()) still.apply(BodyVelocity{});
  EXPECT_STREQ(still.outcome().reason, reason::kBudgetExhausted);
  EXPECT_EQ(still.outcome().steps, 5);
  EXPECT_EQ(still.outcome().cells.size(), 6u);

  ContinuousEpisode driven(problem, grid, options, 0.2, 320, 1);
  while (!driven.done()) driven.apply(BodyVelocity{0.5, 0, 0});
  EXPECT_STREQ(driven.outcome().reason, reason::kGoalReached);
  EXPECT_TRUE(driven.outcome().passed);
  EXPECT_LE(std::fabs(driven.pose().x - 4.5), 0.25);
  EXPECT_EQ(driven.outcome().cells.back(), (Cell{4, 1}));

  ContinuousEpisode broken(problem, grid, options, 0.2, 320, 1);
  broken.apply(BodyVelocity{std::nan(""), 0, 0});
  EXPECT_STREQ(broken.outcome().reason, reason::kInvalidCommand);
  ContinuousEpisode infinite(problem, grid, options, 0.2, 320, 1);
  infinite.apply(BodyVelocity{0, 0, std::numeric_limits<double>::infinity()});
  EXPECT_STREQ(infinite.outcome().reason, reason::kInvalidCommand);
}

TEST(ContinuousEpisodeTest, AProgressTimeoutEndsARunThatStaysNearOnePoint) {
  // A corridor 4 m long, 0.1 s periods, a budget of 320 periods; progress_radius 0.5 cells (0.5 m).
  const Grid grid = gridOf({"#####", ".....", "#####"});
  const Problem problem = problemOf(grid, Cell{0, 1}, Cell{4, 1});
  MotionOptions options;
  options.progress_timeout = 2.0;  // 20 periods
  // Standing still: no progress for 20 periods.
  ContinuousEpisode still(problem, grid, options, 0.2, 320, 1);
  while (!still.done()) still.apply(BodyVelocity{});
  EXPECT_STREQ(still.outcome().reason, reason::kNoProgress);
  EXPECT_FALSE(still.outcome().passed);
  EXPECT_EQ(still.outcome().steps, 20);
  // Creeping at 0.1 m/s: 0.01 m a period, 0.2 m in 20 periods, never 0.5 m from the start.
  ContinuousEpisode creeping(problem, grid, options, 0.2, 320, 1);
  while (!creeping.done()) creeping.apply(BodyVelocity{0.1, 0, 0});
  EXPECT_STREQ(creeping.outcome().reason, reason::kNoProgress);
  EXPECT_EQ(creeping.outcome().steps, 20);
  // Driving at 0.5 m/s, accelerating at 1 m/s^2: 0.01, 0.02, ... 0.05 m in the first five periods, then 0.05 m
  // each; 0.55 m from the start after period 13, and then 0.55 m further every 11 periods: within 20 each time,
  // so it reaches the goal. Given 1 s (10 periods), it is 0.40 m from the start after period 10 and ends there.
  ContinuousEpisode driven(problem, grid, options, 0.2, 320, 1);
  while (!driven.done()) driven.apply(BodyVelocity{0.5, 0, 0});
  EXPECT_STREQ(driven.outcome().reason, reason::kGoalReached);
  options.progress_timeout = 1.0;
  ContinuousEpisode impatient(problem, grid, options, 0.2, 320, 1);
  while (!impatient.done()) impatient.apply(BodyVelocity{0.5, 0, 0});
  EXPECT_STREQ(impatient.outcome().reason, reason::kNoProgress);
  EXPECT_EQ(impatient.outcome().steps, 10);
  EXPECT_NEAR(impatient.pose().x - 0.5, 0.40, 1e-9);
  // Turning on the spot is no progress either; without the option the run goes on to its budget.
  options.progress_timeout = 2.0;
  ContinuousEpisode spinning(problem, grid, options, 0.2, 320, 1);
  while (!spinning.done()) spinning.apply(BodyVelocity{0, 0, 1.0});
  EXPECT_STREQ(spinning.outcome().reason, reason::kNoProgress);
  options.progress_timeout = 0;
  ContinuousEpisode patient(problem, grid, options, 0.2, 320, 1);
  while (!patient.done()) patient.apply(BodyVelocity{});
  EXPECT_STREQ(patient.outcome().reason, reason::kBudgetExhausted);
  EXPECT_EQ(patient.outcome().steps, 320);
  // A run ended for want of progress is diagnosed from its trajectory, as one whose budget ran out.
  const Diagnosis d = diagnoseContinuousRun(false, false, reason::kNoProgress, still.outcome().cells);
  EXPECT_STREQ(d.kind, diagnosis::kStuck);
}

TEST(ContinuousEpisodeTest, ARobotThatCannotStandAtTheStartIsRefusedNamingItsRadius) {
  const Grid grid = gridOf({".....", "....."});
  const Problem problem = problemOf(grid, Cell{0, 0}, Cell{4, 0});
  try {
    ContinuousEpisode run(problem, grid, MotionOptions{}, 0.5, 100, 1);
    FAIL() << "a disc touching the border at the start was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("robot_radius"), std::string::npos) << e.what();
  }
}

TEST(ContinuousEpisodeTest, TheConfigurationSpaceKeepsCellsWhereTheDiscTouchesNothing) {
  const Grid grid = gridOf({"....", "....", "..#.", "...."});
  const SquareWorld world(grid, 1.0);
  const Grid space = continuousConfigurationSpace(world, 0.4);
  EXPECT_TRUE(space.isFree(Cell{1, 1}));
  EXPECT_TRUE(space.isFree(Cell{1, 2}));  // 0.5 from the square's side
  EXPECT_FALSE(space.isFree(Cell{2, 2}));
  EXPECT_FALSE(continuousConfigurationSpace(world, 0.5).isFree(Cell{1, 2}));  // touching
}

TEST(MotionOptionsTest, BadValuesAreRefusedNamingTheOption) {
  const auto refused = [](MotionOptions options, const std::string& name) {
    try {
      options.validate();
      ADD_FAILURE() << name << " accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  MotionOptions options;
  options.control_period = 0;
  refused(options, "control_period");
  options = MotionOptions{};
  options.control_period = -0.1;
  refused(options, "control_period");
  options = MotionOptions{};
  options.max_linear_speed = 0;
  refused(options, "max_linear_speed");
  options = MotionOptions{};
  options.max_angular_speed = -1;
  refused(options, "max_angular_speed");
  options = MotionOptions{};
  options.motion = "ballistic";
  refused(options, "motion");
  options = MotionOptions{};
  options.kinematics = "tracked";
  refused(options, "kinematics");
  options = MotionOptions{};
  options.progress_timeout = -1;
  refused(options, "progress_timeout");
  options = MotionOptions{};
  options.progress_timeout = std::numeric_limits<double>::quiet_NaN();
  refused(options, "progress_timeout");
  options = MotionOptions{};
  options.progress_radius = 0;
  refused(options, "progress_radius");
}

}  // namespace
}  // namespace ppp
