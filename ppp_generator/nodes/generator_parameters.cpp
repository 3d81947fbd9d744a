#include "generator_parameters.hpp"

#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace generator {

namespace {

using ppp_msgs::readParameter;

std::optional<Cell> readCell(const ros::NodeHandle& nh, const std::string& name) {
  std::vector<int> pair;
  if (!nh.hasParam(name)) return std::nullopt;
  if (!nh.getParam(name, pair) || pair.size() != 2) throw InvalidArgument("~" + name, "expected [x, y]");
  return Cell{pair[0], pair[1]};
}

}  // namespace

NodeParameters readNodeParameters(const ros::NodeHandle& nh) {
  NodeParameters p;
  GeneratorOptions& o = p.options;
  std::string options_yaml;
  if (readParameter(nh, "options", &options_yaml, "generator options as YAML text")) {
    o = parseGeneratorOptions(options_yaml, "~options");
  }
  readParameter(nh, "fitness", &o.fitness, "a string");
  readParameter(nh, "population", &o.population, "an integer");
  int matings = static_cast<int>(o.matings);
  readParameter(nh, "matings", &matings, "an integer");
  o.matings = matings;
  readParameter(nh, "tournament_size", &o.tournament_size, "an integer");
  readParameter(nh, "mutation_rate", &o.mutation_rate, "a number");
  readParameter(nh, "width", &o.width, "an integer");
  readParameter(nh, "height", &o.height, "an integer");
  if (auto cell = readCell(nh, "start")) o.start = cell;
  if (auto cell = readCell(nh, "goal")) o.goal = cell;
  readParameter(nh, "max_obstacles", &o.max_obstacles, "an integer");
  readParameter(nh, "max_bar_length", &o.obstacle_shapes.max_bar_length, "an integer");
  readParameter(nh, "max_block_side", &o.obstacle_shapes.max_block_side, "an integer");
  int seed = static_cast<int>(o.seed);
  readParameter(nh, "seed", &seed, "an integer");
  if (seed < 0) throw InvalidArgument("~seed", "expected an integer >= 0, got " + std::to_string(seed));
  o.seed = static_cast<std::uint64_t>(seed);
  readParameter(nh, "characters", &o.characters, "a string");
  readParameter(nh, "replacement", &o.replacement, "a string");
  readParameter(nh, "crowding_window", &o.crowding_window, "an integer");
  ppp_msgs::readStringList(nh, "agents", &o.agents);
  readParameter(nh, "agents_file", &o.agents_file, "a string");
  readParameter(nh, "runs_per_eval", &o.runs_per_eval, "an integer");
  readParameter(nh, "archive", &o.archive, "a string");
  ppp_msgs::readStringList(nh, "features", &o.features);
  readParameter(nh, "bins", &o.bins, "an integer");
  const std::pair<const char*, double*> weights[] = {
      {"weights/start", &o.weights.start},
      {"weights/centre", &o.weights.centre},
      {"weights/top_right", &o.weights.top_right},
      {"weights/bottom_left", &o.weights.bottom_left},
      {"weights/goal", &o.weights.goal},
      {"weights/unused_obstacles", &o.weights.unused_obstacles},
      {"weights/horizontal_openness", &o.weights.horizontal_openness},
      {"weights/vertical_openness", &o.weights.vertical_openness},
      {"weights/one_turn_penalty", &o.weights.one_turn_penalty},
  };
  for (const auto& w : weights) readParameter(nh, w.first, w.second, "a number");
  readParameter(nh, "set_name", &p.set_name, "a string");
  readParameter(nh, "output_dir", &p.output_dir, "a string");
  readParameter(nh, "resume", &p.resume, "true or false");
  readParameter(nh, "publish_index", &p.publish_index, "an integer");
  readParameter(nh, "resolution", &p.resolution, "a number");
  readParameter(nh, "generate_on_start", &p.generate_on_start, "true or false");
  readParameter(nh, "exit_when_done", &p.exit_when_done, "true or false");
  readParameter(nh, "evaluator", &p.evaluator, "a service name");
  readParameter(nh, "evaluator_timeout", &p.evaluator_timeout, "a number of seconds");
  try {
    o.validate();
  } catch (const InvalidArgument& e) {
    throw InvalidArgument("~" + e.name(), std::string(e.what()).substr(e.name().size() + 2));
  }
  if (p.publish_index < 0 || p.publish_index >= o.population) {
    throw InvalidArgument("~publish_index", "expected an index in [0, population = " + std::to_string(o.population) +
                                                "), got " + std::to_string(p.publish_index));
  }
  if (!(p.resolution > 0)) throw InvalidArgument("~resolution", "expected metres per cell > 0");
  if (!(p.evaluator_timeout > 0)) throw InvalidArgument("~evaluator_timeout", "expected seconds > 0");
  if (o.fitness == kFailureFitness && !o.agents_file.empty()) {
    throw InvalidArgument("~agents_file", "a hunt through ROS names the simulator's agents (its ~config); leave it empty");
  }
  return p;
}

}  // namespace generator
}  // namespace ppp
