#include "remote_runs_player.hpp"

#include <memory>

#include "ppp_core/diagnosis.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_msgs/EvaluateProblems.h"
#include "ppp_msgs/conversions.h"
#include "ppp_simulator/results_file.hpp"

namespace ppp {
namespace simulator {

namespace {

/// The outcome an evaluation of `runs` runs says. @throws IoError naming `service` for an unknown diagnosis.
RunsOutcome outcomeOf(const ppp_msgs::ProblemEvaluation& e, int runs, const std::string& service) {
  RunsOutcome outcome;
  outcome.runs = runs;
  outcome.failed = static_cast<int>(e.failed);
  outcome.endless = static_cast<int>(e.endless_loops);
  for (std::size_t i = 0; i < e.diagnoses.size() && i < e.diagnosis_counts.size(); ++i) {
    const int kind = diagnosis::kindIndex(e.diagnoses[i]);
    if (kind < 0) throw IoError(service, "answered an unknown diagnosis '" + e.diagnoses[i] + "'");
    outcome.kinds[static_cast<std::size_t>(kind)] += static_cast<int>(e.diagnosis_counts[i]);
  }
  outcome.signatures = ppp_msgs::signatureCounts(e, service);
  return outcome;
}

}  // namespace

RunsPlayer remoteRunsPlayer(ros::NodeHandle& nh, const std::string& service, const std::string& agent,
                            const EpisodeOptions& episode, double wait_seconds) {
  if (!ros::service::waitForService(service, ros::Duration(wait_seconds))) {
    throw IoError(service, "no ppp_msgs/EvaluateProblems service within " + std::to_string(wait_seconds) +
                               " s (start the simulator node with ~mode hunt, e.g. launch/shrink.launch)");
  }
  auto client = std::make_shared<ros::ServiceClient>(nh.serviceClient<ppp_msgs::EvaluateProblems>(service, true));
  return [client, service, agent, episode](const Problem& problem, const std::vector<std::uint64_t>& seeds) {
    if (!solvableForRobot(problem, episode)) return RunsOutcome{false};  // nothing to play
    ppp_msgs::EvaluateProblems call;
    call.request.problems.push_back(ppp_msgs::toMessage(problem, "candidate", 1.0));
    call.request.agents = {agent};
    call.request.runs = static_cast<std::uint32_t>(seeds.size());
    call.request.run_seeds = seeds;
    if (!client->call(call)) {
      if (!ros::ok()) throw Interrupted();
      throw IoError(service, "the evaluation call failed (is the simulator node still up?)");
    }
    if (!call.response.error.empty()) throw IoError(service, "the simulator refused: " + call.response.error);
    if (call.response.evaluations.size() != 1) {
      throw IoError(service, "answered " + std::to_string(call.response.evaluations.size()) + " evaluations for 1 PPP");
    }
    const ppp_msgs::ProblemEvaluation& evaluation = call.response.evaluations[0];
    for (std::size_t i = 0; i < evaluation.reasons.size(); ++i) {
      if (leavesAgentUnreachable(evaluation.reasons[i])) {  // the agent, not the candidate: judging cannot go on
        throw IoError(service, "agent '" + agent + "' lost " + std::to_string(evaluation.reason_counts.at(i)) +
                                   " runs as " + evaluation.reasons[i] + " (is its node or planner still up?)");
      }
    }
    return outcomeOf(evaluation, static_cast<int>(seeds.size()), service);
  };
}

}  // namespace simulator
}  // namespace ppp
