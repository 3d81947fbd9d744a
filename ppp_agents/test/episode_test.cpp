#include "ppp_agents/episode_runner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/episode_reason.hpp"

namespace ppp {
namespace agents {
namespace {

agents::AgentConfig config(const std::string& type) {
  agents::AgentConfig c;
  c.type = type;
  c.name = type;
  return c;
}

/// The rules of a random walk on an empty map, for the exact chain: whether it heads for the goal once the goal
/// is in its sensor window, and which of its actions use the budget.
struct WalkRules {
  bool seek_goal = false;    ///< Once the goal is within `range` (Chebyshev) it walks straight to it.
  int range = 2;             ///< The sensor range.
  bool stays_count = true;   ///< A stay uses one of the budget.
  bool bumps_count = true;   ///< A move off the grid uses one of the budget.
  int goal_range = 0;        ///< The agent's goal_range: it notices the goal this near; 0 = within `range`.
};

/// Exact probability that a uniform random walk over {stay, N, E, S, W} on an empty W x H grid, where moves off
/// the grid leave it in place, stands on the goal within `budget` counted actions. The distribution over cells
/// is pushed forward one counted action at a time, the goal absorbing. A free action (a stay or a bump the rules
/// do not count) leaves the budget as it was, so per counted action the walk picks uniformly among the counted
/// ones. A goal seeker is absorbed when the goal enters its window, passing if its Manhattan distance to the goal
/// fits in the budget left. (The episode's action limit of 4 x budget is never reached here: it would take
/// fewer than 300 counted actions in 1,200 where each counts with probability at least 2/5.)
double exactRandomPassProbability(int width, int height, Cell start, Cell goal, int budget, const WalkRules& rules) {
  std::vector<double> p(static_cast<std::size_t>(width) * height, 0.0), next;
  p[start.y * width + start.x] = 1.0;
  double absorbed = 0.0;
  const int dx[4] = {0, 1, 0, -1};
  const int dy[4] = {-1, 0, 1, 0};
  for (int used = 0;; ++used) {
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const int distance = std::abs(goal.x - x) + std::abs(goal.y - y);
        const int notice = rules.goal_range > 0 ? rules.goal_range : rules.range;
        const bool in_window = std::max(std::abs(goal.x - x), std::abs(goal.y - y)) <= notice;
        if (distance == 0 || (rules.seek_goal && in_window)) {
          if (used + distance <= budget) absorbed += p[y * width + x];
          p[y * width + x] = 0.0;
        }
      }
    }
    if (used == budget) break;
    next.assign(p.size(), 0.0);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const double mass = p[y * width + x];
        if (mass == 0.0) continue;
        int moves = 0;
        for (int a = 0; a < 4; ++a) {
          const int nx = x + dx[a], ny = y + dy[a];
          moves += nx >= 0 && ny >= 0 && nx < width && ny < height ? 1 : 0;
        }
        const int counted = moves + (rules.stays_count ? 1 : 0) + (rules.bumps_count ? 4 - moves : 0);
        for (int a = 0; a < 4; ++a) {
          const int nx = x + dx[a], ny = y + dy[a];
          if (nx >= 0 && ny >= 0 && nx < width && ny < height) next[ny * width + nx] += mass / counted;
        }
        next[y * width + x] += mass * (counted - moves) / counted;
      }
    }
    p.swap(next);
  }
  return absorbed;
}

