#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/continuous_episode.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_simulator/report/episode_animation.hpp"

namespace ppp {
namespace simulator {

/// Palette colours of a continuous run's animation (with picture.hpp's and episode_animation.hpp's).
constexpr Rgb kBeamColour{250, 214, 120};     ///< The laser's beams.
constexpr Rgb kBeamHitColour{230, 30, 30};    ///< Where a beam meets a square or the border.

/// An animated continuous run: how it went and its GIF.
struct ContinuousAnimation {
  ContinuousOutcome outcome;  ///< The run with its poses (agents::ContinuousRunner::run).
  std::string gif;            ///< The GIF file's bytes.
  int frames = 0;             ///< Frames: the start, every stride-th control period, and the last.
  int stride = 1;             ///< Control periods between two frames.
};

/// Plays one continuous run of `config` with `run_seed` (the run agents::ContinuousRunner plays) and draws it:
/// frame 0 at the start, then every stride-th control period (stride as AnimationOptions::max_frames says) and
/// the last. Each frame shows the map, the laser's beams from the robot (noise-free: where each beam meets a
/// square or the border, red, and every sixth beam as a line), the trajectory so far over them, and the robot as an orange disc
/// of its radius (at least a few pixels) with a line along its heading.
/// @throws InvalidArgument for bad options, or naming "map" for a map too large to animate; Interrupted when
/// `stop`, asked before each frame, says stop.
ContinuousAnimation animateContinuousRun(const Problem& problem, const Grid& grid, const agents::AgentConfig& config,
                                         const EpisodeOptions& options, std::uint64_t run_seed,
                                         const AnimationOptions& animation = {}, const StopCheck& stop = {});

/// animateContinuousRun() of a planner's run played again from its recorded `commands`, ended as `end_reason`
/// (agents::recordedContinuousRun()). @throws as both.
ContinuousAnimation animateRecordedContinuousRun(const Problem& problem, const Grid& grid,
                                                 const agents::AgentConfig& config, const EpisodeOptions& options,
                                                 std::uint64_t run_seed, const std::vector<BodyVelocity>& commands,
                                                 const std::string& end_reason, const AnimationOptions& animation = {},
                                                 const StopCheck& stop = {});

/// Draws the run `outcome` (with its poses) of PPP `problem` (decoded as `grid`) under `options` as
/// animateContinuousRun() does.
ContinuousAnimation drawContinuousRun(const Problem& problem, const Grid& grid, const EpisodeOptions& options,
                                      ContinuousOutcome outcome, const AnimationOptions& animation = {},
                                      const StopCheck& stop = {});

}  // namespace simulator
}  // namespace ppp
