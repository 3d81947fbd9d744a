#include "ppp_simulator/report/episode_animation.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ppp_core/diagnosis.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/gif_animation.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace simulator {
namespace {

agents::AgentConfig agentConfig(const std::string& type, int memory_window = 0) {
  agents::AgentConfig c;
  c.type = type;
  c.name = type;
  c.memory_window = memory_window;
  return c;
}

/// A solvable 20x20 PPP with 20 random obstacles, drawn from a fixed seed.
Problem obstacleProblem() {
  Rng rng(5);
  return randomProblem(rng, Problem::empty(20, 20, 20), 20);
}

/// The colour shown at a cell's centre in frame `frame` (12 pixels per cell: the size chosen for 20x20 maps).
Rgb centreColour(const GifMovie& movie, int frame, Cell c) {
  const Pixel p = cellCentre(c, PictureOptions{12, true});
  const std::uint8_t* rgb = &movie.frames.at(frame).rgb[(static_cast<std::size_t>(p.y) * movie.width + p.x) * 3];
  return Rgb{rgb[0], rgb[1], rgb[2]};
}

/// The cells whose centre shows the agent's colour in a frame.
std::vector<Cell> agentCells(const GifMovie& movie, int frame, const Problem& problem) {
  std::vector<Cell> cells;
  for (int y = 0; y < problem.height; ++y) {
    for (int x = 0; x < problem.width; ++x) {
      if (centreColour(movie, frame, Cell{x, y}) == kAgentColour) cells.push_back(Cell{x, y});
    }
  }
  return cells;
}

bool anyPixel(const GifFrame& frame, Rgb colour) {
  for (std::size_t i = 0; i < frame.rgb.size(); i += 3) {
    if (Rgb{frame.rgb[i], frame.rgb[i + 1], frame.rgb[i + 2]} == colour) return true;
  }
  return false;
}

TEST(EpisodeAnimationTest, OneFramePerStepPlusTheStartWithTheAgentMovingACellAtATime) {
  const Problem problem = obstacleProblem();
  const Grid grid = decodeGrid(problem);
  for (const std::string type : {"bumper", "wall_follower_left", "explorer"}) {
    const EpisodeAnimation a = animateEpisode(problem, grid, agentConfig(type), EpisodeOptions{}, 3);
    agents::EpisodeRunner runner(agentConfig(type), EpisodeOptions{});
    auto agent = agents::makeAgent(agentConfig(type));
    const EpisodeOutcome run = runner.run(problem, grid, *agent, 3, true);
    EXPECT_EQ(a.outcome.steps, run.steps) << type;  // the same episode as a run with that seed
    EXPECT_EQ(a.outcome.path, run.path) << type;
    const GifMovie movie = decodeGif(a.gif, type + ".gif");
    ASSERT_EQ(static_cast<int>(movie.frames.size()), run.steps + 1) << type;
    EXPECT_EQ(a.frames, run.steps + 1);
    EXPECT_EQ(a.stride, 1);
    Cell previous = problem.start;
    for (int f = 0; f < static_cast<int>(movie.frames.size()); ++f) {
      const std::vector<Cell> cells = agentCells(movie, f, problem);
      ASSERT_EQ(cells.size(), 1u) << type << " frame " << f;
      EXPECT_LE(std::abs(cells[0].x - previous.x) + std::abs(cells[0].y - previous.y), 1) << type << " frame " << f;
      previous = cells[0];
      EXPECT_EQ(movie.frames[f].delay_centiseconds, f + 1 < static_cast<int>(movie.frames.size()) ? 6 : 200);
    }
    EXPECT_EQ(agentCells(movie, 0, problem)[0], problem.start) << type;
    EXPECT_EQ(previous, run.path.back()) << type << ": the last frame shows the agent where the episode ended";
    EXPECT_EQ(anyPixel(movie.frames.back(), kBumpColour), run.bumps > 0) << type << " bumped " << run.bumps;
  }
}

TEST(EpisodeAnimationTest, TheSameSeedGivesTheSameBytes) {
  const Problem problem = obstacleProblem();
  const Grid grid = decodeGrid(problem);
  const std::string once = animateEpisode(problem, grid, agentConfig("random"), EpisodeOptions{}, 11).gif;
  EXPECT_EQ(animateEpisode(problem, grid, agentConfig("random"), EpisodeOptions{}, 11).gif, once);
  EXPECT_NE(animateEpisode(problem, grid, agentConfig("random"), EpisodeOptions{}, 12).gif, once);
}

/// The run of `config` with `seed`, stepping Episode directly: its actions, and where the agent stands after each
/// step (entry 0: the start).
struct PlayedRun {
  std::vector<Action> actions;
  std::vector<Cell> positions;
};
PlayedRun playRun(const Problem& problem, const Grid& grid, const agents::AgentConfig& config, std::uint64_t seed) {
  const EpisodeOptions options;
  agents::EpisodeRunner runner(config, options);
  auto agent = agents::makeAgent(config);
  agent->reset(agents::episodeInfo(problem, grid, config, seed, options.connectivity));
  Episode episode(problem, grid, runner.sensor(), seed, options.budget, options.connectivity, true);
  PlayedRun run{{}, {problem.start}};
  while (!episode.done()) {
    run.actions.push_back(agent->act(episode.scan()));
    episode.apply(run.actions.back());
    run.positions.push_back(episode.outcome().path.back());
  }
  return run;
}

TEST(EpisodeAnimationTest, LongEpisodesShowEveryStrideThStepAndTheLast) {
  const Problem problem = Problem::empty(20, 20, 0);  // random on an empty map: 300 steps, no pass, for this seed
  const Grid grid = decodeGrid(problem);
  AnimationOptions options;
  options.max_frames = 11;
  const EpisodeAnimation a = animateEpisode(problem, grid, agentConfig("random"),
                                            EpisodeOptions{}, 5, options);
  ASSERT_EQ(a.outcome.steps, 300) << "the seed was chosen for an episode that uses the whole budget";
  EXPECT_EQ(a.stride, 30);  // ceil(300 / 10)
  EXPECT_EQ(a.frames, 11);  // steps 0, 30, ..., 300
  const GifMovie capped = decodeGif(a.gif, "capped.gif");
  ASSERT_EQ(capped.frames.size(), 11u);
  const std::vector<Cell> at = playRun(problem, grid, agentConfig("random"), 5).positions;
  for (int f = 0; f < 11; ++f) {
    EXPECT_EQ(agentCells(capped, f, problem), std::vector<Cell>{at[30 * f]}) << "frame " << f << ": step " << 30 * f;
  }
  // An episode whose steps the stride does not divide: 0, s, 2s, ... and its last step.
  options.max_frames = 4;
  const EpisodeAnimation b = animateEpisode(problem, grid, agentConfig("astar"), EpisodeOptions{}, 5, options);
  ASSERT_EQ(b.outcome.steps, 38);  // the shortest route corner to corner
  EXPECT_EQ(b.stride, 13);         // ceil(38 / 3)
  EXPECT_EQ(b.frames, 4);          // steps 0, 13, 26 and 38
  const GifMovie uneven = decodeGif(b.gif, "uneven.gif");
  const std::vector<Cell> route = playRun(problem, grid, agentConfig("astar"), 5).positions;
  const int shown[] = {0, 13, 26, 38};
  ASSERT_EQ(uneven.frames.size(), 4u);
  for (int f = 0; f < 4; ++f) {
    EXPECT_EQ(agentCells(uneven, f, problem), std::vector<Cell>{route[shown[f]]}) << "frame " << f;
  }
}

TEST(EpisodeAnimationTest, ShadesWhatTheAgentHasNotSensedOrHasForgotten) {
  const Problem problem = Problem::empty(20, 20, 0);
  const Grid grid = decodeGrid(problem);
  const EpisodeAnimation full = animateEpisode(problem, grid, agentConfig("explorer"), EpisodeOptions{}, 1);
  const GifMovie movie = decodeGif(full.gif, "explorer.gif");
  EXPECT_EQ(centreColour(movie, 0, Cell{1, 1}), kScannedColour);   // in the first scan
  EXPECT_EQ(centreColour(movie, 0, Cell{10, 10}), kUnsensedColour);  // far from the start
  // The known map agent shades nothing.
  const GifMovie astar = decodeGif(animateEpisode(problem, grid, agentConfig("astar"), EpisodeOptions{}, 1).gif, "a.gif");
  EXPECT_FALSE(anyPixel(astar.frames[0], kUnsensedColour));
  // With a 5x5 memory, cells seen at the start and off the trail are forgotten once the agent is far away; with
  // full memory they stay known (white).
  const EpisodeAnimation limited = animateEpisode(problem, grid, agentConfig("explorer", 5), EpisodeOptions{}, 1);
  const GifMovie forgetful = decodeGif(limited.gif, "limited.gif");
  const std::set<std::pair<int, int>> trail_full = [&] {
    std::set<std::pair<int, int>> s;
    for (const Cell c : full.outcome.path) s.insert({c.x, c.y});
    for (const Cell c : limited.outcome.path) s.insert({c.x, c.y});
    return s;
  }();
  int checked = 0;
  for (int y = 0; y <= 2; ++y) {
    for (int x = 0; x <= 2; ++x) {
      if (trail_full.count({x, y}) != 0 || Cell{x, y} == problem.start) continue;
      EXPECT_EQ(centreColour(movie, static_cast<int>(movie.frames.size()) - 1, Cell{x, y}), kFreeColour);
      EXPECT_EQ(centreColour(forgetful, static_cast<int>(forgetful.frames.size()) - 1, Cell{x, y}), kUnsensedColour);
      ++checked;
    }
  }
  EXPECT_GT(checked, 0) << "no cell near the start was off both trails";
}

TEST(EpisodeAnimationTest, ALoopsCycleIsPinkFromTheStepTheLoopBegan) {
  // The first of some random maps on which the left wall follower ends in a loop.
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    Rng rng(seed);
    const Problem problem = randomProblem(rng, Problem::empty(20, 20, 20), 20);
    const EpisodeAnimation played =
        animateEpisode(problem, decodeGrid(problem), agentConfig("wall_follower_left"), EpisodeOptions{}, 1);
    const EpisodeOutcome& o = played.outcome;
    const Diagnosis d = diagnoseRun(o.passed, false, o.reason, o.cells);
    if (std::string(d.kind) != diagnosis::kLoop || d.step == 0) continue;
    const GifMovie movie = decodeGif(played.gif, "loop.gif");
    ASSERT_EQ(movie.frames.size(), static_cast<std::size_t>(o.steps) + 1);  // a frame per step
    EXPECT_FALSE(anyPixel(movie.frames[static_cast<std::size_t>(d.step) - 1], kMarkedColour)) << "seed " << seed;
    EXPECT_TRUE(anyPixel(movie.frames[static_cast<std::size_t>(d.step)], kMarkedColour)) << "seed " << seed;
    EXPECT_TRUE(anyPixel(movie.frames.back(), kMarkedColour)) << "seed " << seed;
    // A run that is no loop shows no pink at all.
    const EpisodeAnimation straight = animateEpisode(problem, decodeGrid(problem), agentConfig("astar"), EpisodeOptions{}, 1);
    EXPECT_FALSE(anyPixel(decodeGif(straight.gif, "astar.gif").frames.back(), kMarkedColour));
    return;
  }
  FAIL() << "the wall follower looped on none of the maps";
}

