// simulator_node: runs an experiment with every agent in its own process. For each agent configuration NAME
// of the experiment it publishes ppp_msgs/ScanBatch on /NAME/scans (one scan per active episode) and takes
// ppp_msgs/MoveBatch from /NAME/moves, in lockstep, through the same AgentLane and episode code as the
// in-process runner, so the results equal `ppp experiment`'s. Results go to results.csv as episodes end;
// summary.csv and the report are written when all runs are done; a sample of episodes and every result are
// recorded in experiment.bag. The node exits when the experiment is finished.
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <ros/topic.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <thread>

#include "episode_recorder.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_msgs/MoveBatch.h"
#include "ppp_msgs/ProblemSet.h"
#include "ppp_msgs/ScanBatch.h"
#include "ppp_msgs/conversions.h"
#include "ppp_msgs/node_liveness.h"
#include "ppp_simulator/agent_lane.hpp"
#include "ppp_simulator/experiment_runner.hpp"
#include "simulator_parameters.hpp"

namespace ppp {
namespace simulator {

namespace {

const ros::WallDuration kShutdownCheck(0.1);  // a lane waiting for a reply notices a shutdown this often

ppp_msgs::GridCell toCell(Cell c) {
  ppp_msgs::GridCell m;
  m.x = c.x;
  m.y = c.y;
  return m;
}

/// Fills `message` with `scans`, reusing its buffers.
void toMessage(const std::vector<ScanRequest>& scans, ppp_msgs::ScanBatch* message) {
  ppp_msgs::ScanBatch& m = *message;
  const std::size_t n = scans.size();
  m.range = n == 0 ? 0 : static_cast<std::uint8_t>(scans[0].range);
  m.starts.clear();
  m.episodes.resize(n);
  m.steps.resize(n);
  m.positions.resize(n);
  m.bumped.resize(n);
  m.cells.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const ScanRequest& r = scans[i];
    m.episodes[i] = r.episode;
    m.steps[i] = static_cast<std::uint32_t>(r.step);
    m.positions[i] = toCell(r.position);
    m.bumped[i] = r.bumped ? 1 : 0;
    m.cells.insert(m.cells.end(), r.cells.begin(), r.cells.end());
    if (!r.start) continue;
    ppp_msgs::EpisodeStart start;
    start.episode = r.episode;
    start.width = static_cast<std::uint32_t>(r.start->width);
    start.height = static_cast<std::uint32_t>(r.start->height);
    start.start = toCell(r.start->start);
    start.goal = toCell(r.goal);
    start.agent_seed = r.start->agent_seed;
    start.prior_map = r.start->prior_map;
    m.starts.push_back(std::move(start));
  }
}

}  // namespace

/// The batched conversation with one agent node.
class LaneRunner {
 public:
  LaneRunner(ros::NodeHandle& nh, const SimulatorParameters& parameters, AgentLane* lane, ResultsFile* results,
             EpisodeRecorder* recorder)
      : parameters_(parameters), lane_(lane), results_(results), recorder_(recorder) {
    const std::string graph_name = agents::agentGraphName(lane->config().name);
    scans_ = nh.advertise<ppp_msgs::ScanBatch>("/" + graph_name + "/scans", 2);
    // The lane's own callback queue, served by the lane's thread while it waits for the answer: the reply
    // wakes that thread directly, not a spinner thread that would then wake it.
    ros::SubscribeOptions options = ros::SubscribeOptions::create<ppp_msgs::MoveBatch>(
        "/" + graph_name + "/moves", 2, [this](const ppp_msgs::MoveBatch::ConstPtr& m) { onMoves(m); },
        ros::VoidConstPtr(), &replies_);
    options.transport_hints = ros::TransportHints().tcpNoDelay();
    moves_ = nh.subscribe(options);
  }