/// Expects the random agent's pass rate over `runs` runs on an empty map, under `rules`, within three standard
/// errors of the exact chain's.
void expectRandomMatchesExact(int width, int height, int budget, int runs, const WalkRules& rules = {}) {
  const Problem problem = Problem::empty(width, height, 0);
  const Grid grid = decodeGrid(problem);
  EpisodeOptions options;
  options.budget = budget;
  options.sensor_range = rules.range;
  options.stays_use_budget = rules.stays_count;
  options.bumps_use_budget = rules.bumps_count;
  agents::AgentConfig random = config("random");
  random.goal_seeking = rules.seek_goal ? kGoalSeekingOn : kGoalSeekingByType;
  random.goal_range = rules.goal_range;
  EpisodeRunner runner(random, options);
  auto agent = agents::makeAgent(random);
  int passes = 0;
  for (int run = 0; run < runs; ++run) {
    const auto outcome = runner.run(problem, grid, *agent, deriveSeed(2024, {static_cast<std::uint64_t>(run)}));
    passes += outcome.passed ? 1 : 0;
    if (rules.stays_count && rules.bumps_count) EXPECT_LE(outcome.steps, budget);
    EXPECT_NE(std::string(outcome.reason), reason::kActionLimit);
  }
  const double exact = exactRandomPassProbability(width, height, problem.start, problem.goal, budget, rules);
  const double observed = static_cast<double>(passes) / runs;
  const double standard_error = std::sqrt(exact * (1 - exact) / runs);
  std::printf("random (goal seeking %s, goal range %d, stays %s, bumps %s) on empty %dx%d, budget %d: exact %.5f, "
              "observed %.5f over %d runs (SE %.5f)\n",
              rules.seek_goal ? "on" : "off", rules.goal_range, rules.stays_count ? "counted" : "free",
              rules.bumps_count ? "counted" : "free", width, height, budget, exact, observed, runs, standard_error);
  EXPECT_NEAR(observed, exact, 3 * standard_error);
}

TEST(EpisodeTest, RandomAgentMatchesTheExactMarkovChainOn20x20) { expectRandomMatchesExact(20, 20, 300, 40000); }

TEST(EpisodeTest, RandomAgentMatchesTheExactMarkovChainOn5x5) { expectRandomMatchesExact(5, 5, 40, 20000); }

TEST(EpisodeTest, GoalSeekingRandomAgentWithFreeBumpsMatchesTheExactChain) {
  WalkRules rules;
  rules.seek_goal = true;
  rules.bumps_count = false;
  // The chain's value by hand would be tedious; its independent check is the plain walk above, and here that
  // seeking and free bumps each raise it (0.975 % without either on 20x20).
  EXPECT_GT(exactRandomPassProbability(20, 20, Cell{0, 0}, Cell{19, 19}, 300, rules),
            exactRandomPassProbability(20, 20, Cell{0, 0}, Cell{19, 19}, 300, WalkRules{true, 2, true, true}));
  expectRandomMatchesExact(20, 20, 300, 20000, rules);
}

TEST(EpisodeTest, RandomAgentNoticingTheGoalWithinThreeCellsMatchesTheExactChain) {
  WalkRules rules;
  rules.seek_goal = true;
  rules.goal_range = 3;
  // Noticing the goal one cell further out than the 5x5 window lifts the chain from 2.941 % to 4.427 % on the
  // empty 20x20 map with every action counted (values of a separate implementation of the same chain).
  EXPECT_NEAR(exactRandomPassProbability(20, 20, Cell{0, 0}, Cell{19, 19}, 300, rules), 0.04427, 0.00001);
  EXPECT_NEAR(exactRandomPassProbability(20, 20, Cell{0, 0}, Cell{19, 19}, 300, WalkRules{true, 2, true, true}),
              0.02941, 0.00001);
  expectRandomMatchesExact(20, 20, 300, 20000, rules);
}

TEST(EpisodeTest, RandomAgentWithFreeStaysAndBumpsMatchesTheExactChain) {
  WalkRules rules;
  rules.stays_count = false;
  rules.bumps_count = false;
  expectRandomMatchesExact(20, 20, 300, 20000, rules);
  expectRandomMatchesExact(5, 5, 40, 20000, rules);
}

