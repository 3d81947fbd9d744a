#include "ppp_generator/generator_options.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "ppp_core/error.hpp"
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

std::optional<Cell> readCell(YamlMapReader& reader, const std::string& key) {
  std::vector<int> pair;
  if (!reader.read(key, &pair)) return std::nullopt;
  if (pair.size() != 2) reader.fail(reader.lookup(key), key, "expected [x, y]");
  return Cell{pair[0], pair[1]};
}

void readWeights(YamlMapReader& parent, DifficultyWeights* w) {
  const YAML::Node node = parent.lookup("weights");
  if (!node) return;
  YamlMapReader reader(node, parent.source(), "weights");
  reader.read("start", &w->start);
  reader.read("centre", &w->centre);
  reader.read("top_right", &w->top_right);
  reader.read("bottom_left", &w->bottom_left);
  reader.read("goal", &w->goal);
  reader.read("unused_obstacles", &w->unused_obstacles);
  reader.read("horizontal_openness", &w->horizontal_openness);
  reader.read("vertical_openness", &w->vertical_openness);
  reader.read("one_turn_penalty", &w->one_turn_penalty);
  reader.rejectUnknownKeys();
}

/// A flow-style YAML list of plain names.
std::string yamlList(const std::vector<std::string>& names) {
  std::string text = "[";
  for (std::size_t i = 0; i < names.size(); ++i) text += (i > 0 ? ", " : "") + names[i];
  return text + "]";
}

