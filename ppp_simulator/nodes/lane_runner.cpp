#include "lane_runner.hpp"

#include <algorithm>

#include "ppp_agents/protocol/batch_codec.hpp"
#include "ppp_msgs/node_liveness.h"
#include "ppp_msgs/topic_names.h"

namespace ppp {
namespace simulator {

namespace {

const ros::WallDuration kShutdownCheck(0.1);  // a lane waiting for a reply notices a shutdown this often

}  // namespace

LaneRunner::LaneRunner(ros::NodeHandle& nh, const SimulatorParameters& parameters, const agents::AgentConfig& agent,
                       ResultSink sink, ScanObserver observer, bool log_rates)
    : parameters_(parameters),
      agent_(agent),
      sink_(std::move(sink)),
      observer_(std::move(observer)),
      log_rates_(log_rates) {
  const std::string graph_name = agents::agentGraphName(agent.name);
  scans_ = nh.advertise<ppp_msgs::ScanBatch>(ppp_msgs::topics::under(graph_name, ppp_msgs::topics::kScans), 2);
  // The lane's own callback queue, served by the lane's thread while it waits for the answer: the reply
  // wakes that thread directly, not a spinner thread that would then wake it.
  ros::SubscribeOptions options = ros::SubscribeOptions::create<ppp_msgs::MoveBatch>(
      ppp_msgs::topics::under(graph_name, ppp_msgs::topics::kMoves), 2, [this](const ppp_msgs::MoveBatch::ConstPtr& m) { onMoves(m); },
      ros::VoidConstPtr(), &replies_);
  options.transport_hints = ros::TransportHints().tcpNoDelay();
  moves_ = nh.subscribe(options);
}

void LaneRunner::run(AgentLane* lane) {
  lane_ = lane;
  const std::string& name = agent_.name;
  const double step_timeout =
      agents::isPlanner(agent_) ? parameters_.planner_step_timeout : parameters_.step_timeout;
  if (!connected_ && !waitForAgent()) {
    ROS_ERROR("agent '%s' never connected within %.0f s: its %ld runs fail as agent_lost", name.c_str(),
              parameters_.connect_timeout, lane_->remaining());
    report(lane_->failAll(reason::kAgentLost));
    return;
  }
  if (suspect_ && !agentAlive()) {  // lost in an earlier lane: fail at once instead of after a timeout
    ROS_ERROR("agent '%s' is still gone: its %ld runs fail as agent_lost", name.c_str(), lane_->remaining());
    report(lane_->failAll(reason::kAgentLost));
    return;
  }
  suspect_ = false;
  connected_ = true;
  const ros::WallTime started = ros::WallTime::now();
  const long episodes = lane_->remaining();
  // Both buffers live across batches, so a batch allocates (almost) nothing.
  std::vector<ScanRequest> scans;
  ppp_msgs::ScanBatch message;
  message.agent = name;
  while (!lane_->finished() && ros::ok()) {
    const std::uint32_t batch = ++batch_;
    lane_->scans(&scans);
    message.header.stamp = ros::Time::now();
    message.batch = batch;
    protocol::encodeScans(scans, &message);
    if (observer_) observer_(name, scans);
    expected_batch_ = batch;
    reply_.reset();
    scans_.publish(message);
    if (awaitReply(step_timeout)) {
      report(lane_->answer(*reply_, missing_reason_));
    } else if (!agentAlive()) {
      ROS_ERROR("agent '%s' is gone: its %ld unfinished runs fail as agent_lost", name.c_str(), lane_->remaining());
      report(lane_->failAll(reason::kAgentLost));
      suspect_ = true;
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
  if (log_rates_) {
    ROS_INFO("agent '%s': %ld episodes in %.1f s (%.1f episodes/s)", name.c_str(), episodes, seconds,
             seconds > 0 ? episodes / seconds : 0.0);
  }
}

bool LaneRunner::awaitReply(double seconds) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
  while (!reply_ && ros::ok()) {
    const ros::WallDuration left = deadline - ros::WallTime::now();
    if (left <= ros::WallDuration(0)) break;
    replies_.callAvailable(std::min(left, kShutdownCheck));
  }
  return reply_.has_value();
}

bool LaneRunner::waitForAgent() {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(parameters_.connect_timeout);
  while (ros::ok() && ros::WallTime::now() < deadline) {
    if (scans_.getNumSubscribers() > 0 && moves_.getNumPublishers() > 0) return true;
    ros::WallDuration(0.05).sleep();  // polling a connection count: there is no event to wait on
  }
  return false;
}

bool LaneRunner::agentAlive() const { return ppp_msgs::publisherAlive(moves_.getTopic()); }

void LaneRunner::onMoves(const ppp_msgs::MoveBatch::ConstPtr& message) {
  if (message->batch != expected_batch_ || reply_) return;  // late answer to an earlier batch
  protocol::DecodedMoves decoded = protocol::decodeMoves(*message);
  if (!decoded.fault.empty()) ROS_WARN_ONCE("agent '%s': %s", agent_.name.c_str(), decoded.fault.c_str());
  reply_ = std::move(decoded.moves);
  missing_reason_ = decoded.missing_reason;
}

void LaneRunner::report(const std::vector<EpisodeResult>& results) {
  if (!results.empty()) sink_(results);
}

}  // namespace simulator
}  // namespace ppp
