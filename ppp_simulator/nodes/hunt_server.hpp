#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "lane_runner.hpp"
#include "ppp_core/progress_meter.hpp"
#include "ppp_msgs/EvaluateProblems.h"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_generator/hunt_evaluation.hpp"
#include "simulator_parameters.hpp"

namespace ppp {
namespace simulator {

/// Answers ~evaluate (ppp_msgs/EvaluateProblems) for hunts. Each request's PPPs are played by the named agents
/// of ~config (agent nodes on /NAME/scans and /NAME/moves, planner bridges, exactly as in an experiment), `runs`
/// times each, seeded as the in-process panel fitnesses do; the answer says per PPP how often the panel failed,
/// why, and how much longer than the optimum its runs took (for the failure and the regret fitness alike).
/// Agents that time out or die fail their runs with that reason, so a hunt never hangs on them.
class HuntServer {
 public:
  /// Reads ~config's agents. @throws IoError, ParseError, InvalidArgument.
  HuntServer(ros::NodeHandle& nh, const SimulatorParameters& parameters, const NodeControl& control);
  ~HuntServer();
  HuntServer(const HuntServer&) = delete;
  HuntServer& operator=(const HuntServer&) = delete;

  /// The service callback: plays one request (one at a time).
  bool evaluate(ppp_msgs::EvaluateProblems::Request& request, ppp_msgs::EvaluateProblems::Response& response);

  /// Plays `agent` (of ~config) on `problem` (solvable for the robot) once per seed of `seeds`, as the service
  /// would; returns the rows in run order (a planner's with its actions). Calls for different agents play at once;
  /// for one agent, one after another. @throws Interrupted when the node stops first.
  std::vector<agents::EpisodeResult> playRows(const agents::AgentConfig& agent, const Problem& problem,
                                              const std::vector<std::uint64_t>& seeds);

 private:
  /// One agent's runners (one per instance, agents::instanceCount, of its lockstep protocol), made on first use.
  struct AgentRunners {
    std::mutex playing;  // held while its runners play: one evaluation at a time per agent
    generator::HuntEvaluation* target = nullptr;  // the evaluation in play, where its runners' results go
    std::vector<std::unique_ptr<LaneRunner>> grid;
    std::vector<std::unique_ptr<ContinuousLaneRunner>> continuous;
  };

  static ppp_msgs::ProblemEvaluation toMessage(const generator::PanelEvaluation& e);
  /// The agent's entry, made on first use (its address stays the same).
  AgentRunners& runnersOf(const agents::AgentConfig& agent);
  /// Plays every lane of `evaluation` (the panel's, in panel order) on the panel's runners, one thread each; the
  /// caller holds every panel agent's `playing`. @throws what a runner threw; IoError when ROS shut down before
  /// every run was played.
  void play(generator::HuntEvaluation& evaluation, const std::vector<agents::AgentConfig>& panel);
  /// `entry`'s runners of one lockstep protocol for `agent`, made on first use (the caller holds its `playing`).
  template <class Runner>
  const std::vector<std::unique_ptr<Runner>>& runnersFor(const agents::AgentConfig& agent, AgentRunners* entry,
                                                          std::vector<std::unique_ptr<Runner>>* runners);

  ros::NodeHandle& nh_;
  SimulatorParameters parameters_;
  NodeControl control_;
  ExperimentConfig config_;
  std::mutex serving_;  // one service request at a time
  std::mutex agents_mutex_;  // guards the map agents_, not its entries
  std::map<std::string, std::unique_ptr<AgentRunners>> agents_;
  long requests_ = 0;
  long episodes_ = 0;
  ProgressMeter progress_{"hunt", "episodes"};  // a line every few seconds, not one per request
};

/// The simulator node in hunt mode: serves ~evaluate (advertised on `services_nh`) with a HuntServer until the node
/// stops. Returns the exit status.
int runHuntServer(ros::NodeHandle& nh, ros::NodeHandle& services_nh, const SimulatorParameters& parameters,
                  const NodeControl& control);

}  // namespace simulator
}  // namespace ppp