TEST(EpisodeTest, ChainOfAGoalSeekerBesideTheGoalIsExact) {
  // On a 3x3 grid with range 2 the goal is in the window from the start: it passes iff its 4 moves fit.
  WalkRules rules;
  rules.seek_goal = true;
  EXPECT_DOUBLE_EQ(exactRandomPassProbability(3, 3, Cell{0, 0}, Cell{2, 2}, 4, rules), 1.0);
  EXPECT_DOUBLE_EQ(exactRandomPassProbability(3, 3, Cell{0, 0}, Cell{2, 2}, 3, rules), 0.0);
  // With goal_range 3 the goal of a 4x4 grid is noticed from the start: it passes iff its 6 moves fit.
  rules.goal_range = 3;
  EXPECT_DOUBLE_EQ(exactRandomPassProbability(4, 4, Cell{0, 0}, Cell{3, 3}, 6, rules), 1.0);
  EXPECT_DOUBLE_EQ(exactRandomPassProbability(4, 4, Cell{0, 0}, Cell{3, 3}, 5, rules), 0.0);
  // Without seeking, a 2x1 corridor: each action reaches the goal with probability 1/5 (East), so within 2 actions
  // 1 - (4/5)^2; with free stays and bumps only East counts there, so 1.
  EXPECT_DOUBLE_EQ(exactRandomPassProbability(2, 1, Cell{0, 0}, Cell{1, 0}, 2, WalkRules{}), 1 - 0.8 * 0.8);
  WalkRules free_actions;
  free_actions.stays_count = false;
  free_actions.bumps_count = false;
  EXPECT_DOUBLE_EQ(exactRandomPassProbability(2, 1, Cell{0, 0}, Cell{1, 0}, 1, free_actions), 1.0);
}

TEST(EpisodeTest, AstarPassesInTheFewestMovesAndCountsAreConsistent) {
  Rng rng(11);
  EpisodeRunner runner(config("astar"), EpisodeOptions{});
  auto agent = agents::makeAgent(config("astar"));
  for (int i = 0; i < 100; ++i) {
    const Problem problem = randomProblem(rng, Problem::empty(16, 12, 12), 12);
    const Grid grid = decodeGrid(problem);
    const auto outcome = runner.run(problem, grid, *agent, i, true);
    const int optimal = stepDistances(grid, problem.start)[grid.index(problem.goal)];
    EXPECT_TRUE(outcome.passed);
    EXPECT_STREQ(outcome.reason, "goal_reached");
    EXPECT_EQ(outcome.path_length, optimal);
    EXPECT_EQ(outcome.steps, optimal);
    EXPECT_EQ(outcome.bumps, 0);
    ASSERT_EQ(outcome.path.size(), static_cast<std::size_t>(optimal) + 1);
    EXPECT_EQ(outcome.path.front(), problem.start);
    EXPECT_EQ(outcome.path.back(), problem.goal);
  }
}

TEST(EpisodeTest, BudgetEndsAnEpisodeAndBumpsAreCounted) {
  // The bumper on a 3x3 grid whose goal is walled off by a diagonal can only bump and wander: it must stop at the budget.
  Problem problem = Problem::empty(3, 3, 1);
  problem.obstacles.push_back(Obstacle{Shape::DiagonalUp, 0, 2, 3, 1});  // (0,2),(1,1),(2,0): cuts the goal off
  const Grid grid = decodeGrid(problem);
  EpisodeOptions options;
  options.budget = 25;
  EpisodeRunner runner(config("bumper"), options);
  auto agent = agents::makeAgent(config("bumper"));
  const auto outcome = runner.run(problem, grid, *agent, 3);
  EXPECT_FALSE(outcome.passed);
  EXPECT_STREQ(outcome.reason, "budget_exhausted");
  EXPECT_EQ(outcome.steps, 25);
  EXPECT_GT(outcome.bumps, 0);
  EXPECT_LE(outcome.bumps + outcome.path_length, outcome.steps);
}

