#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ppp_core/dpa.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_generator/generator_options.hpp"

namespace ppp {
namespace generator {

/// One member of the pool: a valid PPP and its fitness.
struct Individual {
  Problem problem;     ///< Always valid (goal reachable).
  Grid grid;           ///< The decoded grid.
  std::uint64_t grid_hash = 0;  ///< Hash of the grid's cells, to find duplicates quickly.
  double value = 0;    ///< Raw fitness value.
  double score = 0;    ///< Fitness oriented so that larger is fitter (may carry a tie-break, see FitnessScore).
  std::map<std::string, int> signatures;  ///< A panel fitness: failed runs per failure signature.
};

/// The variation operators and the evaluation shared by the genetic algorithm and the MAP-Elites archive:
/// random chromosomes, one-point crossover, mutation (change, add or remove one descriptor), decoding with
/// Wei's pruning, and scoring one PPP at a time or through the fitness's batch scorer. Every random choice
/// comes from the one generator it is given.
class Breeder {
 public:
  /// Operators for `options` (validated by the caller) drawing from `rng`, scoring with `fitness`.
  /// @throws InvalidArgument naming "start" or "goal" when the robot (robot_radius) cannot stand there.
  Breeder(const GeneratorOptions& options, const Fitness& fitness, Rng* rng);

  /// A chromosome of 1..max_obstacles random descriptors.
  Problem randomChromosome();
  /// A random chromosome that decodes to a solvable PPP (decode() done); unsolvable draws are counted in
  /// `redraws`. @throws InvalidArgument("population", ...) once `redraws` passes kMaxRandomRedraws.
  Individual randomSolvable(long* redraws);
  /// One-point crossover of descriptor lists: a[0, i) + b[j, end) and b[0, j) + a[i, end), capped to the budget.
  void crossover(const Problem& a, const Problem& b, Problem* child_a, Problem* child_b);
  /// With probability mutation_rate: change, add or remove one descriptor.
  void mutate(Problem* problem);
  /// Decodes the grid and its hash; false when the goal is unreachable (Wei's pruning). For a fitness
  /// without a batch scorer the value and score are set too.
  bool decode(Individual* individual);
  /// Scores decoded individuals that have no score yet (a batch fitness: in calls of batch_size).
  /// @throws InvalidArgument("fitness", ...) when a batch scorer answers with the wrong number of scores.
  void score(const std::vector<Individual*>& individuals);
  /// True when the fitness scores in batches (then decode() leaves value and score unset).
  bool batched() const { return static_cast<bool>(fitness_.batch); }
  /// Matings per round: the batch size of a batch fitness, else 1.
  int roundSize() const { return batched() ? fitness_.batch_size : 1; }

 private:
  GeneratorOptions options_;
  const Fitness& fitness_;
  Rng* rng_;
  DpaSolver dpa_;
  Problem shape_;
};

/// Most unsolvable or repeated random chromosomes drawn for a starting pool before giving up.
constexpr long kMaxRandomRedraws = 1000000;

/// True when `candidate`'s grid equals the grid of a member of `pool`.
bool gridInPool(const std::vector<Individual>& pool, const Individual& candidate);

}  // namespace generator
}  // namespace ppp
