#pragma once

// The simulator node: runs an experiment (~mode experiment, the default), or serves ~evaluate for a hunt (~mode
// hunt: see hunt_server.hpp). With ~generator_nodes it plays the sets the generator nodes publish (serving ~evaluate
// to hunting ones meanwhile), as launch/experiment.launch runs it. For each agent configuration NAME of the
// experiment it publishes ppp_msgs/ScanBatch on /NAME/scans (one scan per active episode) and takes
// ppp_msgs/MoveBatch from /NAME/moves, in lockstep, through the same AgentLane and episode code as the in-process
// runner, so the results equal `ppp experiment`'s. Results go to results.csv as episodes end; summary.csv and the
// report are written when all runs are done; a sample of episodes and every result are recorded in experiment.bag.
// Its parameters: docs/reference/options.md#simulator-node; its topics and services: docs/reference/ros-graph.md.
// It runs as a process of its own (simulator_node, which exits when the experiment is finished) or as the nodelet
// ppp_simulator/Simulator (which then shuts its manager down: the graph ends with the experiment).

#include <atomic>
#include <thread>

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include "lane_runner.hpp"
#include "simulator_parameters.hpp"

namespace ppp {
namespace simulator {

/// The simulator's experiment or hunt service, run by run() until it is done or stop() is called.
class SimulatorNode {
 public:
  /// Reads the private parameters; `nh`'s callbacks (the agents' replies, the sets) must be served by the caller's
  /// threads (a spinner, or a nodelet manager), with `in_network_thread` as in NodeControl. The ~evaluate service
  /// has a thread of its own. @throws Error naming the parameter.
  SimulatorNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, bool in_network_thread);
  ~SimulatorNode();
  SimulatorNode(const SimulatorNode&) = delete;
  SimulatorNode& operator=(const SimulatorNode&) = delete;

  /// Runs the experiment, or serves hunts, until done, stopped or ROS shuts down; returns the exit status (0 done,
  /// 1 failed, 130 interrupted: rerun to resume).
  int run();
  /// Makes run() return within a second, resumably (any thread).
  void stop() { stop_requested_ = true; }

 private:
  int runExperiment();

  ros::NodeHandle nh_;
  SimulatorParameters parameters_;
  std::atomic<bool> stop_requested_{false};
  NodeControl control_;
  ros::CallbackQueue services_queue_;  // ~evaluate's: its calls last a whole round of a hunt
  ros::NodeHandle services_nh_;        // the private namespace, on services_queue_
  ros::AsyncSpinner services_spinner_;
};

}  // namespace simulator
}  // namespace ppp