TEST(EpisodeTest, FreeStaysAndBumpsDoNotUseTheBudgetUpToTheActionLimit) {
  const Problem open = Problem::empty(5, 5, 0);
  const Grid grid = decodeGrid(open);
  const SensorModel sensor(SensorOptions{2, 0.0});
  // Stays free: stay, stay, east, stay, east spend a budget of 2 in 5 actions.
  Episode stays(open, grid, sensor, 1, BudgetRule(2, false, true), Connectivity::Four);
  for (Action a : {Action::Stay, Action::Stay, Action::East, Action::Stay}) {
    stays.apply(a);
    EXPECT_FALSE(stays.done());
  }
  stays.apply(Action::East);
  EXPECT_TRUE(stays.done());
  EXPECT_STREQ(stays.outcome().reason, reason::kBudgetExhausted);
  EXPECT_EQ(stays.outcome().steps, 5);
  EXPECT_EQ(stays.outcome().path_length, 2);
  // Stays free, bumps counted: two bumps off the top edge spend a budget of 2.
  Episode bumps_counted(open, grid, sensor, 1, BudgetRule(2, false, true), Connectivity::Four);
  bumps_counted.apply(Action::North);
  EXPECT_FALSE(bumps_counted.done());
  bumps_counted.apply(Action::North);
  EXPECT_STREQ(bumps_counted.outcome().reason, reason::kBudgetExhausted);
  EXPECT_EQ(bumps_counted.outcome().bumps, 2);
  // Bumps free: bumping forever ends at the action limit, 4 x the budget of 3.
  Episode bumps_free(open, grid, sensor, 1, BudgetRule(3, true, false), Connectivity::Four);
  EXPECT_EQ(BudgetRule(3, true, false).actionLimit(), 12);
  for (int i = 0; i < 11; ++i) bumps_free.apply(Action::West);
  EXPECT_FALSE(bumps_free.done());
  bumps_free.apply(Action::West);
  EXPECT_TRUE(bumps_free.done());
  EXPECT_FALSE(bumps_free.outcome().passed);
  EXPECT_STREQ(bumps_free.outcome().reason, reason::kActionLimit);
  EXPECT_EQ(bumps_free.outcome().steps, 12);
  EXPECT_EQ(bumps_free.outcome().bumps, 12);
  // By default every action counts: three stays spend a budget of 3, and the limit is the budget.
  Episode plain(open, grid, sensor, 1, 3, Connectivity::Four);
  EXPECT_EQ(BudgetRule(3).actionLimit(), 3);
  for (int i = 0; i < 3; ++i) plain.apply(Action::Stay);
  EXPECT_STREQ(plain.outcome().reason, reason::kBudgetExhausted);
  EXPECT_EQ(plain.outcome().steps, 3);
  // The goal reached with the last counted action passes.
  Episode last(open, grid, sensor, 1, BudgetRule(8, false, false), Connectivity::Four);
  for (Action a : {Action::East, Action::East, Action::East, Action::East, Action::South, Action::South,
                   Action::South, Action::Stay, Action::South}) {
    last.apply(a);
  }
  EXPECT_TRUE(last.outcome().passed);
  EXPECT_EQ(last.outcome().steps, 9);
}

TEST(EpisodeTest, SameSeedSameEpisode) {
  Rng rng(5);
  const Problem problem = randomProblem(rng, Problem::empty(20, 20, 10), 10);
  const Grid grid = decodeGrid(problem);
  for (const char* type : {"random", "explorer", "bumper", "decision_bumper", "long_term_explorer"}) {
    agents::AgentConfig c = config(type);
    c.sensor_noise = 0.05;
    EpisodeRunner runner(c, EpisodeOptions{});
    auto a = agents::makeAgent(c);
    auto b = agents::makeAgent(c);
    const auto first = runner.run(problem, grid, *a, 77, true);
    const auto second = runner.run(problem, grid, *b, 77, true);
    EXPECT_EQ(first.path, second.path) << type;
    EXPECT_EQ(first.steps, second.steps) << type;
  }
}