  /// Plays every run of the lane; returns when it is finished or ROS shuts down.
  void run() {
    const std::string& name = lane_->config().name;
    const double step_timeout =
        agents::isPlanner(lane_->config()) ? parameters_.planner_step_timeout : parameters_.step_timeout;
    if (!waitForAgent()) {
      ROS_ERROR("agent '%s' never connected within %.0f s: its %ld runs fail as agent_lost", name.c_str(),
                parameters_.connect_timeout, lane_->remaining());
      report(lane_->failAll(reason::kAgentLost));
      return;
    }
    const ros::WallTime started = ros::WallTime::now();
    const long episodes = lane_->remaining();
    // Both buffers live across batches, so a batch allocates (almost) nothing.
    std::vector<ScanRequest> scans;
    ppp_msgs::ScanBatch message;
    message.agent = name;
    for (std::uint32_t batch = 1; !lane_->finished() && ros::ok(); ++batch) {
      lane_->scans(&scans);
      message.header.stamp = ros::Time::now();
      message.batch = batch;
      toMessage(scans, &message);
      recorder_->recordScans(name, scans);
      expected_batch_ = batch;
      reply_.reset();
      scans_.publish(message);
      if (awaitReply(step_timeout)) {
        report(lane_->answer(*reply_, missing_reason_));
      } else if (!agentAlive()) {
        ROS_ERROR("agent '%s' is gone: its %ld unfinished runs fail as agent_lost", name.c_str(), lane_->remaining());
        report(lane_->failAll(reason::kAgentLost));
      } else {
        const auto ended = lane_->unanswered(reason::kTimeout, parameters_.timeouts_before_giving_up);
        if (lane_->finished() && lane_->silentBatches() >= parameters_.timeouts_before_giving_up) {
          ROS_ERROR("agent '%s' did not answer %d batches in a row: its unfinished runs fail as timeout",
                    name.c_str(), lane_->silentBatches());
        } else {
          ROS_WARN("agent '%s' did not answer batch %u within %.1f s: its episodes fail as timeout", name.c_str(),
                   batch, step_timeout);
        }
        report(ended);
      }
    }
    const double seconds = (ros::WallTime::now() - started).toSec();
    ROS_INFO("agent '%s': %ld episodes in %.1f s (%.1f episodes/s)", name.c_str(), episodes, seconds,
             seconds > 0 ? episodes / seconds : 0.0);
  }

 private:
  /// Serves the lane's queue until the reply to the current batch came (true), `seconds` passed or ROS
  /// shut down.
  bool awaitReply(double seconds) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
    while (!reply_ && ros::ok()) {
      const ros::WallDuration left = deadline - ros::WallTime::now();
      if (left <= ros::WallDuration(0)) break;
      replies_.callAvailable(std::min(left, kShutdownCheck));
    }
    return reply_.has_value();
  }

  bool waitForAgent() {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(parameters_.connect_timeout);
    while (ros::ok() && ros::WallTime::now() < deadline) {
      if (scans_.getNumSubscribers() > 0 && moves_.getNumPublishers() > 0) return true;
      ros::WallDuration(0.05).sleep();  // polling a connection count: there is no event to wait on
    }
    return false;
  }

  /// True while the agent's process answers (a killed node's registration stays with the master).
  bool agentAlive() const { return ppp_msgs::publisherAlive(moves_.getTopic()); }

  void onMoves(const ppp_msgs::MoveBatch::ConstPtr& message) {
    if (message->batch != expected_batch_ || reply_) return;  // late answer to an earlier batch
    const std::size_t n = message->episodes.size();
    if (message->steps.size() != n || message->actions.size() != n) {
      // A malformed batch answers no episode: all of them fail as invalid_action.
      ROS_WARN_ONCE("agent '%s': a MoveBatch whose episodes, steps and actions differ in length",
                    lane_->config().name.c_str());
      reply_ = std::vector<MoveReply>();
      missing_reason_ = reason::kInvalidAction;
      return;
    }
    std::vector<MoveReply> moves(n);
    for (std::size_t i = 0; i < n; ++i) moves[i] = {message->episodes[i], message->steps[i], message->actions[i]};
    for (const ppp_msgs::EpisodeFailure& f : message->failures) {
      const char* reason = reason::agentReportedReason(f.reason);
      if (reason == nullptr) {
        ROS_WARN_ONCE("agent '%s' gave an episode up for an unknown reason '%s': recorded as invalid_action",
                      lane_->config().name.c_str(), f.reason.c_str());
        reason = reason::kInvalidAction;
      }
      for (MoveReply& m : moves) {
        if (m.episode == f.episode) m.failure = reason;
      }
    }
    reply_ = std::move(moves);
    missing_reason_ = reason::kTimeout;
  }

