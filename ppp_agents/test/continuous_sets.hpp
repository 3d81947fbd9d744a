#pragma once

// What the continuous-motion tests play: the A* control, continuous options for a disc of 0.3 cells, two small sets
// of random PPPs and a seed per run.

#include <cstdint>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/prepared_set.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/rng.hpp"

namespace ppp {
namespace agents {
namespace test {

inline AgentConfig astar() {
  AgentConfig config;
  config.name = config.type = "astar";
  return config;
}

/// Continuous motion for a disc of 0.3 cells with `kinematics`.
inline EpisodeOptions continuousOptions(const char* kinematics = kKinematicsDiffDrive) {
  EpisodeOptions options;
  options.motion.motion = kMotionContinuous;
  options.motion.kinematics = kinematics;
  options.robot_radius = 0.3;
  return options;
}

/// Two sets ("a", "b") of three random 12x12 PPPs of 6 descriptors, drawn from `seed`.
inline std::vector<PreparedSet> smallSets(const EpisodeOptions& options, std::uint64_t seed) {
  std::vector<PreparedSet> sets;
  Rng rng(seed);
  for (const char* name : {"a", "b"}) {
    ProblemSet set;
    for (int i = 0; i < 3; ++i) {
      set.ids.push_back("ppp_00" + std::to_string(i));
      set.problems.push_back(randomProblem(rng, Problem::empty(12, 12, 6), 6));
    }
    sets.push_back(prepareSet(name, set, options));
  }
  return sets;
}

/// The seed of run `run` of PPP `problem` of set `set`.
inline std::uint64_t seedOf(int set, int problem, int run) {
  return deriveSeed(5, {static_cast<std::uint64_t>(set), static_cast<std::uint64_t>(problem),
                        static_cast<std::uint64_t>(run)});
}

}  // namespace test
}  // namespace agents
}  // namespace ppp
