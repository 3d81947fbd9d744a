#include "ppp_generator/generator_options.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/option_yaml.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_generator/taxonomy.hpp"

namespace ppp {
namespace generator {

namespace {

/// Largest generator options file read (the options are a few hundred bytes).
constexpr std::size_t kMaxOptionsBytes = 1u << 20;

/// The panel fitnesses' and the archive's options.
void validateHuntOptions(const GeneratorOptions& o) {
  const bool panel = isPanelFitness(o.fitness);
  if (panel && o.agents.empty()) {
    throw InvalidArgument("agents", "empty panel: the " + o.fitness + " fitness needs at least one agent name");
  }
  if (o.archive == kSignatureArchive && !panel) {
    throw InvalidArgument("archive", "'" + std::string(kSignatureArchive) + "' keeps a panel's failures by signature, "
                                     "and fitness '" + o.fitness + "' plays no panel; use it with failure or regret");
  }
  if (!panel && !o.agents.empty()) {
    throw InvalidArgument("agents", "only the panel fitnesses (failure, regret) use an agent panel");
  }
  for (std::size_t i = 0; i < o.agents.size(); ++i) {
    if (o.agents[i].empty()) throw InvalidArgument("agents", "empty agent name");
    for (std::size_t j = 0; j < i; ++j) {
      if (o.agents[i] == o.agents[j]) throw InvalidArgument("agents", "'" + o.agents[i] + "' named twice");
    }
  }
  if (o.features.size() < 2) {
    throw InvalidArgument("features", "expected two or more character names, got " + std::to_string(o.features.size()));
  }
  const std::vector<std::string>& names = availableCharacterNames();
  for (std::size_t i = 0; i < o.features.size(); ++i) {
    if (std::find(names.begin(), names.end(), o.features[i]) == names.end()) {
      throw InvalidArgument("features", "unknown character '" + o.features[i] + "'; valid: " + joinNames(names));
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (o.features[i] == o.features[j]) throw InvalidArgument("features", "'" + o.features[i] + "' named twice");
    }
  }
  double cells = 1.0;
  for (std::size_t i = 0; i < o.features.size(); ++i) cells *= o.bins;
  if (cells > static_cast<double>(kMaxArchiveCells)) {
    throw InvalidArgument("bins", "bins^features = " + formatShortest(cells) + " archive cells; at most " +
                                      std::to_string(kMaxArchiveCells));
  }
}

}  // namespace

void GeneratorOptions::validate() const {
  checkOptionRanges(generatorOptionSpecs(), *this);
  if (isPanelFitness(fitness)) {
    fitnessMaximises(fitness);
  } else {
    makeFitness(fitness, FitnessParameters{weights, seed});
  }
  validateHuntOptions(*this);
  const double archive_cells = archive == kMapElitesArchive ? std::pow(bins, static_cast<double>(features.size())) : 0;
  const double pool_cells = (population + archive_cells) * width * height;
  if (pool_cells > kMaxPoolCells) {
    throw InvalidArgument("population", "(population " + std::to_string(population) +
                                            (archive_cells > 0 ? " + archive cells " + formatShortest(archive_cells) : "") +
                                            ") x " + std::to_string(width) + " x " + std::to_string(height) + " = " +
                                            formatShortest(pool_cells) + " grid cells held at once; at most " +
                                            formatShortest(kMaxPoolCells) + ": lower the population or the map size");
  }
  weights.validate();
  Problem shape = Problem::empty(width, height, max_obstacles);
  shape.start = startCell();
  shape.goal = goalCell();
  validateProblem(shape);
  parseCharacterSet(characters);
}

void applyGeneratorYaml(YamlMapReader& reader, GeneratorOptions* o) {
  readOptionsYaml(reader, generatorOptionSpecs(), o);
}

GeneratorOptions loadGeneratorOptions(const std::string& path) {
  return parseGeneratorOptions(readTextFile(path, kMaxOptionsBytes), path);
}

GeneratorOptions parseGeneratorOptions(const std::string& yaml_text, const std::string& source) {
  const YAML::Node root = parseYaml(yaml_text, source);
  GeneratorOptions options;
  YamlMapReader reader(root, source);
  applyGeneratorYaml(reader, &options);
  reader.rejectUnknownKeys();
  return options;
}

std::string generatorOptionsYaml(const GeneratorOptions& options, bool docs) {
  return optionsYaml(generatorOptionSpecs(), options, docs);
}

const std::vector<OptionSpec<GeneratorOptions>>& generatorOptionSpecs() {
  using O = GeneratorOptions;
  const double side_min = kMinGridSide, side_max = kMaxGridSide;
  static const std::vector<OptionSpec<O>> specs = {
      declareOption("fitness", "fitness function", +[](O& o) -> std::string& { return o.fitness; })
          .withChoices("fitness", fitnessChoices()),
      declareOption("population", "PPPs in the pool", +[](O& o) -> int& { return o.population; },
                    Bounds{2, kMaxPopulation}),
      declareOption("matings", "steady-state mating events", +[](O& o) -> long& { return o.matings; },
                    Bounds{0, static_cast<double>(kMaxMatings)}),
      declareOption("tournament_size", "individuals per mating event; the fittest two mate",
                    +[](O& o) -> int& { return o.tournament_size; }, Bounds{2, kMaxPopulation}),
      declareOption("mutation_rate", "probability that a child gets one mutation (change, add or remove)",
                    +[](O& o) -> double& { return o.mutation_rate; }, Bounds{0, 1}),
      declareOption("width", "grid columns", +[](O& o) -> int& { return o.width; }, Bounds{side_min, side_max}),
      declareOption("height", "grid rows", +[](O& o) -> int& { return o.height; }, Bounds{side_min, side_max}),
      declareOption("start", "start cell [x, y], y down; default the top-left corner",
                    +[](O& o) -> std::optional<Cell>& { return o.start; }),
      declareOption("goal", "goal cell [x, y], y down; default the bottom-right corner",
                    +[](O& o) -> std::optional<Cell>& { return o.goal; }),
      declareOption("robot_radius",
                    "the robot as a disc of this radius in cells: every PPP is solvable for it, and the DPA's "
                    "turns and advances are its (0: a point)",
                    +[](O& o) -> double& { return o.robot_radius; }, Bounds{0, kMaxRobotRadius}),
      declareOption("max_obstacles", "obstacle budget: most descriptors per chromosome",
                    +[](O& o) -> int& { return o.max_obstacles; }, Bounds{0, kMaxObstacleBudget}),
      declareOption("min_obstacles", "fewest descriptors of a random initial chromosome (capped at max_obstacles)",
                    +[](O& o) -> int& { return o.min_obstacles; }, Bounds{1, kMaxObstacleBudget}),
      declareTextOption("shapes", "shape keywords separated by commas",
                        "the shapes random descriptors take, each listed one equally likely (list one twice to draw "
                        "it twice as often)",
                        +[](O& o) -> std::vector<Shape>& { return o.obstacle_shapes.shapes; }, &shapeListProblem,
                        &shapeListText, {"hbar,vbar,block", "hbar,hbar,vbar,vbar,diag_down,diag_up,block"}),
      declareOption("max_bar_length", "longest random bar; 0 = half the longer side",
                    +[](O& o) -> int& { return o.obstacle_shapes.max_bar_length; }, Bounds{0, side_max}),
      declareOption("min_bar_length", "shortest random bar (capped at the longest)",
                    +[](O& o) -> int& { return o.obstacle_shapes.min_bar_length; }, Bounds{1, side_max}),
      declareOption("max_block_side", "longest random block side; 0 = a quarter of the shorter side",
                    +[](O& o) -> int& { return o.obstacle_shapes.max_block_side; }, Bounds{0, side_max}),
      declareOption("seed", "seed of every random choice", +[](O& o) -> std::uint64_t& { return o.seed; }),
      declareOption("characters", "taxonomy characters", +[](O& o) -> std::string& { return o.characters; })
          .withChoices("character set", {{"wei", "Wei's four"}, {"extended", "all 14"}, {"barn", "BARN's five"}}),
      declareOption("replacement", "how a child enters the pool", +[](O& o) -> std::string& { return o.replacement; })
          .withChoices("rule", {{kCrowdingReplacement, "it replaces the most similar of crowding_window PPPs if as fit"},
                                {kTournamentReplacement, "it replaces the least fit of its tournament"}}),
      declareOption("crowding_window", "PPPs a child is compared with under crowding (capped at the population)",
                    +[](O& o) -> int& { return o.crowding_window; }, Bounds{2, kMaxCrowdingWindow}),
      declareOption("agents", "failure, regret: the panel's agent names",
                    +[](O& o) -> std::vector<std::string>& { return o.agents; }),
      declareOption("agents_file", "failure, regret: the agents file the names are looked up in ('': built-in types)",
                    +[](O& o) -> std::string& { return o.agents_file; }),
      declareOption("runs_per_eval", "failure, regret: episodes per agent per evaluated PPP",
                    +[](O& o) -> int& { return o.runs_per_eval; }, Bounds{1, kMaxRunsPerEval}),
      declareOption("round_size",
                    "failure, regret: matings per round, whose children are scored together (through ROS, one "
                    "evaluation call: larger rounds, fewer round trips)",
                    +[](O& o) -> int& { return o.round_size; }, Bounds{1, kMaxRoundSize}),
      declareOption("archive", "what the set is", +[](O& o) -> std::string& { return o.archive; })
          .withChoices("archive", {{kNoArchive, "the final pool"},
                                   {kMapElitesArchive, "the elites of an archive binned over features"},
                                   {kSignatureArchive,
                                    "failure, regret: one PPP per way the panel failed (failure signature), picked "
                                    "for difference; a child failing in a new way enters the pool whatever its score, "
                                    "and half the parents come from the archive"}}),
      declareOption("features", "map_elites: taxonomic characters binned (two or more)",
                    +[](O& o) -> std::vector<std::string>& { return o.features; }),
      declareOption("bins", "map_elites: bins per feature", +[](O& o) -> int& { return o.bins; }, Bounds{2, kMaxBins}),
      declareOption("initial_pool",
                    "directory of PPPs the search starts from (a set ppp generate wrote, a corpus, or your own "
                    "suite of .ppp, map_server .yaml and MovingAI .map files; in an experiment also the name of a "
                    "set listed before): up to population of them, in a set's set.csv order, else in file-name order; "
                    "the rest random ('': all random)",
                    +[](O& o) -> std::string& { return o.initial_pool; }),
      declareOption("weights.start", "difficulty: weight of the visibility from the start",
                    +[](O& o) -> double& { return o.weights.start; }),
      declareOption("weights.centre", "difficulty: weight of the visibility from the centre",
                    +[](O& o) -> double& { return o.weights.centre; }),
      declareOption("weights.top_right", "difficulty: weight of the visibility from the top-right corner",
                    +[](O& o) -> double& { return o.weights.top_right; }),
      declareOption("weights.bottom_left", "difficulty: weight of the visibility from the bottom-left corner",
                    +[](O& o) -> double& { return o.weights.bottom_left; }),
      declareOption("weights.goal", "difficulty: weight of the visibility from the goal",
                    +[](O& o) -> double& { return o.weights.goal; }),
      declareOption("weights.unused_obstacles", "difficulty: weight of 1 - obstacle use",
                    +[](O& o) -> double& { return o.weights.unused_obstacles; }),
      declareOption("weights.horizontal_openness", "difficulty: weight of the average horizontal openness",
                    +[](O& o) -> double& { return o.weights.horizontal_openness; }),
      declareOption("weights.vertical_openness", "difficulty: weight of the average vertical openness",
                    +[](O& o) -> double& { return o.weights.vertical_openness; }),
      declareOption("weights.one_turn_penalty", "difficulty: added when the optimal route turns exactly once",
                    +[](O& o) -> double& { return o.weights.one_turn_penalty; }),
  };
  return specs;
}

}  // namespace generator
}  // namespace ppp
