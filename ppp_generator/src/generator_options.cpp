#include "ppp_generator/generator_options.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_generator/taxonomy.hpp"

namespace ppp {
namespace generator {

namespace {

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

}  // namespace

void GeneratorOptions::validate() const {
  makeFitness(fitness, FitnessParameters{weights, seed});
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
  readWeights(reader, &o->weights);
}

GeneratorOptions loadGeneratorOptions(const std::string& path) {
  const YAML::Node root = loadYamlFile(path);
  GeneratorOptions options;
  YamlMapReader reader(root, path);
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
