#include "lane_runner.hpp"

#include <algorithm>
#include <chrono>

#include <boost/make_shared.hpp>

#include "ppp_agents/protocol/batch_codec.hpp"
#include "ppp_msgs/hand_over.h"
#include "ppp_msgs/node_liveness.h"
#include "ppp_msgs/graph_names.h"

namespace ppp {
namespace simulator {

namespace {

const ros::WallDuration kShutdownCheck(0.1);  // a lane waiting for a reply notices a shutdown this often

/// Writes a lane's scans into the message to send and shows each to an observer.
class ObservedScans : public protocol::ScanSink {
 public:
  ObservedScans(ppp_msgs::ScanBatch* message, const std::string& agent, const LaneRunner::ScanObserver& observer)
      : writer_(message), agent_(agent), observer_(observer) {}
  void begin(std::size_t count, int range, bool window) override { writer_.begin(count, range, window); }
  void add(protocol::ScanRequest& scan) override {
    observer_(agent_, scan);  // before the writer may move the start away
    writer_.add(scan);
  }

 private:
  protocol::ScanBatchWriter writer_;
  const std::string& agent_;
  const LaneRunner::ScanObserver& observer_;
};

}  // namespace

LaneRunner::LaneRunner(ros::NodeHandle& nh, const SimulatorParameters& parameters, const NodeControl& control,
                       const agents::AgentConfig& agent, int instance, ResultSink sink, ScanObserver observer,
                       bool log_rates)
    : parameters_(parameters),
      control_(control),
      agent_(agent),
      label_("agent '" + agent.name + "'" +
             (agents::instanceCount(agent) > 1 ? " instance " + std::to_string(instance + 1) : std::string())),
      sink_(std::move(sink)),
      observer_(std::move(observer)),
      log_rates_(log_rates),
      step_timeout_(agents::isPlanner(agent) ? parameters.planner_step_timeout : parameters.step_timeout) {
  const std::string graph_name = agents::instanceGraphName(agent, instance);
  if (control.in_network_thread) {
    inline_replies_ = std::make_unique<ppp_msgs::InlineCallbackQueue>();
  } else {
    queued_replies_ = std::make_unique<ros::CallbackQueue>();
  }
  scans_ = nh.advertise<ppp_msgs::ScanBatch>(ppp_msgs::topics::under(graph_name, ppp_msgs::topics::kScans), 2);
  moves_ = ppp_msgs::subscribeLockstep<ppp_msgs::MoveBatch>(
      nh, ppp_msgs::topics::under(graph_name, ppp_msgs::topics::kMoves), 2,
      [this](const ppp_msgs::MoveBatch::ConstPtr& m) { onMoves(m); },
      inline_replies_ ? static_cast<ros::CallbackQueueInterface*>(inline_replies_.get()) : queued_replies_.get());
}

void LaneRunner::run(agents::AgentLane* lane) {
  const char* name = label_.c_str();
  if (!connected_ && !waitForAgent()) {
    ROS_ERROR("%s never connected within %.0f s: its %ld runs fail as agent_lost", name,
              parameters_.connect_timeout, lane->remaining());
    report(lane->failAll(reason::kAgentLost));
    return;
  }
  if (suspect_ && !agentAlive()) {  // lost in an earlier lane: fail at once instead of after a timeout
    ROS_ERROR("%s is still gone: its %ld runs fail as agent_lost", name, lane->remaining());
    report(lane->failAll(reason::kAgentLost));
    return;
  }
  suspect_ = false;
  connected_ = true;
  const ros::WallTime started = ros::WallTime::now();
  const long episodes = lane->remaining();
  std::unique_lock<std::mutex> lock(mutex_);
  lane_ = lane;
  failure_ = nullptr;
  try {
    if (!lane_->finished()) sendBatch();
    // Replies are played in the network thread (onMoves), or here from queued_replies_; this thread wakes for
    // them, the deadline and a stop.
    while (!lane_->finished() && !failure_ && !control_.stopping()) {
      const ros::WallDuration left = deadline_ - ros::WallTime::now();
      if (left > ros::WallDuration(0) && queued_replies_) {
        lock.unlock();  // onMoves takes it
        queued_replies_->callAvailable(std::min(left, kShutdownCheck));
        lock.lock();
      } else if (left > ros::WallDuration(0)) {
        lane_done_.wait_for(lock, std::chrono::nanoseconds(std::min(left, kShutdownCheck).toNSec()));
      } else {
        answerSilence();
      }
    }
  } catch (...) {
    failure_ = std::current_exception();
  }
  lane_ = nullptr;
  expected_batch_ = 0;
  if (failure_) std::rethrow_exception(failure_);
  lock.unlock();
  const double seconds = (ros::WallTime::now() - started).toSec();
  if (log_rates_) {
    ROS_INFO("%s: %ld episodes in %.1f s (%.1f episodes/s)", name, episodes, seconds,
             seconds > 0 ? episodes / seconds : 0.0);
  }
}

void LaneRunner::sendBatch() {
  const std::uint32_t batch = ++batch_;
  // A new message per batch, published by pointer: an agent in the same process gets this very object.
  auto message = boost::make_shared<ppp_msgs::ScanBatch>();
  message->agent = agent_.name;
  message->header.stamp = ros::Time::now();
  message->batch = batch;
  if (observer_) {
    ObservedScans scans(message.get(), agent_.name, observer_);
    lane_->scans(&scans);
  } else {
    protocol::ScanBatchWriter scans(message.get());
    lane_->scans(&scans);
  }
  expected_batch_ = batch;
  deadline_ = ros::WallTime::now() + ros::WallDuration(step_timeout_);
  ppp_msgs::publishHandingOver(scans_, message);  // an agent nodelet answers here, in this thread
}

void LaneRunner::answerSilence() {
  const char* name = label_.c_str();
  const std::uint32_t batch = expected_batch_;
  expected_batch_ = 0;  // a late reply to it is dropped
  if (!agentAlive()) {
    ROS_ERROR("%s is gone: its %ld unfinished runs fail as agent_lost", name, lane_->remaining());
    report(lane_->failAll(reason::kAgentLost));
    suspect_ = true;
    return;
  }
  const auto ended = lane_->unanswered(reason::kTimeout, parameters_.timeouts_before_giving_up);
  if (lane_->finished() && lane_->silentBatches() >= parameters_.timeouts_before_giving_up) {
    ROS_ERROR("%s did not answer %d batches in a row: its unfinished runs fail as timeout", name,
              lane_->silentBatches());
  } else {
    ROS_WARN("%s did not answer batch %u within %.1f s: its episodes fail as timeout", name, batch,
             step_timeout_);
  }
  report(ended);
  if (!lane_->finished()) sendBatch();
}

bool LaneRunner::waitForAgent() {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(parameters_.connect_timeout);
  while (!control_.stopping() && ros::WallTime::now() < deadline) {
    if (scans_.getNumSubscribers() > 0 && moves_.getNumPublishers() > 0) return true;
    ros::WallDuration(0.05).sleep();  // polling a connection count: there is no event to wait on
  }
  return false;
}

bool LaneRunner::agentAlive() const { return ppp_msgs::publisherAlive(moves_.getTopic()); }

void LaneRunner::onMoves(const ppp_msgs::MoveBatch::ConstPtr& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (lane_ == nullptr || failure_ || message->batch != expected_batch_) return;  // late or unexpected
  expected_batch_ = 0;
  protocol::DecodedMoves decoded = protocol::decodeMoves(*message);
  if (!decoded.fault.empty()) ROS_WARN_ONCE("%s: %s", label_.c_str(), decoded.fault.c_str());
  try {
    report(lane_->answer(decoded.moves, decoded.missing_reason));
    if (!lane_->finished()) sendBatch();
  } catch (...) {
    failure_ = std::current_exception();
  }
  if (lane_->finished() || failure_) lane_done_.notify_all();
}

void LaneRunner::report(const std::vector<agents::EpisodeResult>& results) {
  if (!results.empty()) sink_(results);
}

}  // namespace simulator
}  // namespace ppp
