#pragma once

#include <map>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_generator/generator_options.hpp"
#include "ppp_generator/genetic_algorithm.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_simulator/episode.hpp"

namespace ppp {
namespace simulator {

/// One evolved set and what else belongs in its directory.
struct EvolvedSet {
  generator::ProblemSet set;                       ///< The PPPs, fittest first.
  std::map<std::string, std::string> extra_files;  ///< File name -> contents (archive.csv, archive.svg).
  std::string summary;                             ///< One line of counters for the user.
};

/// Evolves a set as `options` say: the genetic algorithm, or the MAP-Elites archive (archive: map_elites),
/// with the named fitness or, for fitness `failure`, the failure rate of the panel `options.agents` looked up
/// in `available` (see resolvePanel) played with `episode`'s rules on `threads` threads (0: every core).
/// @throws InvalidArgument naming the option.
EvolvedSet evolveSet(const generator::GeneratorOptions& options, const std::vector<agents::AgentConfig>& available,
                     const EpisodeOptions& episode, int threads, const generator::ProgressCallback& progress = {});

/// Evolves a set with evolveSet and writes its directory (writeProblemSetDirectory plus the extra files).
EvolvedSet evolveSetDirectory(const std::string& dir, const generator::GeneratorOptions& options,
                              const std::vector<agents::AgentConfig>& available, const EpisodeOptions& episode,
                              int threads, const generator::ProgressCallback& progress = {});

}  // namespace simulator
}  // namespace ppp
