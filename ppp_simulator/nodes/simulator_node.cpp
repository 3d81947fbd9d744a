#include "simulator_node.hpp"

#include <algorithm>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <thread>

#include "episode_recorder.hpp"
#include "hunt_server.hpp"
#include "progress_reporter.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_msgs/conversions.h"
#include "ppp_agents/agent_lane.hpp"
#include "ppp_agents/continuous/continuous_runner.hpp"
#include "ppp_simulator/experiment_graph.hpp"
#include "ppp_simulator/experiment_runner.hpp"
#include "set_receiver.hpp"

namespace ppp {
namespace simulator {

namespace {

/// One agent instance's lane of the experiment and the runner that plays it, in either motion model.
class PlayedLane {
 public:
  virtual ~PlayedLane() = default;
  /// Plays the lane to its end (or until the node stops). @throws what the runner's result sink threw.
  virtual void play() = 0;
  /// Runs not yet played.
  virtual long remaining() const = 0;
};

template <class Lockstep>
class PlayedLaneOf : public PlayedLane {
 public:
  template <class... RunnerArguments>
  PlayedLaneOf(typename Lockstep::Lane lane, RunnerArguments&&... arguments)
      : lane_(std::move(lane)), runner_(std::forward<RunnerArguments>(arguments)...) {}
  void play() override { runner_.run(&lane_); }
  long remaining() const override { return lane_.remaining(); }

