#include "lane_runner.hpp"

#include <algorithm>
#include <chrono>

#include <boost/make_shared.hpp>

#include "ppp_agents/protocol/batch_codec.hpp"
#include "ppp_agents/protocol/continuous_codec.hpp"
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

/// A grid lane's next batch of scans, written into `message`.
void fillBatch(agents::AgentLane* lane, ppp_msgs::ScanBatch* message, std::vector<protocol::ScanRequest>*,
               const LaneRunner::ScanObserver& observer) {
  if (observer) {
    ObservedScans scans(message, message->agent, observer);
    lane->scans(&scans);
  } else {
    protocol::ScanBatchWriter scans(message);
    lane->scans(&scans);
  }
}

/// A continuous lane's next batch of sensing, written into `message` through `requests`.
void fillBatch(agents::ContinuousLane* lane, ppp_msgs::SensingBatch* message,
               std::vector<agents::ContinuousRequest>* requests, const ContinuousLaneRunner::ScanObserver& observer) {
  lane->requests(requests);
  if (observer) {
    for (const agents::ContinuousRequest& request : *requests) observer(message->agent, request);
  }
  protocol::encodeSensing(*requests, message);
}

/// Applies a grid lane's moves; returns the episodes that ended.
std::vector<agents::EpisodeResult> applyBatch(agents::AgentLane* lane, const ppp_msgs::MoveBatch& message,
                                              const std::string& label) {
  protocol::DecodedMoves decoded = protocol::decodeMoves(message);
  if (!decoded.fault.empty()) ROS_WARN_ONCE("%s: %s", label.c_str(), decoded.fault.c_str());
  return lane->answer(decoded.moves, decoded.missing_reason);
}

/// Applies a continuous lane's commands; returns the episodes that ended.
std::vector<agents::EpisodeResult> applyBatch(agents::ContinuousLane* lane, const ppp_msgs::CommandBatch& message,
                                              const std::string& label) {
  protocol::DecodedCommands decoded = protocol::decodeCommands(message);
  if (!decoded.fault.empty()) ROS_WARN_ONCE("%s: %s", label.c_str(), decoded.fault.c_str());
  return lane->answer(decoded.replies, decoded.missing_reason);
}

}  // namespace

template <class Lockstep>
LaneRunnerOf<Lockstep>::LaneRunnerOf(ros::NodeHandle& nh, const SimulatorParameters& parameters,
                                     const NodeControl& control, const agents::AgentConfig& agent,
                                     agents::LaneShare share, ResultSink sink, ScanObserver observer, bool log_rates)
    : parameters_(parameters),
      control_(control),
      agent_(agent),
      label_("agent '" + agent.name + "'" +
             (share.count > 1 ? " instance " + std::to_string(share.index + 1) : std::string())),
      sink_(std::move(sink)),
      observer_(std::move(observer)),
      log_rates_(log_rates),
      step_timeout_(agents::isPlanner(agent) ? parameters.planner_step_timeout : parameters.step_timeout) {
  const std::string graph_name = agents::instanceGraphName(agent, share.index, share.count);
  if (control.in_network_thread) {
    inline_replies_ = std::make_unique<ppp_msgs::InlineCallbackQueue>();
  } else {
    queued_replies_ = std::make_unique<ros::CallbackQueue>();
  }
  using Requests = typename Lockstep::Requests;
  using Replies = typename Lockstep::Replies;
  request_publisher_ = nh.advertise<Requests>(ppp_msgs::topics::under(graph_name, Lockstep::kRequestTopic), 2);
  reply_subscriber_ = ppp_msgs::subscribeLockstep<Replies>(
      nh, ppp_msgs::topics::under(graph_name, Lockstep::kReplyTopic), 2,
      [this](const typename Replies::ConstPtr& m) { onReplies(m); },
      inline_replies_ ? static_cast<ros::CallbackQueueInterface*>(inline_replies_.get()) : queued_replies_.get());
}

template <class Lockstep>
void LaneRunnerOf<Lockstep>::run(Lane* lane) {
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
    // Replies are played in the network thread (onReplies), or here from queued_replies_; this thread wakes for
    // them, the deadline and a stop.
    while (!lane_->finished() && !failure_ && !control_.stopping()) {
      const ros::WallDuration left = deadline_ - ros::WallTime::now();
      if (left > ros::WallDuration(0) && queued_replies_) {
        lock.unlock();  // onReplies takes it
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

template <class Lockstep>
void LaneRunnerOf<Lockstep>::sendBatch() {
  const std::uint32_t batch = ++batch_;
  // A new message per batch, published by pointer: an agent in the same process gets this very object.
  auto message = boost::make_shared<typename Lockstep::Requests>();
  message->agent = agent_.name;
  message->header.stamp = ros::Time::now();
  message->batch = batch;
  fillBatch(lane_, message.get(), &requests_, observer_);
  expected_batch_ = batch;
  deadline_ = ros::WallTime::now() + ros::WallDuration(step_timeout_);
  ppp_msgs::publishHandingOver(request_publisher_, message);  // an agent nodelet answers here, in this thread
}

template <class Lockstep>
void LaneRunnerOf<Lockstep>::answerSilence() {
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

template <class Lockstep>
bool LaneRunnerOf<Lockstep>::waitForAgent() {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(parameters_.connect_timeout);
  while (!control_.stopping() && ros::WallTime::now() < deadline) {
    if (request_publisher_.getNumSubscribers() > 0 && reply_subscriber_.getNumPublishers() > 0) return true;
    ros::WallDuration(0.05).sleep();  // polling a connection count: there is no event to wait on
  }
  return false;
}

template <class Lockstep>
bool LaneRunnerOf<Lockstep>::agentAlive() const { return ppp_msgs::publisherAlive(reply_subscriber_.getTopic()); }

template <class Lockstep>
void LaneRunnerOf<Lockstep>::onReplies(const typename Lockstep::Replies::ConstPtr& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (lane_ == nullptr || failure_ || message->batch != expected_batch_) return;  // late or unexpected
  expected_batch_ = 0;
  try {
    report(applyBatch(lane_, *message, label_));
    if (!lane_->finished()) sendBatch();
  } catch (...) {
    failure_ = std::current_exception();
  }
  if (lane_->finished() || failure_) lane_done_.notify_all();
}

template <class Lockstep>
void LaneRunnerOf<Lockstep>::report(const std::vector<agents::EpisodeResult>& results) {
  if (!results.empty()) sink_(results);
}

template class LaneRunnerOf<GridLockstep>;
template class LaneRunnerOf<ContinuousLockstep>;

}  // namespace simulator
}  // namespace ppp
