#include "generator_parameters.hpp"

#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_generator/fitness.hpp"
#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace generator {

NodeParameters readNodeParameters(const ros::NodeHandle& nh) {
  NodeParameters p;
  GeneratorNodeOptions& node = p;
  ppp_msgs::readOptionParameters(nh, generatorNodeOptionSpecs(), &node);
  ppp_msgs::validateParameters(node);
  GeneratorOptions& o = p.options;
  if (!p.options_yaml.empty()) o = parseGeneratorOptions(p.options_yaml, "~options");
  ppp_msgs::readOptionParameters(nh, generatorOptionSpecs(), &o);
  ppp_msgs::validateParameters(o);
  if (p.publish_index < 0 || p.publish_index >= o.population) {
    throw ppp_msgs::parameterError(InvalidArgument(
        "publish_index", "expected an index in [0, population = " + std::to_string(o.population) + "), got " +
                             std::to_string(p.publish_index)));
  }
  if (isPanelFitness(o.fitness) && !p.evaluator.empty() && !o.agents_file.empty()) {
    throw ppp_msgs::parameterError(InvalidArgument(
        "agents_file", "a hunt through ROS names the simulator's agents (its config); leave it empty, or hunt "
                       "in process with an empty evaluator"));
  }
  ppp_msgs::readOptionParameters(nh, episodeOptionSpecs(), &p.episode);
  ppp_msgs::validateParameters(p.episode);
  return p;
}

}  // namespace generator
}  // namespace ppp
