// check_node: `ppp check` for any agent of an experiment, planner nodes included, through ROS. Every run of every
// PPP of the corpus is played by the simulator node serving hunts (ppp_msgs/EvaluateProblems on
// /simulator/evaluate, ~mode hunt) on the agent's node or planner bridge; the check itself (which seeds, the
// verdicts, the JUnit XML) is `ppp check`'s. Its parameters: docs/reference/options.md#check-node;
// launch/check.launch starts it with the simulator and the agent's nodes. Exits 0 when every PPP passes, 1 when
// any fails, 2 on bad input, 130 when shut down (nothing written).
#include <ros/ros.h>

#include <iostream>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_msgs/graph_names.h"
#include "ppp_msgs/node_parameters.h"
#include "ppp_simulator/corpus_check.hpp"
#include "ppp_simulator/experiment_config.hpp"
#include "remote_runs_player.hpp"

namespace ppp {
namespace simulator {
namespace {

/// Seconds to wait for the simulator's evaluation service.
constexpr double kServiceWaitSeconds = 120.0;

int runCheckNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh) {
  CheckTask task;
  ppp_msgs::readOptionParameters(private_nh, checkTaskSpecs(), &task);
  ppp_msgs::validateParameters(task);
  const ExperimentConfig config = loadExperimentConfig(task.config);
  CheckJob job;
  job.task = task;
  job.episode = config.episode;
  // The check of the one PPP again, on the same seeds (its own, or those derived as here).
  job.replay = [task](const CorpusCase& c, std::uint64_t) {
    return checkLaunchCommand(c.file, task.agent, task.config) +
           (c.recorded ? "" : " args:=\"--seed " + std::to_string(task.seed) + " --runs " + std::to_string(task.runs) +
                                  "\"");
  };
  job.play = remoteRunsPlayer(nh, ppp_msgs::topics::kEvaluator, task.agent, config.episode, kServiceWaitSeconds);
  return runCheck(job, [] { return !ros::ok(); }, std::cout);
}

}  // namespace
}  // namespace simulator
}  // namespace ppp

int main(int argc, char** argv) {
  ros::init(argc, argv, "check");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  int status = 2;
  try {
    status = ppp::simulator::runCheckNode(nh, private_nh);
  } catch (const ppp::Interrupted&) {
    std::cerr << "check: interrupted; nothing written\n";
    status = 130;
  } catch (const ppp::Error& e) {
    ROS_FATAL("check: %s", e.what());
  } catch (const std::exception& e) {
    ROS_FATAL("check: unexpected failure: %s", e.what());
  }
  ros::shutdown();
  return status;
}