/// Pass rate of one configuration over a fixed set of PPPs and run seeds.
double passRate(const agents::AgentConfig& c, const std::vector<Problem>& problems, int runs) {
  EpisodeRunner runner(c, EpisodeOptions{});
  auto agent = agents::makeAgent(c);
  int passes = 0;
  for (std::size_t p = 0; p < problems.size(); ++p) {
    const Grid grid = decodeGrid(problems[p]);
    for (int run = 0; run < runs; ++run) {
      passes += runner.run(problems[p], grid, *agent, deriveSeed(99, {p, static_cast<std::uint64_t>(run)})).passed;
    }
  }
  return static_cast<double>(passes) / (problems.size() * runs);
}

TEST(EpisodeTest, HandicapsHurtTheExplorer) {
  // 20 random solvable 20x20 PPPs, 100 runs each, fixed seeds. Measured: explorer 0.724, with noise 0.1 0.573,
  // with a 5x5 memory 0.004 (printed below); the assertions ask for about a third of each gap.
  Rng rng(8);
  std::vector<Problem> problems;
  for (int i = 0; i < 20; ++i) problems.push_back(randomProblem(rng, Problem::empty(20, 20, 10), 10));
  agents::AgentConfig plain = config("explorer");
  agents::AgentConfig memory = plain;
  memory.memory_window = 5;
  agents::AgentConfig noisy = plain;
  noisy.sensor_noise = 0.1;
  const double plain_rate = passRate(plain, problems, 100);
  const double memory_rate = passRate(memory, problems, 100);
  const double noisy_rate = passRate(noisy, problems, 100);
  std::printf("explorer pass rates: plain %.3f, memory 5x5 %.3f, noise 0.1 %.3f\n", plain_rate, memory_rate,
              noisy_rate);
  EXPECT_LT(memory_rate, plain_rate - 0.2);
  EXPECT_LT(noisy_rate, plain_rate - 0.05);
}

TEST(EpisodeTest, BadOptions) {
  EpisodeOptions options;
  options.budget = 0;
  EXPECT_THROW(EpisodeRunner(config("random"), options), InvalidArgument);
  options.budget = 300;
  options.sensor_range = 0;
  EXPECT_THROW(EpisodeRunner(config("random"), options), InvalidArgument);
  EXPECT_THROW(EpisodeRunner(config("flier"), EpisodeOptions{}), InvalidArgument);
  options.sensor_range = 2;
  for (int connectivity : {0, 5, 6, 9}) {
    options.connectivity = static_cast<Connectivity>(connectivity);
    try {
      EpisodeRunner(config("random"), options);
      FAIL() << "no error for connectivity " << connectivity;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.name(), "connectivity");
    }
  }
}

// Rows of '.' (free) and '#' (obstacle), y down; start top-left, goal bottom-right.
Problem problemOf(const std::vector<std::string>& rows) {
  Problem p = Problem::empty(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()), 10);
  for (int y = 0; y < p.height; ++y) {
    for (int x = 0; x < p.width; ++x) {
      if (rows[y][x] == '#') p.obstacles.push_back(Obstacle{Shape::HorizontalBar, x, y, 1, 1});
    }
  }
  return p;
}

