#include "generator_parameters.hpp"

#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace generator {

using ppp_msgs::readParameter;

NodeParameters readNodeParameters(const ros::NodeHandle& nh) {
  NodeParameters p;
  GeneratorOptions& o = p.options;
  std::string options_yaml;
  if (readParameter(nh, "options", &options_yaml, "generator options as YAML text")) {
    o = parseGeneratorOptions(options_yaml, "~options");
  }
  ppp_msgs::readOptionParameters(nh, generatorOptionSpecs(), &o);
  readParameter(nh, "set_name", &p.set_name, "a string");
  readParameter(nh, "output_dir", &p.output_dir, "a string");
  readParameter(nh, "resume", &p.resume, "true or false");
  readParameter(nh, "publish_index", &p.publish_index, "an integer");
  readParameter(nh, "resolution", &p.resolution, "a number");
  readParameter(nh, "generate_on_start", &p.generate_on_start, "true or false");
  readParameter(nh, "exit_when_done", &p.exit_when_done, "true or false");
  readParameter(nh, "evaluator", &p.evaluator, "a service name");
  readParameter(nh, "evaluator_timeout", &p.evaluator_timeout, "a number of seconds");
  ppp_msgs::validateParameters(o);
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
