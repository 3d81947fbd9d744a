#include "simulator_parameters.hpp"

#include "ppp_core/error.hpp"
#include "ppp_msgs/node_parameters.h"

namespace ppp {
namespace simulator {

using ppp_msgs::readParameter;
using ppp_msgs::requirePositive;

SimulatorParameters readSimulatorParameters(const ros::NodeHandle& nh) {
  SimulatorParameters p;
  readParameter(nh, "mode", &p.mode, "experiment or hunt");
  readParameter(nh, "config", &p.config, "the path of an experiment YAML");
  readParameter(nh, "output_dir", &p.output_dir, "a directory path");
  readParameter(nh, "batch_size", &p.batch_size, "an integer");
  readParameter(nh, "step_timeout", &p.step_timeout, "a number of seconds");
  readParameter(nh, "planner_step_timeout", &p.planner_step_timeout, "a number of seconds");
  readParameter(nh, "timeouts_before_giving_up", &p.timeouts_before_giving_up, "an integer");
  readParameter(nh, "connect_timeout", &p.connect_timeout, "a number of seconds");
  readParameter(nh, "generator_nodes", &p.generator_nodes, "true or false");
  readParameter(nh, "set_timeout", &p.set_timeout, "a number of seconds");
  readParameter(nh, "record", &p.record, "true or false");
  readParameter(nh, "record_runs", &p.record_runs, "an integer");
  readParameter(nh, "record_problems", &p.record_problems, "an integer");
  readParameter(nh, "resolution", &p.resolution, "a number of metres per cell");
  if (p.config.empty()) throw InvalidArgument("~config", "required: the experiment YAML (e.g. config/experiment.yaml)");
  if (p.mode != kExperimentMode && p.mode != kHuntMode) {
    throw InvalidArgument("~mode", "expected experiment or hunt, got '" + p.mode + "'");
  }
  if (p.mode == kExperimentMode && p.output_dir.empty()) {
    throw InvalidArgument("~output_dir", "required: where results, report and bag go");
  }
  if (p.batch_size < 1) throw InvalidArgument("~batch_size", "expected at least 1, got " + std::to_string(p.batch_size));
  requirePositive(p.step_timeout, "~step_timeout");
  requirePositive(p.planner_step_timeout, "~planner_step_timeout");
  requirePositive(p.connect_timeout, "~connect_timeout");
  requirePositive(p.set_timeout, "~set_timeout");
  requirePositive(p.resolution, "~resolution");
  if (p.timeouts_before_giving_up < 1) throw InvalidArgument("~timeouts_before_giving_up", "expected at least 1");
  if (p.record_runs < 0) throw InvalidArgument("~record_runs", "expected >= 0");
  if (p.record_problems < 0) throw InvalidArgument("~record_problems", "expected >= 0");
  return p;
}

}  // namespace simulator
}  // namespace ppp