TEST(EpisodeAnimationTest, ChoosesTheCellSizeByMapSizeAndRefusesMapsTooLargeToAnimate) {
  const agents::AgentConfig astar = agentConfig("astar");
  const Problem small = Problem::empty(20, 20, 0);
  EXPECT_EQ(animateEpisode(small, decodeGrid(small), astar, EpisodeOptions{}, 1).width, 20 * 12 + 1);
  const Problem wide = Problem::empty(200, 10, 0);  // 240 / 200 -> at least 3 pixels per cell
  EXPECT_EQ(animateEpisode(wide, decodeGrid(wide), astar, EpisodeOptions{}, 1).width, 200 * 3 + 1);
  const Problem huge = Problem::empty(2731, 2, 0);  // 2731 * 3 + 1 = 8194 pixels > 8192
  try {
    animateEpisode(huge, decodeGrid(huge), astar, EpisodeOptions{}, 1);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "map");
    EXPECT_NE(std::string(e.what()).find("too large to animate at 3 pixels per cell (at most 2730 cells a side"),
              std::string::npos) << e.what();
  }
}

TEST(EpisodeAnimationTest, AStopCheckIsAskedBeforeEachFrame) {
  const Problem problem = obstacleProblem();
  int asked = 0;
  const StopCheck stop_at_the_fifth = [&asked] { return ++asked == 5; };
  EXPECT_THROW(animateEpisode(problem, decodeGrid(problem), agentConfig("random"), EpisodeOptions{}, 1, {},
                              stop_at_the_fifth),
               Interrupted);
  EXPECT_EQ(asked, 5);
}

