#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_generator/generator_options.hpp"
#include "ppp_simulator/episode.hpp"

namespace ppp {
namespace simulator {

/// Where one PPP set of an experiment comes from: evolved with generator options, or an existing set directory.
struct SetSpec {
  std::string name;                                      ///< Set name in results and reports.
  std::optional<generator::GeneratorOptions> generator;  ///< Evolve the set with these options...
  std::string directory;                                 ///< ...or read it from this `ppp generate` directory.
};

/// An experiment: every agent runs `runs` times on every PPP of every set (SPEC 8).
struct ExperimentConfig {
  std::uint64_t seed = 1;      ///< Every run's seed derives from this one.
  int runs = 1000;             ///< Runs per agent per PPP.
  EpisodeOptions episode;      ///< Budget and sensor range.
  int threads = 0;             ///< Worker threads; 0 = every core.
  int hardest = 6;             ///< Pictures of the hardest PPPs in the report.
  std::vector<SetSpec> sets;   ///< The PPP sets, in report order.
  std::vector<agents::AgentConfig> agents;  ///< The agent configurations, in report order.
  /// @throws InvalidArgument naming the field.
  void validate() const;
  /// Runs per PPP of `agent`: its own `runs`, or the experiment's.
  int runsFor(const agents::AgentConfig& agent) const { return agent.runs > 0 ? agent.runs : runs; }
};

/// Most pictures of hardest PPPs in a report.
constexpr int kMaxHardest = 1000;

/// One declaration per experiment-wide option (the top-level keys of an experiment YAML besides sets and agents;
/// `ppp experiment --threads`).
const std::vector<OptionSpec<ExperimentConfig>>& experimentOptionSpecs();

/// Loads an experiment YAML (see config/experiment.yaml). Relative paths (agents file, set directories) are
/// relative to the YAML's directory; sets' `generator` keys override that directory's generator.yaml.
/// @throws IoError, ParseError (file:line: key: what), InvalidArgument.
ExperimentConfig loadExperimentConfig(const std::string& path);

/// Canonical text of everything that decides an experiment's results (not threads or report options);
/// stored in the output directory so a rerun can tell whether it is the same experiment.
std::string experimentFingerprint(const ExperimentConfig& config);

}  // namespace simulator
}  // namespace ppp