 private:
  typename Lockstep::Lane lane_;
  LaneRunnerOf<Lockstep> runner_;
};

}  // namespace

SimulatorNode::SimulatorNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, bool in_network_thread)
    : nh_(nh),
      parameters_(readSimulatorParameters(private_nh)),
      control_{[this] { return stop_requested_ || !ros::ok(); }, in_network_thread},
      services_nh_(private_nh),
      services_spinner_(1, &services_queue_) {
  services_nh_.setCallbackQueue(&services_queue_);
  services_spinner_.start();
}

SimulatorNode::~SimulatorNode() {
  stop();
  services_spinner_.stop();
}

int SimulatorNode::run() {
  try {
    return parameters_.mode == kHuntMode ? runHuntServer(nh_, services_nh_, parameters_, control_) : runExperiment();
  } catch (const Error& e) {
    ROS_FATAL("simulator: %s", e.what());
  } catch (const std::exception& e) {
    ROS_FATAL("simulator: unexpected failure: %s", e.what());
  }
  return 1;
}

/// Takes the sets (from the generator nodes, or made here), then runs the experiment.
int SimulatorNode::runExperiment() {
  ros::NodeHandle& nh = nh_;
  const SimulatorParameters& parameters = parameters_;
  const std::function<bool()> stopping = control_.stopping;
  const ExperimentConfig config = launchedConfig(parameters);
  const std::string config_text = readTextFile(parameters.config, 1u << 20);
  ReceivedSets received;
  if (parameters.generator_nodes) {
    openExperimentDirectory(config, parameters.output_dir);
    received = receiveSets(nh, services_nh_, config, parameters, control_);
    if (received.sets.empty()) return 130;  // shut down while waiting
  } else {
    try {
      received.sets = beginExperiment(
          config, parameters.output_dir, [](const std::string& line) { ROS_INFO("%s", line.c_str()); },
          stopping);
    } catch (const Interrupted&) {
      return 130;  // shut down mid-generation; the set being evolved was not written
    }
    for (const agents::PreparedSet& set : received.sets) {
      received.messages.push_back(ppp_msgs::toSetMessage(set.name, set.set.problems, set.set.ids, parameters.resolution));
    }
  }
  const std::vector<agents::PreparedSet>& sets = received.sets;
  checkContinuousStarts(config, sets);
  std::unique_ptr<ResultsFile> opened;
  try {
    opened = std::make_unique<ResultsFile>(resultsPath(parameters.output_dir), stopping);
  } catch (const Interrupted&) {
    return 130;  // shut down while reading the results of an earlier run; the file is as it was
  }
  ResultsFile& results = *opened;
  std::vector<std::string> agent_names;
  for (const auto& a : config.agents) agent_names.push_back(a.name);
  const bool continuous = std::any_of(config.agents.begin(), config.agents.end(), [&](const agents::AgentConfig& a) {
    return agents::playsContinuously(a, config.episode);
  });
  EpisodeRecorder recorder(nh, parameters, sets, agent_names, agents::largestActionLimit(sets),
                           continuous ? agents::longestContinuousRun(sets, config.episode) : 0);
  recorder.recordSets(received.messages);

  // A lane whose results cannot be written stops every lane: the node exits 1.
  std::atomic<bool> failed{false};
  NodeControl lanes_control = control_;
  lanes_control.stopping = [&failed, stopping] { return failed || stopping(); };
  std::vector<std::unique_ptr<PlayedLane>> lanes;
  std::map<std::string, long> runs_of_agent;             // what each agent's lanes have to play ...
  std::map<std::string, std::atomic<long>> ended_of_agent;  // ... and have played (the progress line's lanes)
  for (const auto& agent : config.agents) ended_of_agent[agent.name].store(0);
  const auto sink = [&results, &recorder, &ended_of_agent](const std::vector<agents::EpisodeResult>& ended) {
    results.append(ended);
    recorder.recordResults(ended);
    for (const agents::EpisodeResult& r : ended) ++ended_of_agent.at(r.agent);
  };
  for (const auto& agent : config.agents) {
    const int instances = agents::instanceCount(agent, config.episode);  // instances share the agent's runs
    for (int instance = 0; instance < instances; ++instance) {
      const agents::LaneShare share{instance, instances};
      if (agents::playsContinuously(agent, config.episode)) {
        lanes.push_back(std::make_unique<PlayedLaneOf<ContinuousLockstep>>(
            experimentContinuousLane(agent, config.episode, sets, config.seed, config.runsFor(agent), results.done(),
                                     parameters.batch_size, share),
            nh, parameters, lanes_control, agent, share, sink,
            [&recorder](const std::string& name, const agents::ContinuousRequest& sensing) {
              recorder.recordSensing(name, sensing);
            }));
      } else {
        lanes.push_back(std::make_unique<PlayedLaneOf<GridLockstep>>(
            experimentLane(agent, config.episode, sets, config.seed, config.runsFor(agent), results.done(),
                           parameters.batch_size, share),
            nh, parameters, lanes_control, agent, share, sink,
            [&recorder](const std::string& name, const protocol::ScanRequest& scan) {
              recorder.recordScan(name, scan);
            }));
      }
      runs_of_agent[agent.name] += lanes.back()->remaining();
    }
  }
  long remaining = 0;
  for (const auto& [agent, runs] : runs_of_agent) remaining += runs;
  ROS_INFO("running %ld episodes (%zu already done, %zu lost to the agent link played again) with %zu agent nodes and "
           "planner instances, batches of %d", remaining, results.done().size(), results.lostRuns(), lanes.size(),
           parameters.batch_size);
  {
    const ProgressReporter progress("episodes", "episodes", [&runs_of_agent, &ended_of_agent] {
      std::vector<LaneCount> counts;
      for (const auto& [agent, runs] : runs_of_agent) counts.push_back({agent, ended_of_agent.at(agent).load(), runs});
      return counts;
    });
    std::vector<std::thread> threads;
    for (const std::unique_ptr<PlayedLane>& lane : lanes) {
      threads.emplace_back([&lane, &failed] {
        try {
          lane->play();
        } catch (const std::exception& e) {  // results.csv or the bag cannot be written (a full disk, say)
          ROS_FATAL("simulator: %s", e.what());
          failed = true;  // every lane stops
        }
      });
    }
    for (std::thread& t : threads) t.join();
  }
  if (failed) return 1;
  lanes.clear();  // their agents are free for the report's planner runs
  recorder.close();
  if (stopping()) {
    ROS_WARN("interrupted: every finished run is in results.csv; restart on the same output_dir to resume");
    return 130;
  }
  // The report shrinks each planner's worst PPP, and a hunted set's corpus its failures, by playing candidates on the
  // planner's bridges, as a hunt does; a planner whose link is lost is not asked again (each try would wait for it to
  // connect). Planners are played from several threads at once (one agent each).
  std::mutex planner_runs_mutex;  // guards the two below
  std::unique_ptr<HuntServer> planner_runs;
  std::set<std::string> unreachable;
  const PlannerRows planner_rows = [&](const agents::AgentConfig& agent, const Problem& problem,
                                       const std::vector<std::uint64_t>& seeds) {
    HuntServer* server = nullptr;
    {
      std::lock_guard<std::mutex> lock(planner_runs_mutex);
      if (unreachable.count(agent.name) > 0) throw AgentUnreachable(agent.name, "lost after its runs");
      if (!planner_runs) planner_runs = std::make_unique<HuntServer>(nh, parameters, control_);
      server = planner_runs.get();
    }
    std::vector<agents::EpisodeResult> rows = server->playRows(agent, problem, seeds);
    if (std::any_of(rows.begin(), rows.end(), [](const auto& r) { return leavesAgentUnreachable(r.reason); })) {
      std::lock_guard<std::mutex> lock(planner_runs_mutex);
      unreachable.insert(agent.name);
      ROS_WARN("agent '%s' is gone: its failures are not shrunk (for the report, into a corpus)", agent.name.c_str());
      throw AgentUnreachable(agent.name, "lost after its runs");
    }
    return rows;
  };
  try {
    finishExperiment(config, config_text, parameters.output_dir, sets, &results, stopping,
                     [](const std::string& line) { ROS_INFO("%s", line.c_str()); }, planner_rows);
  } catch (const Interrupted&) {
    ROS_WARN("interrupted while finishing (the report, the corpora): restart on the same output_dir to finish");
    return 130;
  }
  ROS_INFO("experiment done: report in %s/report.html", parameters.output_dir.c_str());
  return 0;
}

}  // namespace simulator
}  // namespace ppp
