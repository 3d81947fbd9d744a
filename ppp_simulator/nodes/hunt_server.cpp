#include "hunt_server.hpp"

#include <algorithm>
#include <exception>
#include <functional>
#include <thread>

#include "ppp_core/error.hpp"
#include "ppp_msgs/conversions.h"
#include "ppp_msgs/graph_names.h"
#include "ppp_simulator/experiment_graph.hpp"

namespace ppp {
namespace simulator {

HuntServer::HuntServer(ros::NodeHandle& nh, const SimulatorParameters& parameters, const NodeControl& control)
    : nh_(nh), parameters_(parameters), control_(control), config_(launchedConfig(parameters)) {}

HuntServer::~HuntServer() = default;

bool HuntServer::evaluate(ppp_msgs::EvaluateProblems::Request& request, ppp_msgs::EvaluateProblems::Response& response) {
  std::lock_guard<std::mutex> serving(serving_);  // one request at a time: the agents serve one lane each
  try {
    const std::vector<agents::AgentConfig> panel = generator::resolvePanel(request.agents, config_.agents, true);
    std::vector<AgentRunners*> entries;
    for (const agents::AgentConfig& agent : panel) entries.push_back(&runnersOf(agent));
    // Locked in one order (by address): a second caller locking the same agents waits, never deadlocks.
    std::sort(entries.begin(), entries.end(), std::less<AgentRunners*>());
    entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
    std::vector<std::unique_lock<std::mutex>> playing;
    for (AgentRunners* entry : entries) playing.emplace_back(entry->playing);
    std::vector<Problem> problems;
    for (const ppp_msgs::Problem& m : request.problems) problems.push_back(ppp_msgs::fromMessage(m));
    generator::HuntEvaluation evaluation(problems, panel, config_.episode, static_cast<int>(request.runs), request.seed,
                                         parameters_.batch_size, request.run_seeds);
    play(evaluation, panel);
    for (const generator::PanelEvaluation& e : evaluation.evaluations()) response.evaluations.push_back(toMessage(e));
    episodes_ += static_cast<long>(problems.size() * panel.size()) * request.runs;
    ++requests_;
    const std::string line =
        progress_.update(episodes_, 0, steadySeconds(), "evaluations: " + std::to_string(requests_));
    if (!line.empty()) ROS_INFO("%s", line.c_str());
  } catch (const Error& e) {
    response.evaluations.clear();
    response.error = e.what();
    ROS_ERROR("evaluation refused: %s", e.what());
  } catch (const std::exception& e) {
    response.evaluations.clear();
    response.error = std::string("unexpected failure: ") + e.what();
    ROS_ERROR("evaluation failed: %s", e.what());
  }
  return true;
}

std::vector<agents::EpisodeResult> HuntServer::playRows(const agents::AgentConfig& agent, const Problem& problem,
                                                        const std::vector<std::uint64_t>& seeds) {
  std::lock_guard<std::mutex> playing(runnersOf(agent).playing);
  generator::HuntEvaluation evaluation({problem}, {agent}, config_.episode, static_cast<int>(seeds.size()), 0,
                                       parameters_.batch_size, seeds);
  try {
    play(evaluation, {agent});
  } catch (const IoError&) {
    if (control_.stopping()) throw Interrupted();  // stopped mid-run: the caller's stop, not a broken link
    throw;
  }
  std::vector<agents::EpisodeResult> rows = evaluation.rows();
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.run < b.run; });
  return rows;
}

