#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_generator/generator_options.hpp"
#include "ppp_agents/episode_runner.hpp"
#include "ppp_simulator/report/reference.hpp"

namespace ppp {
namespace simulator {

/// Where one PPP set of an experiment comes from: evolved with generator options, or an existing set directory.
struct SetSpec {
  std::string name;                                      ///< Set name in results and reports.
  std::optional<generator::GeneratorOptions> generator;  ///< Evolve the set with these options...
  std::string directory;                                 ///< ...or read it from this `ppp generate` directory.
  /// A hunted set's corpus: each PPP of it that its panel fails in the experiment is shrunk into this directory,
  /// once per obstacle shape ("": none; not in the fingerprint: it changes no result).
  std::string corpus;
};

/// An experiment: every agent runs `runs` times on every PPP of every set.
struct ExperimentConfig {
  std::uint64_t seed = 1;      ///< Every run's seed derives from this one.
  int runs = 1000;             ///< Runs per agent per PPP.
  EpisodeOptions episode;      ///< Budget and sensor range.
  int threads = 0;             ///< Worker threads; 0 = every core.
  int hardest = 6;             ///< Pictures of the hardest PPPs in the report.
  int animation_frames = 301;  ///< Most frames of a failing run's animation in the report (default: budget 300 whole).
  bool shrink_worst = true;    ///< The report shows each built-in agent's pictured worst PPP shrunk (ppp shrink).
  std::vector<SetSpec> sets;   ///< The PPP sets, in report order.
  std::vector<agents::AgentConfig> agents;  ///< The agent configurations, in report order.
  std::vector<ReferenceRate> reference;     ///< Published pass rates shown beside the measured ones, in YAML order
                                            ///< (not in the fingerprint: they change no result).
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

/// The agent of `config` named `name`. @throws InvalidArgument naming "agent" when it has none so named.
const agents::AgentConfig& configAgent(const ExperimentConfig& config, const std::string& name);

/// loadExperimentConfig() on text: `yaml` is the experiment YAML of `path` (named in errors; relative paths are
/// relative to its directory, where the files it names are read). @throws ParseError, InvalidArgument, IoError
/// (a file it names).
ExperimentConfig parseExperimentConfig(const std::string& yaml, const std::string& path);

/// The set of `config` called `name`, or null.
const SetSpec* findSet(const ExperimentConfig& config, const std::string& name);

/// Where the set's PPPs are when the experiment writes to `dir`: `dir`/sets/NAME for an evolved set, else its
/// directory.
std::string setDirectory(const SetSpec& set, const std::string& dir);

/// An evolved set's generator options as run with the experiment writing to `dir`: an initial_pool naming a set
/// of the experiment (listed before it) becomes that set's directory.
generator::GeneratorOptions generatorOptionsIn(const ExperimentConfig& config, const SetSpec& set,
                                               const std::string& dir);

/// How much an experiment asks for, estimated before it starts.
struct ExperimentWork {
  double episodes = 0;       ///< Runs of agents on PPPs (sets x PPPs x agents x runs; ROS planners included).
  double hunt_episodes = 0;  ///< Episodes the panel fitnesses play while hunting (2 per mating x panel x runs).
  double matings = 0;        ///< Mating events of every evolved set.
  double result_bytes = 0;   ///< Size of results.csv (about 90 bytes a row).
};

/// Above any of these an experiment is large: it runs only when asked to explicitly (`--large`).
constexpr double kLargeEpisodes = 1e8;       ///< Episodes plus hunting episodes (the default experiment: 1.8e6 + 1.2e6).
constexpr double kLargeMatings = 1e8;        ///< Mating events in all (the default: 3e4).
constexpr double kLargeResultBytes = 1e10;   ///< results.csv bytes (the default: 1.5e8).

/// Estimates the work of `config`; sets given as directories are counted from their set.csv (0 when unreadable).
ExperimentWork estimateWork(const ExperimentConfig& config);

/// The estimate in a line ("1.8e+06 episodes, 1.2e+07 while hunting, 30000 matings, results.csv about 160 MB").
std::string workSummary(const ExperimentWork& work);

/// @throws InvalidArgument naming "work" with the estimate when it is above a limit and `allow_large` is false.
void checkWork(const ExperimentWork& work, bool allow_large);

/// Canonical text of everything that decides an experiment's results (not threads or report options);
/// stored in the output directory so a rerun can tell whether it is the same experiment.
std::string experimentFingerprint(const ExperimentConfig& config);

}  // namespace simulator
}  // namespace ppp
