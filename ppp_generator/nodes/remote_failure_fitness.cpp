#include "remote_failure_fitness.hpp"

#include <memory>

#include "ppp_core/episode_reason.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_generator/failure_fitness.hpp"
#include "ppp_generator/hunt_evaluation.hpp"
#include "ppp_msgs/EvaluateProblems.h"
#include "ppp_msgs/conversions.h"

namespace ppp {
namespace generator {

Fitness makeRemoteFailureFitness(ros::NodeHandle& nh, const GeneratorOptions& options, const std::string& service,
                                 double wait_seconds, const std::function<bool()>& stopping) {
  if (!ros::service::waitForService(service, ros::Duration(wait_seconds))) {
    throw IoError(service, "no ppp_msgs/EvaluateProblems service within " + std::to_string(wait_seconds) +
                               " s (start the simulator node with ~mode hunt, e.g. launch/hunt.launch)");
  }
  auto client = std::make_shared<ros::ServiceClient>(nh.serviceClient<ppp_msgs::EvaluateProblems>(service, true));
  Fitness fitness;
  fitness.name = options.fitness;
  fitness.maximise = true;
  fitness.batch_size = options.round_size;
  fitness.batch = [client, options, service, stopping](const std::vector<const Problem*>& problems,
                                             const std::vector<const Grid*>&) {
    ppp_msgs::EvaluateProblems call;
    for (std::size_t i = 0; i < problems.size(); ++i) {
      call.request.problems.push_back(ppp_msgs::toMessage(*problems[i], "c" + std::to_string(i), 1.0));
    }
    call.request.agents = options.agents;
    call.request.runs = static_cast<std::uint32_t>(options.runs_per_eval);
    call.request.seed = options.seed;
    if (!client->call(call)) {
      if (stopping()) throw Interrupted();  // stopped mid-call: nothing is wrong with the simulator
      throw IoError(service, "the evaluation call failed (is the simulator node still up?)");
    }
    if (!call.response.error.empty()) throw IoError(service, "the simulator refused: " + call.response.error);
    if (call.response.evaluations.size() != problems.size()) {
      throw IoError(service, "answered " + std::to_string(call.response.evaluations.size()) + " evaluations for " +
                                 std::to_string(problems.size()) + " PPPs");
    }
    std::vector<FitnessScore> scores;
    for (const ppp_msgs::ProblemEvaluation& e : call.response.evaluations) {
      FailureEstimate estimate;
      estimate.failure_rate = e.failure_rate;
      estimate.budget_used = e.budget_used;
      estimate.regret = e.regret;
      estimate.steps = static_cast<long>(e.steps);
      estimate.signatures = ppp_msgs::signatureCounts(e, service);
      scores.push_back(panelScore(options.fitness, estimate));
      for (std::size_t r = 0; r < e.reasons.size() && r < e.reason_counts.size(); ++r) {
        if (e.reasons[r] != reason::kBudgetExhausted && e.reasons[r] != kSoftFailureReason) {
          ROS_WARN_THROTTLE(10, "hunt: %u runs of a candidate failed as %s", e.reason_counts[r], e.reasons[r].c_str());
        }
      }
    }
    return scores;
  };
  return fitness;
}

}  // namespace generator
}  // namespace ppp
