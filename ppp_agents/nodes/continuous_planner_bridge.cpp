#include "continuous_planner_bridge.hpp"

#include <boost/make_shared.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "planner_bridge_messages.hpp"
#include "ppp_agents/protocol/batch_types.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/error.hpp"
#include "ppp_msgs/graph_names.h"

namespace ppp {
namespace agents {

namespace {

// Simulated time between one episode's last period and the next one's first: a second, or two control periods when
// that is longer, so a planner tells an episode's first period from one that continues the last (one period on).
const ros::Duration kEpisodeGap(1.0);

ros::Duration episodeGap(double control_period) {
  return std::max(kEpisodeGap, ros::Duration(2 * control_period));
}

}  // namespace

ContinuousPlannerBridge::ContinuousPlannerBridge(PlannerLink* link, const BridgeParameters& parameters,
                                                 bool in_network_thread)
    : link_(*link),
      parameters_(parameters),
      spinner_(1, &own_queue_),
      handed_over_(in_network_thread ? nullptr : std::make_unique<ppp_msgs::LockstepQueue>(false)) {}

ContinuousPlannerBridge::~ContinuousPlannerBridge() {
  sensing_.shutdown();
  spinner_.stop();
}

void ContinuousPlannerBridge::serve(ros::NodeHandle& nh) {
  commands_ = nh.advertise<ppp_msgs::CommandBatch>(ppp_msgs::topics::kCommands, 10);
  ros::SubscribeOptions options;
  options.init<ppp_msgs::SensingBatch>(ppp_msgs::topics::kSensing, 10,
                                       [this](const ppp_msgs::SensingBatch::ConstPtr& b) { onSensing(b); });
  options.callback_queue = handed_over_ ? handed_over_->get() : &own_queue_;
  // The planner's time starts before its first episode: a timer or rate started at time 0 waits for the first
  // clock and then a whole period, which the episode's first period would wait on for ever.
  last_stamp_ = ros::Time(1.0);
  link_.publishClock(last_stamp_);
  link_.publishOdometryFrame();
  sensing_ = nh.subscribe(options);
  if (!handed_over_) spinner_.start();
}

void ContinuousPlannerBridge::warnOnce(const std::string& kind, const std::string& text) {
  if (warnings_[kind]++ == 0) {
    ROS_WARN("bridge '%s': %s (further '%s' warnings are not logged)", parameters_.config.name.c_str(),
             text.c_str(), kind.c_str());
  }
}

void ContinuousPlannerBridge::onSensing(const ppp_msgs::SensingBatch::ConstPtr& batch) {
  std::vector<agents::ContinuousReply> replies(batch->episodes.size());
  for (std::size_t i = 0; i < replies.size(); ++i) {
    replies[i].episode = batch->episodes[i];
    replies[i].step = i < batch->steps.size() ? static_cast<int>(batch->steps[i]) : 0;
    replies[i].failure = reason::kInvalidCommand;  // unless played below
  }
  std::string what;
  const std::string fault = protocol::checkSensingBatch(*batch, &what);
  if (!fault.empty()) {
    warnOnce(fault, "rejected a malformed batch: " + what);
  } else if (!replies.empty()) {
    for (std::size_t i = 1; i < replies.size(); ++i) {
      warnOnce("batch_size", "the bridge plays one episode at a time; rejected episode " +
                                 std::to_string(batch->episodes[i]) + " (give the agent type planner)");
    }
    replies[0] = step(*batch);
  }
  auto commands = boost::make_shared<ppp_msgs::CommandBatch>(
      protocol::encodeCommands(parameters_.config.name, batch->batch, replies));
  commands->header.stamp = ros::Time::now();
  commands_.publish(commands);
}

agents::ContinuousReply ContinuousPlannerBridge::step(const ppp_msgs::SensingBatch& batch) {
  agents::ContinuousReply reply{batch.episodes[0], static_cast<int>(batch.steps[0]), {}, nullptr};
  bool begins = false;  // the batch's period is its episode's first
  for (const ppp_msgs::ContinuousStart& start : batch.starts) {
    if (start.episode != reply.episode) continue;
    begins = true;
    try {
      episode_ = protocol::decodeContinuousStart(start);
    } catch (const InvalidArgument& e) {
      warnOnce(e.name(), std::string("rejected an episode's start: ") + e.what());
      episode_.reset();
      reply.failure = reason::kInvalidCommand;
      return reply;
    }
    episode_id_ = start.episode;
    origin_ = last_stamp_ + episodeGap(episode_->start.control_period);
    episode_start_ = origin_;
    link_.newEpisode();
    const MapFrame& frame = episode_->start.frame;
    const Grid* prior = episode_->start.prior_map;
    start_map_ = prior != nullptr ? protocol::priorMapCells(*prior)
                                  : std::vector<std::int8_t>(static_cast<std::size_t>(frame.width) * frame.height,
                                                             kScanUnknown);
    if (!commandsVelocity(parameters_)) {
      link_.publishContinuousMap(origin_, episode_start_, frame, start_map_);
      plans_.start(episode_->start, parameters_.plan_requests);
    }
  }
  if (!episode_ || episode_id_ != reply.episode) {
    warnOnce("episode", "sensing for episode " + std::to_string(reply.episode) + " that never started");
    reply.failure = reason::kInvalidCommand;
    return reply;
  }
  const ros::Time stamp = origin_ + ros::Duration(batch.time[0]);
  if (begins) first_period_ = stamp;
  last_stamp_ = stamp;
  const std::vector<float> ranges(batch.ranges.begin(), batch.ranges.end());
  const ContinuousSensing sensing{Pose2D{batch.x[0], batch.y[0], batch.theta[0]},
                                  BodyVelocity{batch.forward[0], batch.left[0], batch.turn[0]}, batch.time[0], &ranges};
  if (commandsVelocity(parameters_)) {
    command(stamp, sensing, &reply);
  } else {
    followPlans(stamp, sensing, &reply);
  }
  return reply;
}

void ContinuousPlannerBridge::publish(const ros::Time& stamp, const ContinuousSensing& sensing, bool request) {
  const ContinuousStart& start = episode_->start;
  // A planner in a process of its own reads each topic on a connection of its own, in no set order, and tells the
  // period's map (and so whether it begins a new episode) from the previous episode's by its stamp: with
  // period_messages every, each period of a local planner's carries the map and goal stamped with it; with changes,
  // only the episode's first does, and the planner tells a later period by its distance from the last it answered
  // (one control period).
  const bool velocity = commandsVelocity(parameters_);
  const bool episode_news = !velocity || !sendsChangesOnly(parameters_) || stamp == first_period_;
  if (velocity && episode_news) {
    link_.publishContinuousMap(stamp, episode_start_, start.frame, start_map_);
  }
  link_.publishContinuous(stamp, sensing.pose, sensing.velocity, *sensing.ranges, start.beams,
                          request && episode_news ? std::optional<MapPoint>(start.goal) : std::nullopt);
}

const char* ContinuousPlannerBridge::silentPlannerFailure() {
  return link_.lostWhileWaiting() || link_.gone() ? reason::kPlannerLost : reason::kPlannerTimeout;
}

void ContinuousPlannerBridge::command(const ros::Time& stamp, const ContinuousSensing& sensing,
                                      ContinuousReply* reply) {
  publish(stamp, sensing, true);
  // A period left unanswered for a wall second is asked again (a planner that restarted missed it). A timer on the
  // robot's clock can sleep past the period it is asked: a planner that started its timer at the period's time (it
  // started late), or rospy's Rate, which reads the clock once to reckon its sleep and again to start it, and
  // oversleeps by a period when the clock moved between the two. The clock moves only when the planner answers, so
  // such a planner would never wake: it is asked the period again one control period later, the rest of the episode
  // moved with it (the period's sensing is the same, so a planner whose answer depends on what it senses answers as
  // it would have). A planner that answers each period's messages gets them again as they were: one that is only
  // slow answers the period once, and its time runs as it would have.
  const auto resend = [&] {
    if (!wakesOnTimer(parameters_)) return publish(stamp, sensing, true);
    origin_ += ros::Duration(episode_->start.control_period);
    last_stamp_ = origin_ + ros::Duration(sensing.time);
    publish(last_stamp_, sensing, true);
  };
  const std::optional<VelocityAnswer> answer = link_.waitForCommand(stamp, resend);
  if (!answer) {
    reply->failure = silentPlannerFailure();
    return;
  }
  if (answer->aborted) {
    ROS_INFO_THROTTLE(5, "bridge '%s': episode %u fails as %s: the planner gave up: %s",
                      parameters_.config.name.c_str(), episode_id_, reason::kPlannerAborted, answer->aborted->c_str());
    reply->failure = reason::kPlannerAborted;
    return;
  }
  const geometry_msgs::TwistStamped* command = &answer->command;
  const std::string& frame = command->header.frame_id;
  if (!frame.empty() && frame != parameters_.base_frame) {
    warnOnce("frame", "a command in frame '" + frame + "'; expected the robot's, '" + parameters_.base_frame + "'");
    reply->failure = reason::kInvalidCommand;
    return;
  }
  reply->command = BodyVelocity{command->twist.linear.x, command->twist.linear.y, command->twist.angular.z};
}

void ContinuousPlannerBridge::followPlans(const ros::Time& stamp, const ContinuousSensing& sensing,
                                          ContinuousReply* reply) {
  const bool ask = plans_.observe(sensing);
  if (ask) link_.publishContinuousMap(stamp, episode_start_, episode_->start.frame, plans_.map());
  publish(stamp, sensing, ask);
  if (ask) {
    const auto resend = [&] {
      link_.publishContinuousMap(stamp, episode_start_, episode_->start.frame, plans_.map());
      publish(stamp, sensing, true);
    };
    const std::optional<nav_msgs::Path> path =
        link_.waitForPath(stamp, [](const nav_msgs::Path&) { return true; }, resend);
    if (!path) {
      reply->failure = silentPlannerFailure();
      return;
    }
    std::vector<MapPoint> points;
    const std::string frame_problem = pathPoints(*path, parameters_.map_frame, &points);
    const PlanVerdict verdict = frame_problem.empty() ? plans_.take(points, sensing.pose)
                                                      : PlanVerdict{reason::kInvalidPath, frame_problem};
    if (verdict.failure != nullptr) {
      ROS_INFO_THROTTLE(5, "bridge '%s': episode %u fails as %s: %s", parameters_.config.name.c_str(), episode_id_,
                        verdict.failure, verdict.detail.c_str());
      reply->failure = verdict.failure;
      return;
    }
  }
  reply->command = plans_.command(sensing);
}

}  // namespace agents
}  // namespace ppp
