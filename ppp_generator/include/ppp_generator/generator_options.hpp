#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ppp_core/evaluation.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/option_spec.hpp"
#include "ppp_core/random_problem.hpp"
#include "ppp_core/yaml_reader.hpp"
#include "ppp_generator/fitness.hpp"

namespace ppp {
namespace generator {

/// Replacement rule of the dissertation: children replace the least fit of their tournament.
constexpr const char* kTournamentReplacement = "tournament";
/// Restricted tournament replacement: a child replaces the most similar of a random window if at least as fit.
constexpr const char* kCrowdingReplacement = "crowding";
/// No archive: the set is the genetic algorithm's final pool.
constexpr const char* kNoArchive = "none";
/// MAP-Elites: the set is the elites of an archive binned over taxonomic characters.
constexpr const char* kMapElitesArchive = "map_elites";
/// A hunt's archive of failures by signature: the set is one PPP per way the panel fails, picked for difference.
constexpr const char* kSignatureArchive = "signatures";
/// Largest crowding window (a window beyond the population is the whole pool).
constexpr int kMaxCrowdingWindow = 100000;
/// Most runs per evaluation of a panel fitness (failure, regret).
constexpr int kMaxRunsPerEval = 10000;
/// Most matings per round of a panel fitness (candidates scored in one call).
constexpr int kMaxRoundSize = 1024;
/// Most bins per feature of a MAP-Elites archive.
constexpr int kMaxBins = 100;
/// Most cells of a MAP-Elites archive in all (bins to the power of the features).
constexpr long kMaxArchiveCells = 100000;
/// Largest population.
constexpr int kMaxPopulation = 100000;
/// Most mating events of one run.
constexpr long kMaxMatings = 1000000000;
/// Most grid cells the generator holds at once: (population + archive cells) x width x height (2^28, about
/// 270 MB of grids), so a large population on a large map is refused before anything is allocated.
constexpr double kMaxPoolCells = 268435456;

/// Everything that shapes one run of the generator. Defaults match config/generator.yaml.
struct GeneratorOptions {
  std::string fitness = "turns";    ///< Fitness function name (see fitnessCatalogue()).
  DifficultyWeights weights;        ///< Weights of the `difficulty` fitness.
  int population = 60;              ///< PPPs in the pool, >= 2.
  long matings = 10000;             ///< Steady-state mating events, >= 0.
  int tournament_size = 4;          ///< Individuals drawn per mating event (capped at the population), >= 2.
  double mutation_rate = 0.9;       ///< Probability that a child is mutated once (change, add or remove).
  int width = 20;                   ///< Grid columns.
  int height = 20;                  ///< Grid rows.
  std::optional<Cell> start;        ///< Start cell; default top-left.
  std::optional<Cell> goal;         ///< Goal cell; default bottom-right.
  double robot_radius = 0;          ///< The robot as a disc of this radius in cells: PPPs are solvable for it.
  int max_obstacles = 10;           ///< Obstacle budget: most descriptors per chromosome, >= 0.
  int min_obstacles = 1;            ///< Fewest descriptors of a random initial chromosome (capped at max_obstacles).
  RandomObstacleOptions obstacle_shapes;  ///< Shapes and size limits of random descriptors.
  std::uint64_t seed = 1;           ///< Seed of every random choice of the run.
  std::string characters = "extended";  ///< Character set of the taxonomy (wei, extended or barn).
  std::string replacement = kCrowdingReplacement;  ///< kCrowdingReplacement or kTournamentReplacement.
  int crowding_window = 20;         ///< Pool members a child is compared with under crowding (capped at the pool).
  std::vector<std::string> agents;  ///< Panel fitness: the panel's agent names.
  std::string agents_file;          ///< Panel fitness: agents file the names resolve in ("": built-in types).
  int runs_per_eval = 20;           ///< Panel fitness: episodes per agent per evaluated PPP.
  int round_size = kFailureBatchSize;  ///< Panel fitness: matings per round, their children scored together.
  std::string archive = kNoArchive; ///< kNoArchive, kMapElitesArchive or kSignatureArchive.
  std::vector<std::string> features{"turns", "obstacles"};  ///< MAP-Elites: characters binned (two or more).
  int bins = 8;                     ///< MAP-Elites: bins per feature.
  std::string initial_pool;         ///< Directory of .ppp files the initial pool starts from ("": all random).

  /// Checks every option. @throws InvalidArgument naming the option and what was expected.
  void validate() const;
  /// The start cell in effect.
  Cell startCell() const { return start ? *start : Cell{0, 0}; }
  /// The goal cell in effect.
  Cell goalCell() const { return goal ? *goal : Cell{width - 1, height - 1}; }
};

/// Every option of GeneratorOptions, declared once: the YAML keys, the generator node's `~` parameters and the
/// `ppp generate` flags are these (config/generator.yaml is generatorOptionsYaml(defaults, true)).
const std::vector<OptionSpec<GeneratorOptions>>& generatorOptionSpecs();

/// Applies the keys of a generator YAML mapping (config/generator.yaml) over `options`.
/// @throws ParseError naming the file, line and key for unknown keys and wrong types.
void applyGeneratorYaml(YamlMapReader& reader, GeneratorOptions* options);

/// Loads config/generator.yaml-style options from a file, over the defaults.
/// @throws IoError, ParseError, InvalidArgument.
GeneratorOptions loadGeneratorOptions(const std::string& path);

/// Parses generator options from YAML text (as generatorOptionsYaml() writes it) coming from `source` (the file
/// or parameter named in errors), over the defaults. @throws ParseError.
GeneratorOptions parseGeneratorOptions(const std::string& yaml_text, const std::string& source);

/// The options as YAML in the config file's format (written with every generated set); with `docs`, each with its
/// one-line doc and range, as config/generator.yaml ships.
std::string generatorOptionsYaml(const GeneratorOptions& options, bool docs = false);

}  // namespace generator
}  // namespace ppp