void HuntServer::play(generator::HuntEvaluation& evaluation, const std::vector<agents::AgentConfig>& panel) {
  // One task per lane, pairing the panel's runners with the evaluation's lanes of the same protocol, in order.
  std::vector<std::function<void()>> tasks;
  std::size_t grid = 0, continuous = 0;
  std::vector<AgentRunners*> entries;
  for (const agents::AgentConfig& agent : panel) {
    AgentRunners& entry = runnersOf(agent);
    entry.target = &evaluation;  // its runners' sink
    entries.push_back(&entry);
    if (agents::playsContinuously(agent, config_.episode)) {
      for (const auto& runner : runnersFor(agent, &entry, &entry.continuous)) {
        tasks.push_back([runner = runner.get(), lane = evaluation.continuousLanes().at(continuous++).get()] {
          runner->run(lane);
        });
      }
    } else {
      for (const auto& runner : runnersFor(agent, &entry, &entry.grid)) {
        tasks.push_back([runner = runner.get(), lane = evaluation.lanes().at(grid++).get()] { runner->run(lane); });
      }
    }
  }
  std::vector<std::exception_ptr> failures(tasks.size());
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    threads.emplace_back([task = tasks[i], failure = &failures[i]] {
      try {
        task();
      } catch (...) {
        *failure = std::current_exception();
      }
    });
  }
  for (std::thread& t : threads) t.join();
  for (AgentRunners* entry : entries) entry->target = nullptr;
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
  if (!evaluation.finished()) throw IoError("~evaluate", "shutting down before every run was played");
}

ppp_msgs::ProblemEvaluation HuntServer::toMessage(const generator::PanelEvaluation& e) {
  ppp_msgs::ProblemEvaluation m;
  m.failure_rate = e.estimate.failure_rate;
  m.budget_used = e.estimate.budget_used;
  m.regret = e.estimate.regret;
  m.episodes = static_cast<std::uint32_t>(e.episodes);
  m.failed = static_cast<std::uint32_t>(e.failed);
  for (const auto& [reason, count] : e.reasons) {
    m.reasons.push_back(reason);
    m.reason_counts.push_back(static_cast<std::uint32_t>(count));
  }
  for (const auto& [kind, count] : e.diagnoses) {
    m.diagnoses.push_back(kind);
    m.diagnosis_counts.push_back(static_cast<std::uint32_t>(count));
  }
  m.endless_loops = static_cast<std::uint32_t>(e.endless);
  m.steps = static_cast<std::uint64_t>(e.estimate.steps);
  for (const auto& [signature, count] : e.estimate.signatures) {
    m.signatures.push_back(signature);
    m.signature_counts.push_back(static_cast<std::uint32_t>(count));
  }
  return m;
}

HuntServer::AgentRunners& HuntServer::runnersOf(const agents::AgentConfig& agent) {
  std::lock_guard<std::mutex> lock(agents_mutex_);
  std::unique_ptr<AgentRunners>& entry = agents_[agent.name];
  if (!entry) entry = std::make_unique<AgentRunners>();
  return *entry;
}

template <class Runner>
const std::vector<std::unique_ptr<Runner>>& HuntServer::runnersFor(const agents::AgentConfig& agent,
                                                                    AgentRunners* entry,
                                                                    std::vector<std::unique_ptr<Runner>>* runners) {
  const int instances = agents::instanceCount(agent, config_.episode);
  for (int instance = static_cast<int>(runners->size()); instance < instances; ++instance) {
    runners->push_back(std::make_unique<Runner>(
        nh_, parameters_, control_, agent, agents::LaneShare{instance, instances},
        [entry](const std::vector<agents::EpisodeResult>& ended) { entry->target->record(ended); },
        typename Runner::ScanObserver{}, false));
  }
  return *runners;
}

int runHuntServer(ros::NodeHandle& nh, ros::NodeHandle& services_nh, const SimulatorParameters& parameters,
                  const NodeControl& control) {
  HuntServer server(nh, parameters, control);
  ros::ServiceServer service = services_nh.advertiseService(ppp_msgs::topics::kEvaluate, &HuntServer::evaluate, &server);
  ROS_INFO("serving %s for hunts with the agents of %s", service.getService().c_str(), parameters.config.c_str());
  while (!control.stopping()) ros::WallDuration(0.1).sleep();  // a stop flag has no event to wait on
  return 0;
}

}  // namespace simulator
}  // namespace ppp
