// shrink_node: `ppp shrink` for any agent of an experiment, planner nodes included, through ROS. Each candidate PPP
// is judged by the simulator node serving hunts (ppp_msgs/EvaluateProblems on /simulator/evaluate, ~mode hunt),
// which plays it on the agent's node or planner bridge on the judged run seeds and answers with the runs'
// diagnoses; the shrink itself (delta debugging, what is kept, what is written) is `ppp shrink`'s. Its
// parameters: docs/reference/options.md#shrink-node; launch/shrink.launch starts it with the simulator and the
// agent's nodes. Exits 0 when the shrunk PPP is written, 1 when the agent fails nothing (nothing written), 2 on
// an error, 130 when shut down (nothing written).
#include <ros/ros.h>

#include <iostream>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_msgs/graph_names.h"
#include "ppp_msgs/node_parameters.h"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_simulator/corpus_check.hpp"
#include "ppp_simulator/shrink_job.hpp"
#include "remote_runs_player.hpp"

namespace ppp {
namespace simulator {
namespace {

/// Seconds to wait for the simulator's evaluation service.
constexpr double kServiceWaitSeconds = 120.0;

int runShrinkNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh) {
  ShrinkTask task;
  ppp_msgs::readOptionParameters(private_nh, shrinkTaskSpecs(), &task);
  ppp_msgs::validateParameters(task);
  const ExperimentConfig config = loadExperimentConfig(task.config);
  agents::AgentConfig agent;
  try {
    agent = configAgent(config, task.agent);
  } catch (const InvalidArgument& e) {
    throw ppp_msgs::parameterError(e);  // "~agent: ..."
  }
  ShrinkJob job = shrinkJobOf(
      task, agent, config.episode,
      remoteRunsPlayer(nh, ppp_msgs::topics::kEvaluator, agent.name, config.episode, kServiceWaitSeconds));
  job.replay = [task](const std::string& file, std::uint64_t) {  // a shrunk PPP records its seeds: check plays them
    return checkLaunchCommand(file, task.agent, task.config);
  };
  return runShrinkJob(job, [] { return !ros::ok(); }, std::cout, std::cerr);
}

}  // namespace
}  // namespace simulator
}  // namespace ppp

int main(int argc, char** argv) {
  ros::init(argc, argv, "shrink");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  int status = 2;
  try {
    status = ppp::simulator::runShrinkNode(nh, private_nh);
  } catch (const ppp::Interrupted&) {
    std::cerr << "shrink: interrupted; nothing written\n";
    status = 130;
  } catch (const ppp::Error& e) {
    ROS_FATAL("shrink: %s", e.what());
  } catch (const std::exception& e) {
    ROS_FATAL("shrink: unexpected failure: %s", e.what());
  }
  ros::shutdown();
  return status;
}
