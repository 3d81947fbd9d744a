#pragma once

#include <functional>
#include <vector>

#include "ppp_core/rng.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_generator/breeder.hpp"
#include "ppp_generator/signature_archive.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_generator/generator_options.hpp"

namespace ppp {
namespace generator {

/// Counters of one run, for logs and tests.
struct GenerationStats {
  long matings = 0;            ///< Mating events performed.
  long children_accepted = 0;  ///< Valid children that entered the pool.
  long children_pruned = 0;    ///< Children discarded by Wei's pruning (goal unreachable).
  long children_duplicate = 0; ///< Valid children discarded because their grid is already in the pool.
  long children_rejected = 0;  ///< Valid children that lost to the member they would have replaced (crowding).
  long children_novel = 0;     ///< archive signatures: children that showed a failure signature new to the archive.
  long initial_redraws = 0;    ///< Unsolvable or repeated random chromosomes redrawn for the initial pool.
};

/// Called every `progress_interval` mating events and at the end: (matings done, total, best raw value).
using ProgressCallback = std::function<void(long done, long total, double best_value)>;

/// Ashlock's steady-state genetic algorithm over obstacle chromosomes with Wei's pruning.
/// Each mating event draws a tournament, the two fittest mate (one-point crossover of descriptor lists,
/// then with probability `mutation_rate` one mutation: change, add or remove a descriptor). Replacement:
/// `tournament` (the dissertation's): the valid children replace the least fit of the tournament;
/// `crowding` (restricted tournament replacement): each valid child is compared with the most similar
/// (fewest differing cells) of `crowding_window` random pool members and replaces it if at least as fit, so
/// a good layout can only push out its own near-copies and the pool keeps many layouts. A child whose
/// grid is already in the pool is discarded, so the pool holds distinct PPPs.
/// A batch fitness (failure, regret) is scored a round of batch_size matings at a time: the round's parents are
/// drawn from the pool as it was before the round, and the children enter in mating order afterwards (under
/// `tournament` replacement into the tournament slots drawn before the round, so a later mating of the round
/// may replace an earlier one's child).
/// `archive: signatures` (a panel fitness): every scored PPP is offered to a SignatureArchive, and a child that
/// shows a failure signature the archive did not hold enters the pool whatever its score (under crowding it
/// replaces its nearest rival), so the search keeps each new way of failing as a stepping stone; a tournament
/// ranks equally fit PPPs by how seldom the archive has seen their rarest signature. Half the matings (a coin per
/// mating) take both parents from the archive instead (SignatureArchive::randomElite(): the rarer a signature, the
/// likelier), and its hardest passed PPP climbs towards the failures that easier ones hide. The set is drawn from
/// the archive (SignatureArchive::diverseSet()).
/// Deterministic for a seed.
class GeneticAlgorithm {
 public:
  /// Prepares a run with the fitness named in the options. @throws InvalidArgument for bad options.
  explicit GeneticAlgorithm(const GeneratorOptions& options);
  /// Prepares a run with a fitness built elsewhere (a panel fitness). @throws InvalidArgument.
  GeneticAlgorithm(const GeneratorOptions& options, Fitness fitness);
  GeneticAlgorithm(const GeneticAlgorithm&) = delete;             ///< Its breeder refers to its own members.
  GeneticAlgorithm& operator=(const GeneticAlgorithm&) = delete;  ///< As the copy constructor.

  /// Builds the initial pool (options.initial_pool's PPPs first, then random ones) and runs every mating event;
  /// returns the final pool in pool order, or under `archive: signatures` the archive's diverseSet() of
  /// `population` PPPs (the final pool filling what the archive leaves).
  /// @throws Interrupted when `stop` says stop (asked before each PPP of the initial pool and each round).
  std::vector<Individual> run(const ProgressCallback& progress = {}, long progress_interval = 1000,
                              const StopCheck& stop = {});

  /// Counters of the last run().
  const GenerationStats& stats() const { return stats_; }
  /// The failures of the last run() by signature (empty unless `archive: signatures`).
  const SignatureArchive& signatureArchive() const { return signatures_; }

 private:
  std::vector<Individual> initialPool(const StopCheck& stop);
  bool keepsSignatures() const;
  void replace(std::vector<Individual>* pool, const std::vector<int>& tournament, Individual* child, int* replaced);

  GeneratorOptions options_;
  Fitness fitness_;
  Rng rng_;
  Breeder breeder_;
  GenerationStats stats_;
  SignatureArchive signatures_;
};

/// Draws up to `count` distinct pool indices below `size` (a partial Fisher-Yates shuffle of `order`).
std::vector<int> drawDistinct(Rng* rng, int size, int count);

}  // namespace generator
}  // namespace ppp
