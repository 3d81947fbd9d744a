#include "simulator_parameters.hpp"

#include "ppp_core/error.hpp"
#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace simulator {

using ppp_msgs::readParameter;

SimulatorParameters readSimulatorParameters(const ros::NodeHandle& nh) {
  SimulatorParameters p;
  readParameter(nh, "mode", &p.mode, "experiment or hunt");
  readParameter(nh, "config", &p.config, "the path of an experiment YAML");
  readParameter(nh, "output_dir", &p.output_dir, "a directory path");
  readParameter(nh, "generator_nodes", &p.generator_nodes, "true or false");
  SimulatorOptions& options = p;
  ppp_msgs::readOptionParameters(nh, simulatorOptionSpecs(), &options);
  ppp_msgs::validateParameters(options);
  if (p.config.empty()) throw InvalidArgument("~config", "required: the experiment YAML (e.g. config/experiment.yaml)");
  if (p.mode != kExperimentMode && p.mode != kHuntMode) {
    throw InvalidArgument("~mode", "expected experiment or hunt, got '" + p.mode + "'");
  }
  if (p.mode == kExperimentMode && p.output_dir.empty()) {
    throw InvalidArgument("~output_dir", "required: where results, report and bag go");
  }
  return p;
}

}  // namespace simulator
}  // namespace ppp