TEST(EpisodeTest, DiagonalMovesUnderConnectivityEight) {
  // . . .
  // . # .
  // . . .
  const Problem problem = problemOf({"...", ".#.", "..."});
  const Grid grid = decodeGrid(problem);
  const SensorModel sensor(SensorOptions{2, 0.0});
  Episode episode(problem, grid, sensor, 1, 10, Connectivity::Eight, true);
  episode.apply(Action::SouthEast);  // would pass beside (1,0) and (0,1): free, but lands on the obstacle
  EXPECT_TRUE(episode.scan().bumped());
  episode.apply(Action::East);        // (1,0)
  episode.apply(Action::SouthEast);   // passes beside (2,0) (free) and (1,1) (obstacle): a cut corner
  EXPECT_TRUE(episode.scan().bumped());
  episode.apply(Action::East);        // (2,0)
  episode.apply(Action::South);       // (2,1)
  episode.apply(Action::SouthWest);   // passes beside (1,1): refused
  EXPECT_TRUE(episode.scan().bumped());
  episode.apply(Action::South);       // (2,2): the goal
  const EpisodeOutcome& o = episode.outcome();
  EXPECT_TRUE(o.passed);
  EXPECT_EQ(o.steps, 7);
  EXPECT_EQ(o.bumps, 3);
  EXPECT_EQ(o.path_length, 4);
  EXPECT_EQ(o.diagonal_moves, 0);
  EXPECT_EQ(pathLength(o), 4);
  // On an open map the diagonal is taken and costs sqrt(2).
  const Problem open = problemOf({"...", "...", "..."});
  const Grid open_grid = decodeGrid(open);
  Episode diagonal(open, open_grid, sensor, 1, 10, Connectivity::Eight, true);
  diagonal.apply(Action::SouthEast);
  diagonal.apply(Action::SouthEast);
  EXPECT_TRUE(diagonal.outcome().passed);
  EXPECT_EQ(diagonal.outcome().diagonal_moves, 2);
  EXPECT_DOUBLE_EQ(pathLength(diagonal.outcome()), 2 * std::sqrt(2.0));
  EXPECT_EQ(diagonal.outcome().path, (std::vector<Cell>{{0, 0}, {1, 1}, {2, 2}}));
}

TEST(EpisodeTest, DiagonalUnderConnectivityFourIsAnInvalidAction) {
  const Problem open = problemOf({"...", "...", "..."});
  const Grid grid = decodeGrid(open);
  const SensorModel sensor(SensorOptions{2, 0.0});
  Episode episode(open, grid, sensor, 1, 10, Connectivity::Four);
  episode.apply(Action::East);
  episode.apply(Action::SouthEast);
  EXPECT_TRUE(episode.done());
  EXPECT_FALSE(episode.outcome().passed);
  EXPECT_STREQ(episode.outcome().reason, reason::kInvalidAction);
}

TEST(EpisodeTest, AstarTakesOctileRoutesUnderConnectivityEight) {
  // . . . .
  // . # # .
  // . . . .   start (0,0), goal (3,2). Every diagonal that would shorten the way passes beside the bar
  //           ((2,0)-(3,1) beside (2,1), (0,1)-(1,2) beside (1,1)), so the octile optimum is 5 straight moves.
  const Problem blocked = problemOf({"....", ".##.", "...."});
  EpisodeOptions options;
  options.connectivity = Connectivity::Eight;
  EpisodeRunner runner(config("astar"), options);
  auto agent = agents::makeAgent(config("astar"));
  const EpisodeOutcome o = runner.run(blocked, decodeGrid(blocked), *agent, 1);
  EXPECT_TRUE(o.passed);
  EXPECT_EQ(o.diagonal_moves, 0);
  EXPECT_EQ(o.path_length, 5);
  // 5 x 5 open: four diagonals, 4 sqrt(2), where 4-connected astar needs 8 moves.
  const Problem open = Problem::empty(5, 5, 10);
  const EpisodeOutcome d = runner.run(open, decodeGrid(open), *agent, 1);
  EXPECT_EQ(d.steps, 4);
  EXPECT_NEAR(pathLength(d), 4 * std::sqrt(2.0), 1e-12);
  EpisodeRunner four(config("astar"), EpisodeOptions{});
  EXPECT_EQ(four.run(open, decodeGrid(open), *agent, 1).steps, 8);
}

}  // namespace
}  // namespace agents
}  // namespace ppp
