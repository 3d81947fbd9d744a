#include "simulator_parameters.hpp"

#include "ppp_core/error.hpp"
#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace simulator {

SimulatorParameters readSimulatorParameters(const ros::NodeHandle& nh) {
  SimulatorParameters p;
  SimulatorTask& task = p;
  ppp_msgs::readOptionParameters(nh, simulatorTaskSpecs(), &task);
  SimulatorOptions& options = p;
  ppp_msgs::readOptionParameters(nh, simulatorOptionSpecs(), &options);
  ppp_msgs::validateParameters(options);
  if (p.config.empty()) {
    throw ppp_msgs::parameterError(
        InvalidArgument("config", "required: the experiment YAML (e.g. config/experiment.yaml)"));
  }
  if (p.mode == kExperimentMode && p.output_dir.empty()) {
    throw ppp_msgs::parameterError(InvalidArgument("output_dir", "required: where results, report and bag go"));
  }
  return p;
}

}  // namespace simulator
}  // namespace ppp
