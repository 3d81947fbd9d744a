#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/action.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/picture.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_agents/episode_runner.hpp"

namespace ppp {
namespace simulator {

/// Largest frame cap of an animation.
constexpr int kMaxAnimationFrames = 10000;

/// Longer side of an animation, roughly, when the cell size is chosen by map size (12 pixels per cell on 20x20).
constexpr int kAnimationTargetPixels = 240;

/// How an episode is animated.
struct AnimationOptions {
  /// Side of a cell in pixels, in [3, 64], or 0 to choose by map size: kAnimationTargetPixels / the longer map
  /// side, within [3, 12]. A map whose picture would exceed kMaxPictureSide pixels a side cannot be animated.
  int cell_pixels = 0;
  /// Most frames, in [2, kMaxAnimationFrames]. An episode of more than max_frames - 1 steps shows every stride-th
  /// step, stride = ceil(steps / (max_frames - 1)), and its last; the default shows every step of budgets up
  /// to 1,000.
  int max_frames = 1001;
  int frame_ms = 60;         ///< How long each frame is shown: a multiple of 10 ms (GIF's unit) in [20, 10000].
  int last_frame_ms = 2000;  ///< How long the last frame is held before the animation loops (same rule).
  /// @throws InvalidArgument naming "cell_pixels", "max_frames", "frame_ms" or "last_frame_ms".
  void validate() const;
};

/// The side of a cell in pixels an animation of `problem` uses under `options` (AnimationOptions::cell_pixels).
/// @throws InvalidArgument naming "map" when the picture would exceed kMaxPictureSide pixels a side.
int animationCellPixels(const Problem& problem, const AnimationOptions& options);

/// Palette colours of the animation (with picture.hpp's map colours).
constexpr Rgb kAgentColour{255, 120, 0};     ///< The agent's disc.
constexpr Rgb kBumpColour{220, 0, 200};      ///< Bump marks.
constexpr Rgb kScannedColour{255, 238, 160}; ///< Free cells in the current scan.
constexpr Rgb kUnsensedColour{214, 214, 222};  ///< Free cells the agent does not know.

/// An animated episode: how it went and its GIF.
struct EpisodeAnimation {
  EpisodeOutcome outcome;  ///< The episode, as agents::EpisodeRunner::run gives it with its path.
  std::string gif;         ///< The GIF file's bytes.
  int frames = 0;          ///< Frames in the GIF: floor(steps / stride) + 1, and one more for the last step
                           ///< when stride does not divide steps (steps + 1 when stride is 1); at most max_frames.
  int stride = 1;          ///< Steps between two frames (1 unless the cap applied).
  int width = 0;           ///< Picture columns.
  int height = 0;          ///< Picture rows.
};

/// Plays one episode of the agent `config` with `run_seed` (the same episode as EpisodeRunner::run) and draws it
/// frame by frame: frame 0 at the start, then one frame after each step (or each stride-th, see max_frames) and
/// the last. Drawing a frame costs the same whatever the episode's length (the trail and the bump marks are
/// drawn once per distinct move and bump). Each frame shows the true map, shaded where the agent has not sensed a cell or has forgotten it
/// (its memory as rebuilt from the scans it was given, with its memory window; nothing is shaded for an agent
/// given the map), the cells of the current scan tinted, the scan window outlined, the trail so far, a mark on
/// the side of a cell for every bump (towards the blocked move), start, goal, and the agent as an orange disc;
/// when the run ends in a loop (diagnoseRun()), its cycle's cells pink from the step the loop began.
/// @throws InvalidArgument for bad options, or naming "map" for a map too large to animate; Interrupted when
/// `stop`, asked before each frame, says stop.
EpisodeAnimation animateEpisode(const Problem& problem, const Grid& grid, const agents::AgentConfig& config,
                                const EpisodeOptions& options, std::uint64_t run_seed,
                                const AnimationOptions& animation = {}, const StopCheck& stop = {});

/// Draws a recorded run as animateEpisode draws a played one: the episode of `config` with `run_seed` (its scans,
/// for the memory shading) driven by `actions`, ended where they end for `reason` (results.csv's reason) unless
/// the world ended it (the goal, the budget). For the runs of planner agents, which cannot be replayed.
/// @throws InvalidArgument for an unknown reason or bad options; Error when the actions do not make that run
/// (the world ends it before or after they do); Interrupted as animateEpisode.
EpisodeAnimation animateRecordedEpisode(const Problem& problem, const Grid& grid, const agents::AgentConfig& config,
                                        const EpisodeOptions& options, std::uint64_t run_seed,
                                        const std::vector<Action>& actions, const std::string& reason,
                                        const AnimationOptions& animation = {}, const StopCheck& stop = {});

}  // namespace simulator
}  // namespace ppp