/// The failure fitness's and the archive's options.
void validateHuntOptions(const GeneratorOptions& o) {
  const bool failure = o.fitness == kFailureFitness;
  if (failure && o.agents.empty()) {
    throw InvalidArgument("agents", "empty panel: the failure fitness needs at least one agent name");
  }
  if (!failure && !o.agents.empty()) throw InvalidArgument("agents", "only the failure fitness uses an agent panel");
  for (std::size_t i = 0; i < o.agents.size(); ++i) {
    if (o.agents[i].empty()) throw InvalidArgument("agents", "empty agent name");
    for (std::size_t j = 0; j < i; ++j) {
      if (o.agents[i] == o.agents[j]) throw InvalidArgument("agents", "'" + o.agents[i] + "' named twice");
    }
  }
  if (o.runs_per_eval < 1 || o.runs_per_eval > kMaxRunsPerEval) {
    throw InvalidArgument("runs_per_eval", "expected runs in [1, " + std::to_string(kMaxRunsPerEval) + "], got " +
                                               std::to_string(o.runs_per_eval));
  }
  if (o.archive != kNoArchive && o.archive != kMapElitesArchive) {
    throw InvalidArgument("archive", "unknown archive '" + o.archive + "'; valid: none, map_elites");
  }
  if (o.features.size() < 2) {
    throw InvalidArgument("features", "expected two or more character names, got " + std::to_string(o.features.size()));
  }
  const std::vector<std::string>& names = characterNames();
  for (std::size_t i = 0; i < o.features.size(); ++i) {
    if (std::find(names.begin(), names.end(), o.features[i]) == names.end()) {
      throw InvalidArgument("features", "unknown character '" + o.features[i] + "'; valid: " + joinNames(names));
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (o.features[i] == o.features[j]) throw InvalidArgument("features", "'" + o.features[i] + "' named twice");
    }
  }
  if (o.bins < 2 || o.bins > kMaxBins) {
    throw InvalidArgument("bins", "expected bins per feature in [2, " + std::to_string(kMaxBins) + "], got " +
                                      std::to_string(o.bins));
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
  if (fitness == kFailureFitness) {
    fitnessMaximises(fitness);
  } else {
    makeFitness(fitness, FitnessParameters{weights, seed});
  }
  validateHuntOptions(*this);
  if (replacement != kCrowdingReplacement && replacement != kTournamentReplacement) {
    throw InvalidArgument("replacement", "unknown rule '" + replacement + "'; valid: crowding, tournament");
  }
  if (crowding_window < 2 || crowding_window > kMaxCrowdingWindow) {
    throw InvalidArgument("crowding_window", "expected pool members in [2, " + std::to_string(kMaxCrowdingWindow) +
                                                 "], got " + std::to_string(crowding_window));
  }
  weights.validate();
  if (population < 2) throw InvalidArgument("population", "expected at least 2, got " + std::to_string(population));
  if (matings < 0) throw InvalidArgument("matings", "expected a count >= 0, got " + std::to_string(matings));
  if (tournament_size < 2) {
    throw InvalidArgument("tournament_size", "expected at least 2, got " + std::to_string(tournament_size));
  }
  if (!(mutation_rate >= 0.0 && mutation_rate <= 1.0)) {
    throw InvalidArgument("mutation_rate", "expected a probability in [0, 1], got " + std::to_string(mutation_rate));
  }
  validateGridSize(width, height, "size");
  if (max_obstacles < 0 || max_obstacles > kMaxObstacleBudget) {
    throw InvalidArgument("max_obstacles", "expected a budget in [0, " + std::to_string(kMaxObstacleBudget) +
                                               "], got " + std::to_string(max_obstacles));
  }
  if (obstacle_shapes.max_bar_length < 0) throw InvalidArgument("max_bar_length", "expected >= 0 (0: automatic)");
  if (obstacle_shapes.max_block_side < 0) throw InvalidArgument("max_block_side", "expected >= 0 (0: automatic)");
  Problem shape = Problem::empty(width, height, max_obstacles);
  shape.start = startCell();
  shape.goal = goalCell();
  validateProblem(shape);
  parseCharacterSet(characters);
}

void applyGeneratorYaml(YamlMapReader& reader, GeneratorOptions* o) {
  reader.read("fitness", &o->fitness);
  reader.read("population", &o->population);
  reader.read("matings", &o->matings);
  reader.read("tournament_size", &o->tournament_size);
  reader.read("mutation_rate", &o->mutation_rate);
  reader.read("width", &o->width);
  reader.read("height", &o->height);
  if (auto cell = readCell(reader, "start")) o->start = cell;
  if (auto cell = readCell(reader, "goal")) o->goal = cell;
  reader.read("max_obstacles", &o->max_obstacles);
  reader.read("max_bar_length", &o->obstacle_shapes.max_bar_length);
  reader.read("max_block_side", &o->obstacle_shapes.max_block_side);
  unsigned long seed = 0;
  if (reader.read("seed", &seed)) o->seed = seed;
  reader.read("characters", &o->characters);
  reader.read("replacement", &o->replacement);
  reader.read("crowding_window", &o->crowding_window);
  reader.read("agents", &o->agents);
  reader.read("agents_file", &o->agents_file);
  reader.read("runs_per_eval", &o->runs_per_eval);
  reader.read("archive", &o->archive);
  reader.read("features", &o->features);
  reader.read("bins", &o->bins);
  readWeights(reader, &o->weights);
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

std::string generatorOptionsYaml(const GeneratorOptions& o) {
  std::ostringstream out;
  out << "fitness: " << o.fitness << "\n"
      << "population: " << o.population << "\n"
      << "matings: " << o.matings << "\n"
      << "tournament_size: " << o.tournament_size << "\n"
      << "mutation_rate: " << formatShortest(o.mutation_rate) << "\n"
      << "width: " << o.width << "\n"
      << "height: " << o.height << "\n"
      << "start: [" << o.startCell().x << ", " << o.startCell().y << "]\n"
      << "goal: [" << o.goalCell().x << ", " << o.goalCell().y << "]\n"
      << "max_obstacles: " << o.max_obstacles << "\n"
      << "max_bar_length: " << o.obstacle_shapes.max_bar_length << "\n"
      << "max_block_side: " << o.obstacle_shapes.max_block_side << "\n"
      << "seed: " << o.seed << "\n"
      << "characters: " << o.characters << "\n"
      << "replacement: " << o.replacement << "\n"
      << "crowding_window: " << o.crowding_window << "\n"
      << "agents: " << yamlList(o.agents) << "\n"
      << "agents_file: '" << o.agents_file << "'\n"
      << "runs_per_eval: " << o.runs_per_eval << "\n"
      << "archive: " << o.archive << "\n"
      << "features: " << yamlList(o.features) << "\n"
      << "bins: " << o.bins << "\n"
      << "weights:\n"
      << "  start: " << formatShortest(o.weights.start) << "\n"
      << "  centre: " << formatShortest(o.weights.centre) << "\n"
      << "  top_right: " << formatShortest(o.weights.top_right) << "\n"
      << "  bottom_left: " << formatShortest(o.weights.bottom_left) << "\n"
      << "  goal: " << formatShortest(o.weights.goal) << "\n"
      << "  unused_obstacles: " << formatShortest(o.weights.unused_obstacles) << "\n"
      << "  horizontal_openness: " << formatShortest(o.weights.horizontal_openness) << "\n"
      << "  vertical_openness: " << formatShortest(o.weights.vertical_openness) << "\n"
      << "  one_turn_penalty: " << formatShortest(o.weights.one_turn_penalty) << "\n";
  return out.str();
}

}  // namespace generator
}  // namespace ppp
