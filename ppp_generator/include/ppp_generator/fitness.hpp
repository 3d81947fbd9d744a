#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "ppp_core/option_spec.hpp"
#include "ppp_core/dpa.hpp"
#include "ppp_core/evaluation.hpp"
#include "ppp_core/problem.hpp"

namespace ppp {
namespace generator {

/// What a fitness function may be configured with.
struct FitnessParameters {
  DifficultyWeights weights;  ///< For `difficulty`.
  std::uint64_t seed = 1;     ///< For `random`: its values come from a generator seeded with this.
};

/// What a batch scorer says of one PPP.
struct FitnessScore {
  double value = 0;  ///< The raw fitness value (e.g. a failure rate).
  double score = 0;  ///< Larger is fitter: the value oriented, plus any documented tie-break.
  double failure_rate = 0;  ///< A panel fitness: the share of the panel's runs that failed (as `failure`'s value).
  /// A panel fitness: its failed and soft-failed runs per failure signature (docs/reference/signatures.md).
  std::map<std::string, int> signatures{};
  long steps = 0;  ///< A panel fitness: the steps its runs took (moves, or control periods in continuous motion).
};

/// Scores many valid PPPs at once, in input order (`grids[i]` is the decoded grid of `problems[i]`): the
/// panel fitnesses (failure, regret) play episodes of their agents on them, in process or through the simulator node.
using BatchScorer = std::function<std::vector<FitnessScore>(const std::vector<const Problem*>& problems,
                                                            const std::vector<const Grid*>& grids)>;

/// A named fitness function: a value per valid PPP, and whether selection maximises or minimises it.
struct Fitness {
  std::string name;   ///< Registry name, e.g. "turns".
  bool maximise = true;  ///< True when larger values are fitter (harder).
  /// The raw value of a valid PPP, given its decoded grid and DPA result.
  std::function<double(const Problem&, const Grid&, const DpaResult&)> value;
  /// When set, PPPs are scored through it, `batch_size` at a time, and `value` is unused.
  BatchScorer batch;
  int batch_size = 1;  ///< PPPs per batch call (and matings per round of the generator).

  /// Fitness as "larger is fitter" whatever the direction.
  double score(double raw_value) const { return maximise ? raw_value : -raw_value; }
};

/// One registry entry, as listed by `ppp generate --help`.
struct FitnessInfo {
  std::string name;         ///< Registry name.
  bool maximise;            ///< Direction of selection.
  std::string description;  ///< One line for users.
};

/// Every registered fitness function, in registry order.
std::vector<FitnessInfo> fitnessCatalogue();

/// Comma-separated registry names, for error messages.
std::string fitnessNames();

/// The registry as an option's choices: each fitness's name and description.
std::vector<OptionChoice> fitnessChoices();

/// The fitness that is the failure rate of a panel of agents; built by makeFailureFitness
/// (failure_fitness.hpp) in process, or with the simulator node's evaluations through ROS, not by makeFitness.
constexpr const char* kFailureFitness = "failure";

/// The fitness that is a panel's mean regret: how much longer than the optimum its runs took, a failed
/// run counting as its whole budget; built like kFailureFitness.
constexpr const char* kRegretFitness = "regret";

/// True for the fitnesses that play episodes of an agent panel (kFailureFitness, kRegretFitness).
bool isPanelFitness(const std::string& name);

/// PPPs a panel fitness scores per batch (and matings per round of a hunt), in process and through ROS, unless the
/// generator's round_size says otherwise. 64: through ROS a round is one evaluation call of up to 300 lockstep
/// steps, and over four seeds rounds of 64 searched as well as rounds of 16 (BENCHMARKS.md).
constexpr int kFailureBatchSize = 64;

/// The failure fitness's score of a PPP: its failure rate plus 0.001 x the mean share of the move budget the
/// panel used, so that among PPPs failed equally often the one that kept the panel busy longest wins (a
/// gradient before the first failure is found).
FitnessScore failureScore(double failure_rate, double budget_used);

/// The regret fitness's score of a PPP: its mean regret plus 0.001 x the mean share of the move budget the panel
/// used, as failureScore() breaks ties.
FitnessScore regretScore(double regret, double budget_used);

/// Builds a fitness function by name. @throws InvalidArgument("fitness", ...) listing the valid names, and
/// for a panel fitness, which needs an agent panel.
Fitness makeFitness(const std::string& name, const FitnessParameters& parameters = {});

/// True when the named fitness (any registered name or a panel fitness) selects larger values.
/// @throws InvalidArgument("fitness", ...) for an unknown name.
bool fitnessMaximises(const std::string& name);

}  // namespace generator
}  // namespace ppp
