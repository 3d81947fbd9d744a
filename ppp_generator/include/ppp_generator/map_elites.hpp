#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "ppp_core/evaluation.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_generator/breeder.hpp"
#include "ppp_generator/genetic_algorithm.hpp"

namespace ppp {
namespace generator {

/// The range of a taxonomic character that the archive divides into bins; values outside it fall into the
/// first or last bin. Visibilities, opennesses, obstacle_use and one_turn: [0, 1]; turns: [0, W+H];
/// advances: [|dx|+|dy| of start to goal, W·H/2]; turns_plus_advances: that plus W+H at the top;
/// obstacles: [0, max_obstacles]; difficulty: [0, the sum of the weights]; BARN's: closest obstacle
/// [0, min(W,H)/2], visibility [0, max(W,H)/2], dispersion [0, 8], characteristic dimension [0, min(W,H)],
/// tortuosity the advances' range over the start-to-goal distance.
struct FeatureRange {
  double low = 0;   ///< Lower end (first bin starts here).
  double high = 1;  ///< Upper end (last bin ends here).
};

/// The range of character `name` for PPPs shaped by `options`. @throws InvalidArgument for an unknown name.
FeatureRange featureRange(const std::string& name, const GeneratorOptions& options);

/// The bin (0..bins-1) of `value` in `range`: equal-width bins, values outside clamped to the end bins.
int binOf(double value, const FeatureRange& range, int bins);

/// One occupied archive cell.
struct Elite {
  std::vector<int> bins;          ///< Bin per feature.
  std::vector<double> features;   ///< The elite's feature values.
  Individual individual;          ///< The fittest PPP that fell into this cell.
};

/// A MAP-Elites archive (Mouret and Clune): cells over two or more features, each keeping the fittest PPP
/// offered to it. A PPP replaces a cell's elite only when strictly fitter (score), so the first of equals stays.
class Archive {
 public:
  /// An archive binning `ranges.size()` features into `bins` each.
  Archive(std::vector<FeatureRange> ranges, int bins);
  /// Offers a PPP with its feature values; returns true when it became its cell's elite.
  bool offer(const Individual& individual, const std::vector<double>& features);
  /// The cell index of feature values (row-major over the bins, first feature slowest).
  long cellOf(const std::vector<double>& features) const;
  /// The occupied cells by index.
  const std::map<long, Elite>& elites() const { return elites_; }
  /// Bins per feature.
  int bins() const { return bins_; }
  /// True when some elite's grid equals `candidate`'s.
  bool holds(const Individual& candidate) const;

 private:
  std::vector<FeatureRange> ranges_;
  int bins_;
  std::map<long, Elite> elites_;
};

/// Counters of a MAP-Elites run.
struct ArchiveStats {
  long matings = 0;            ///< Variation events (two children each).
  long children_pruned = 0;    ///< Unsolvable children (Wei's pruning).
  long children_duplicate = 0; ///< Children whose grid an elite already has.
  long children_accepted = 0;  ///< Children that became an elite.
  long children_rejected = 0;  ///< Children less fit than their cell's elite.
};

/// MAP-Elites with the generator's chromosomes and operators: `population` valid PPPs (initial_pool's, then
/// random ones) seed the archive; each of `matings` events picks two elites at random, crosses and mutates them,
/// and offers the valid children to the archive. A batch fitness is scored a round of batch_size events at a time (parents
/// drawn before the round). Deterministic for a seed.
class MapElites {
 public:
  /// @throws InvalidArgument for bad options (features, bins, ...).
  MapElites(const GeneratorOptions& options, Fitness fitness);
  MapElites(const MapElites&) = delete;             ///< Its breeder refers to its own members.
  MapElites& operator=(const MapElites&) = delete;  ///< As the copy constructor.
  /// Runs the search and returns the elites, fittest first (ties in cell order), at most `population` of them.
  /// @throws Interrupted when `stop` says stop (asked before each round).
  std::vector<Individual> run(const ProgressCallback& progress = {}, long progress_interval = 1000,
                              const StopCheck& stop = {});
  /// The archive after run().
  const Archive& archive() const { return archive_; }
  /// Counters of the last run().
  const ArchiveStats& stats() const { return stats_; }

 private:
  std::vector<double> featuresOf(const Individual& individual);

  GeneratorOptions options_;
  Fitness fitness_;
  Rng rng_;
  Breeder breeder_;
  Evaluator evaluator_;
  DpaSolver dpa_;  // a child's DPA, shared by its evaluation and its BARN metrics
  Archive archive_;
  ArchiveStats stats_;
  bool barn_features_;  // some feature is a BARN metric: measure them too
};

/// The archive as CSV: one row per occupied cell (bin and value per feature, fitness value, and the set id
/// of the elite when it is in `set_ids`, keyed by grid hash).
std::string archiveCsv(const Archive& archive, const std::vector<std::string>& features,
                       const std::map<std::uint64_t, std::string>& set_ids);

/// The archive as an SVG heat map over its first two features (the fittest elite over any further ones):
/// one square per cell, shaded from the least fit elite (pale) to the fittest (dark red) whatever the fitness's
/// direction, empty cells grey, axes named after the features.
std::string archiveHeatMapSvg(const Archive& archive, const std::vector<std::string>& features,
                              const std::vector<FeatureRange>& ranges, const std::string& title);

}  // namespace generator
}  // namespace ppp