// A recorded run drawn from its actions is the played run drawn: the same bytes, for a run that reaches the goal
// (wall follower) and one that spends its budget (bumper).
TEST(EpisodeAnimationTest, ARecordedRunIsDrawnAsThePlayedOne) {
  const Problem problem = obstacleProblem();
  const Grid grid = decodeGrid(problem);
  for (const std::string type : {"wall_follower_left", "bumper"}) {
    const EpisodeAnimation played = animateEpisode(problem, grid, agentConfig(type), EpisodeOptions{}, 3);
    const std::vector<Action> actions = playRun(problem, grid, agentConfig(type), 3).actions;
    const EpisodeAnimation recorded = animateRecordedEpisode(problem, grid, agentConfig(type), EpisodeOptions{}, 3,
                                                             actions, played.outcome.reason);
    EXPECT_EQ(recorded.gif, played.gif) << type;
    EXPECT_EQ(recorded.outcome.path, played.outcome.path) << type;
    EXPECT_EQ(recorded.outcome.reason, played.outcome.reason) << type;
  }
}

// A planner's run that ended early (its planner found no path at step 3) ends there with that reason; actions
// that do not make the recorded run, and reasons no episode ends for, are refused.
TEST(EpisodeAnimationTest, ARecordedRunEndsWhereAndWhyItsRowSays) {
  const Problem problem = Problem::empty(5, 5, 1);
  const Grid grid = decodeGrid(problem);
  const std::vector<Action> three = {Action::East, Action::East, Action::South};
  const EpisodeAnimation a =
      animateRecordedEpisode(problem, grid, agentConfig("explorer"), EpisodeOptions{}, 1, three, "no_path");
  EXPECT_EQ(a.outcome.steps, 3);
  EXPECT_EQ(a.outcome.reason, std::string(reason::kNoPath));
  EXPECT_EQ(a.outcome.path.back(), (Cell{2, 1}));
  EXPECT_EQ(decodeGif(a.gif, "no_path.gif").frames.size(), 4u);
  // The row says the goal was reached, but three moves do not reach it.
  EXPECT_THROW(animateRecordedEpisode(problem, grid, agentConfig("explorer"), EpisodeOptions{}, 1, three,
                                      "goal_reached"),
               Error);
  // Eight moves reach the goal; a row saying the run ended after three does not match them.
  std::vector<Action> eight(4, Action::East);
  eight.insert(eight.end(), 4, Action::South);
  EXPECT_EQ(animateRecordedEpisode(problem, grid, agentConfig("explorer"), EpisodeOptions{}, 1, eight, "goal_reached")
                .outcome.steps,
            8);
  eight.push_back(Action::North);  // a move after the goal: the world ended the run first
  EXPECT_THROW(animateRecordedEpisode(problem, grid, agentConfig("explorer"), EpisodeOptions{}, 1, eight,
                                      "goal_reached"),
               Error);
  try {
    animateRecordedEpisode(problem, grid, agentConfig("explorer"), EpisodeOptions{}, 1, three, "lost_in_space");
    ADD_FAILURE() << "an unknown reason was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "reason");
  }
}

TEST(EpisodeAnimationTest, RejectsBadOptionsByName) {
  const Problem problem = Problem::empty(5, 5, 0);
  const Grid grid = decodeGrid(problem);
  const auto error = [&](AnimationOptions o) {
    try {
      animateEpisode(problem, grid, agentConfig("astar"), EpisodeOptions{}, 1, o);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  AnimationOptions o;
  o.max_frames = 1;
  EXPECT_NE(error(o).find("max_frames"), std::string::npos) << error(o);
  o = AnimationOptions{};
  o.frame_ms = 65;
  EXPECT_NE(error(o).find("frame_ms: expected a multiple of 10 ms"), std::string::npos) << error(o);
  o = AnimationOptions{};
  o.cell_pixels = 2;
  EXPECT_NE(error(o).find("cell_pixels"), std::string::npos) << error(o);
}

}  // namespace
}  // namespace simulator
}  // namespace ppp