  void report(const std::vector<EpisodeResult>& results) {
    if (results.empty()) return;
    results_->append(results);
    recorder_->recordResults(results);
  }

  SimulatorParameters parameters_;
  AgentLane* lane_;
  ResultsFile* results_;
  EpisodeRecorder* recorder_;
  ros::CallbackQueue replies_;  // the moves subscription's callbacks, called by the lane's thread
  ros::Publisher scans_;
  ros::Subscriber moves_;       // after replies_: unsubscribes before the queue goes
  std::uint32_t expected_batch_ = 0;
  std::optional<std::vector<MoveReply>> reply_;
  const char* missing_reason_ = reason::kTimeout;  // for episodes the reply has no move for
};

/// Waits for the generator nodes' sets, then runs the experiment.
int runSimulator(ros::NodeHandle& nh, const SimulatorParameters& parameters) {
  const ExperimentConfig config = loadExperimentConfig(parameters.config);
  const std::string config_text = readTextFile(parameters.config, 1u << 20);
  checkExperimentDirectory(config, parameters.output_dir);
  for (const std::string& topic : parameters.wait_for_sets) {
    ROS_INFO("waiting for the PPP set on %s", topic.c_str());
    if (!ros::topic::waitForMessage<ppp_msgs::ProblemSet>(topic, nh, ros::Duration(parameters.set_timeout))) {
      throw InvalidArgument("~wait_for_sets", "no ppp_msgs/ProblemSet on " + topic + " within " +
                                                  std::to_string(parameters.set_timeout) + " s");
    }
  }
  const std::vector<PreparedSet> sets = beginExperiment(config, parameters.output_dir, [](const std::string& line) {
    ROS_INFO("%s", line.c_str());
  });
  ResultsFile results(resultsPath(parameters.output_dir));
  std::vector<std::string> agent_names;
  for (const auto& a : config.agents) agent_names.push_back(a.name);
  EpisodeRecorder recorder(nh, parameters, sets, agent_names, config.episode.budget);
  std::vector<ppp_msgs::ProblemSet> set_messages;
  for (const PreparedSet& set : sets) {
    ppp_msgs::ProblemSet m;
    m.header.stamp = ros::Time::now();
    m.header.frame_id = "map";
    m.name = set.name;
    for (std::size_t i = 0; i < set.set.problems.size(); ++i) {
      m.problems.push_back(ppp_msgs::toMessage(set.set.problems[i], set.set.ids[i], parameters.resolution));
    }
    set_messages.push_back(std::move(m));
  }
  recorder.recordSets(set_messages);

  std::vector<std::unique_ptr<AgentLane>> lanes;
  std::vector<std::unique_ptr<LaneRunner>> runners;
  long remaining = 0;
  for (const auto& agent : config.agents) {
    lanes.push_back(std::make_unique<AgentLane>(agent, config.episode, sets, config.seed, config.runsFor(agent),
                                                results.done(),
                                                parameters.batch_size));
    remaining += lanes.back()->remaining();
    runners.push_back(std::make_unique<LaneRunner>(nh, parameters, lanes.back().get(), &results, &recorder));
  }
  ROS_INFO("running %ld episodes (%zu already done) with %zu agent nodes, batches of %d", remaining,
           results.done().size(), lanes.size(), parameters.batch_size);
  std::vector<std::thread> threads;
  for (auto& runner : runners) threads.emplace_back([&runner] { runner->run(); });
  for (std::thread& t : threads) t.join();
  recorder.close();
  if (!ros::ok()) {
    ROS_WARN("interrupted: every finished run is in results.csv; restart on the same output_dir to resume");
    return 130;
  }
  finishExperiment(config, config_text, parameters.output_dir, sets, &results);
  ROS_INFO("experiment done: report in %s/report.html", parameters.output_dir.c_str());
  return 0;
}

}  // namespace simulator
}  // namespace ppp

int main(int argc, char** argv) {
  ros::init(argc, argv, "simulator");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  int status = 1;
  try {
    status = ppp::simulator::runSimulator(nh, ppp::simulator::readSimulatorParameters(private_nh));
  } catch (const ppp::Error& e) {
    ROS_FATAL("simulator: %s", e.what());
  } catch (const std::exception& e) {
    ROS_FATAL("simulator: unexpected failure: %s", e.what());
  }
  spinner.stop();
  ros::shutdown();
  return status;
}
