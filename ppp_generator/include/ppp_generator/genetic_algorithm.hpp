#pragma once

#include <functional>
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
  double score = 0;    ///< Fitness oriented so that larger is fitter.
};

/// Counters of one run, for logs and tests.
struct GenerationStats {
  long matings = 0;            ///< Mating events performed.
  long children_accepted = 0;  ///< Valid children that entered the pool.
  long children_pruned = 0;    ///< Children discarded by Wei's pruning (goal unreachable).
  long children_duplicate = 0; ///< Valid children discarded because their grid is already in the pool.
  long initial_redraws = 0;    ///< Unsolvable random chromosomes redrawn for the initial pool.
};

/// Called every `progress_interval` mating events and at the end: (matings done, total, best raw value).
using ProgressCallback = std::function<void(long done, long total, double best_value)>;

/// Ashlock's steady-state genetic algorithm over obstacle chromosomes with Wei's pruning.
/// Each mating event draws a tournament, the two fittest mate (one-point crossover of descriptor lists,
/// then with probability `mutation_rate` one mutation: change, add or remove a descriptor), and the valid
/// children replace the least fit of the tournament. A child whose decoded grid equals one already in the
/// pool is discarded too, so the pool keeps distinct PPPs (a set of copies is useless to a test engineer).
/// Deterministic for a seed.
class GeneticAlgorithm {
 public:
  /// Prepares a run. @throws InvalidArgument for bad options.
  explicit GeneticAlgorithm(const GeneratorOptions& options);

  /// Builds the initial pool and runs every mating event; returns the final pool in pool order.
  std::vector<Individual> run(const ProgressCallback& progress = {}, long progress_interval = 1000);

  /// Counters of the last run().
  const GenerationStats& stats() const { return stats_; }

 private:
  bool evaluate(Individual* individual);
  bool inPool(const std::vector<Individual>& pool, const Individual& candidate) const;
  Problem randomChromosome();
  void crossover(const Problem& a, const Problem& b, Problem* child_a, Problem* child_b);
  void mutate(Problem* problem);

  GeneratorOptions options_;
  Fitness fitness_;
  Rng rng_;
  DpaSolver dpa_;
  Problem shape_;
  GenerationStats stats_;
};

}  // namespace generator
}  // namespace ppp
