// A path planner driven in continuous motion (PlanFollower, as the planner bridge plays one): an optimistic A* that
// plans on the robot's laser-built map (unknown cells free) reaches the goal of every PPP solvable for its disc
// under each plan_requests; given the true map it is asked once; bad answers fail the run as they should.

#include "ppp_agents/continuous/plan_follower.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ppp_agents/continuous/continuous_astar.hpp"
#include "ppp_agents/continuous/continuous_runner.hpp"
#include "ppp_agents/planner_bridge_options.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/square_world.hpp"

namespace ppp {
namespace agents {
namespace {

/// Plays `problem` with a planner that plans centreRoute() on the robot's map (unknown cells free), asked as
/// `requests` says; counts its requests.
struct OptimisticRun {
  ContinuousOutcome outcome;
  int requests = 0;
};

OptimisticRun playOptimistic(const Problem& problem, const EpisodeOptions& options, const std::string& requests,
                             bool prior_map) {
  const Grid grid = decodeGrid(problem);
  AgentConfig config;
  config.name = config.type = "planner";
  config.prior_map = prior_map;
  const int grid_moves = fewestMoves(grid, problem.start, problem.goal, Connectivity::Four);
  ContinuousEpisode episode = continuousEpisode(problem, grid, options,
                                                continuousOptimalMoves(problem, grid, options, grid_moves), 3);
  const ContinuousStart start = continuousStart(episode, options, config, grid, 3);
  PlanFollower follower;
  follower.start(start, requests);
  OptimisticRun run;
  std::vector<float> ranges;
  while (!episode.done()) {
    episode.scan(&ranges);
    const ContinuousSensing sensing{episode.pose(), episode.velocity(), episode.time(), &ranges};
    if (follower.observe(sensing)) {
      ++run.requests;
      Grid known(grid.width(), grid.height());
      for (std::size_t i = 0; i < follower.map().size(); ++i) {
        known.setObstacle(Cell{static_cast<int>(i) % grid.width(), static_cast<int>(i) / grid.width()},
                          follower.map()[i] == kScanObstacle);
      }
      const PlanVerdict verdict = follower.take(
          centreRoute(known, start.frame, start.radius, MapPoint{sensing.pose.x, sensing.pose.y}, start.goal),
          sensing.pose);
      if (verdict.failure != nullptr) {
        episode.fail(verdict.failure);
        break;
      }
    }
    episode.apply(follower.command(sensing));
  }
  run.outcome = episode.outcome();
  return run;
}

TEST(PlanFollowerTest, AnOptimisticPlannerOnTheLaserMapPassesEveryPppSolvableForItsDisc) {
  Rng rng(31);
  int solvable = 0;
  for (int map = 0; map < 8; ++map) {
    const Problem problem = randomProblem(rng, Problem::empty(12, 12, 8), 8);
    for (const char* kinematics : {kKinematicsDiffDrive, kKinematicsHolonomic}) {
      EpisodeOptions options;
      options.motion.motion = kMotionContinuous;
      options.motion.kinematics = kinematics;
      options.robot_radius = 0.3;
      const Grid grid = decodeGrid(problem);
      const Grid space = continuousConfigurationSpace(SquareWorld(grid, options.motion.resolution),
                                                      options.robot_radius * options.motion.resolution);
      if (!space.isFree(problem.start) || !isReachable(space, problem.start, problem.goal)) continue;
      ++solvable;
      for (const char* requests : {kPlanRequestsEveryStep, kPlanRequestsOnChange, kPlanRequestsOnBlocked}) {
        const OptimisticRun run = playOptimistic(problem, options, requests, false);
        EXPECT_TRUE(run.outcome.passed) << "map " << map << ", " << kinematics << ", " << requests << ": "
                                        << run.outcome.reason << " after " << run.outcome.steps << " periods";
        if (requests == kPlanRequestsEveryStep) EXPECT_EQ(run.requests, run.outcome.steps);
      }
    }
  }
  EXPECT_GE(solvable, 8);  // most of the 16 cases: the test is not vacuous
}

TEST(PlanFollowerTest, GivenTheTrueMapItIsAskedOnceAndOnBlockedAsksLessThanOnChange) {
  Rng rng(32);
  EpisodeOptions options;
  options.motion.motion = kMotionContinuous;
  options.robot_radius = 0.3;
  int compared = 0;
  for (int map = 0; map < 6; ++map) {
    const Problem problem = randomProblem(rng, Problem::empty(12, 12, 8), 8);
    const OptimisticRun with_map = playOptimistic(problem, options, kPlanRequestsOnChange, true);
    if (!with_map.outcome.passed) continue;  // not solvable for the disc
    EXPECT_EQ(with_map.requests, 1) << "map " << map;
    const OptimisticRun on_change = playOptimistic(problem, options, kPlanRequestsOnChange, false);
    const OptimisticRun on_blocked = playOptimistic(problem, options, kPlanRequestsOnBlocked, false);
    EXPECT_LE(on_blocked.requests, on_change.requests) << "map " << map;
    EXPECT_LT(on_change.requests, on_change.outcome.steps) << "map " << map;
    ++compared;
  }
  EXPECT_GE(compared, 3);
}

TEST(PlanFollowerTest, AnEmptyPathAPointOffTheMapOrAPathAwayFromTheRobotFailTheRun) {
  ContinuousStart start;
  start.frame = MapFrame{4, 4, 1.0};
  start.pose = Pose2D{0.5, 3.5, 0};
  start.goal = MapPoint{3.5, 0.5};
  PlanFollower follower;
  follower.start(start, kPlanRequestsOnChange);
  EXPECT_STREQ(follower.take({}, start.pose).failure, reason::kNoPath);
  const PlanVerdict off = follower.take({{0.5, 3.5}, {4.5, 3.5}}, start.pose);
  EXPECT_STREQ(off.failure, reason::kInvalidPath);
  EXPECT_NE(off.detail.find("off the map"), std::string::npos) << off.detail;
  const PlanVerdict away = follower.take({{2.5, 1.5}, {3.5, 0.5}}, start.pose);
  EXPECT_STREQ(away.failure, reason::kInvalidPath);
  EXPECT_NE(away.detail.find("more than a cell"), std::string::npos) << away.detail;
  EXPECT_EQ(follower.take({{0.5, 3.5}, {3.5, 3.5}}, start.pose).failure, nullptr);
  // Standing still before it moves: the command heads along the path.
  const ContinuousSensing sensing{start.pose, BodyVelocity{}, 0, nullptr};
  EXPECT_GT(follower.command(sensing).forward, 0);
}

}  // namespace
}  // namespace agents
}  // namespace ppp
