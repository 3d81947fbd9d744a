#include "velocity_planner_link.hpp"

#include <actionlib_msgs/GoalStatus.h>
#include <boost/make_shared.hpp>
#include <geometry_msgs/TwistStamped.h>

#include <utility>

#include "ppp_core/error.hpp"
#include "ppp_msgs/graph_names.h"
#include "ppp_msgs/hand_over.h"

namespace ppp {
namespace planners {
namespace {

/// Scans and poses kept to find a request's by its stamp.
constexpr std::size_t kKept = 16;

/// The newest message of `messages` stamped exactly `stamp`, or null.
template <class Message>
typename Message::ConstPtr stampedAt(const std::deque<typename Message::ConstPtr>& messages, const ros::Time& stamp) {
  for (auto it = messages.rbegin(); it != messages.rend(); ++it) {
    if ((*it)->header.stamp == stamp) return *it;
  }
  return nullptr;
}

/// Keeps `message` among the newest kKept of `messages`.
template <class Message>
void keep(std::deque<Message>* messages, Message message) {
  messages->push_back(std::move(message));
  if (messages->size() > kKept) messages->pop_front();
}

}  // namespace

VelocityPlannerLink::VelocityPlannerLink(ros::NodeHandle& nh, const PlannerFrames& frames, double control_period,
                                         bool in_network_thread, Answer answer)
    : frames_(frames),
      control_period_(control_period),
      answer_(std::move(answer)),
      queue_(in_network_thread) {
  namespace names = ppp_msgs::topics;
  command_ = nh.advertise<geometry_msgs::TwistStamped>(names::kPlannerCommand, 10);
  status_ = nh.advertise<actionlib_msgs::GoalStatus>(names::kPlannerStatus, 10);
  scan_ = ppp_msgs::subscribeLockstep<sensor_msgs::LaserScan>(
      nh, names::kPlannerScan, 10, [this](const sensor_msgs::LaserScan::ConstPtr& m) { onScan(m); }, queue_.get());
  odom_ = ppp_msgs::subscribeLockstep<nav_msgs::Odometry>(
      nh, names::kPlannerOdom, 10, [this](const nav_msgs::Odometry::ConstPtr& m) { onOdom(m); }, queue_.get());
  map_ = ppp_msgs::subscribeLockstep<nav_msgs::OccupancyGrid>(
      nh, names::kPlannerMap, 2, [this](const nav_msgs::OccupancyGrid::ConstPtr& m) { onMap(m); }, queue_.get());
  goal_ = ppp_msgs::subscribeLockstep<geometry_msgs::PoseStamped>(
      nh, names::kPlannerGoal, 10, [this](const geometry_msgs::PoseStamped::ConstPtr& m) { onGoal(m); },
      queue_.get());
}

std::string VelocityPlannerLink::topics() const {
  return scan_.getTopic() + ", " + odom_.getTopic() + ", " + map_.getTopic() + ", " + goal_.getTopic() + " -> " +
         command_.getTopic();
}

void VelocityPlannerLink::onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
  std::lock_guard<std::mutex> lock(mutex_);
  keep(&scans_, scan);
  continuous() ? drive() : serve();
}

void VelocityPlannerLink::onOdom(const nav_msgs::Odometry::ConstPtr& odom) {
  std::lock_guard<std::mutex> lock(mutex_);
  keep(&poses_, odom);
  continuous() ? drive() : serve();
}

void VelocityPlannerLink::onMap(const nav_msgs::OccupancyGrid::ConstPtr& map) {
  std::lock_guard<std::mutex> lock(mutex_);
  map_message_ = map;
  continuous() ? drive() : serve();
}

void VelocityPlannerLink::onGoal(const geometry_msgs::PoseStamped::ConstPtr& goal) {
  if (goal->header.frame_id != frames_.map_frame) {
    ROS_WARN("a goal in frame '%s', expected '%s': not answered", goal->header.frame_id.c_str(),
             frames_.map_frame.c_str());
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (continuous()) {
    goal_pose_ = goal;  // the episode's goal; the periods' scans and poses ask
    drive();
  } else {
    pending_ = goal;
    serve();
  }
}

void VelocityPlannerLink::serve() {
  if (!pending_ || !map_message_ || map_message_->header.stamp < pending_->header.stamp) return;
  const ros::Time stamp = pending_->header.stamp;
  if (stamp <= answered_) {  // a request asked again (the bridge thought this node restarted): answered already
    pending_ = nullptr;
    return;
  }
  const sensor_msgs::LaserScan::ConstPtr scan = stampedAt<sensor_msgs::LaserScan>(scans_, stamp);
  const nav_msgs::Odometry::ConstPtr pose = stampedAt<nav_msgs::Odometry>(poses_, stamp);
  if (!scan || !pose) return;
  const geometry_msgs::PoseStamped goal = *pending_;
  pending_ = nullptr;
  if (pose->header.frame_id != frames_.map_frame || pose->child_frame_id != frames_.base_frame) {
    ROS_WARN("odometry of frame '%s' in frame '%s', expected '%s' in '%s': not answered", pose->child_frame_id.c_str(),
             pose->header.frame_id.c_str(), frames_.base_frame.c_str(), frames_.map_frame.c_str());
    return;
  }
  answered_ = stamp;
  respond(stamp, *scan, *pose, goal);
}

void VelocityPlannerLink::drive() {
  if (!goal_pose_ || !map_message_ || scans_.empty()) return;
  const ros::Time stamp = scans_.back()->header.stamp;
  if (stamp <= answered_) return;
  const nav_msgs::Odometry::ConstPtr pose = stampedAt<nav_msgs::Odometry>(poses_, stamp);
  if (!pose) return;
  // Each topic has a connection of its own, read in no set order. A period one control period after the last one
  // answered continues its episode, whose goal and map are in. Any other begins an episode: its goal and map
  // (which says that it begins one) are the ones stamped with it, not whichever came last.
  const bool continues = answered_ > ros::Time() && stamp - answered_ < control_period_ * 1.5 &&
                         goal_pose_->header.stamp <= stamp && map_message_->header.stamp <= stamp;
  if (!continues && (goal_pose_->header.stamp != stamp || map_message_->header.stamp != stamp)) return;
  answered_ = stamp;
  respond(stamp, *scans_.back(), *pose, *goal_pose_);
}

void VelocityPlannerLink::respond(const ros::Time& stamp, const sensor_msgs::LaserScan& scan,
                                  const nav_msgs::Odometry& pose, const geometry_msgs::PoseStamped& goal) {
  const bool new_episode = map_message_->info.map_load_time != episode_;
  episode_ = map_message_->info.map_load_time;
  // A new message per answer, published by pointer: a bridge in the same manager gets this very object.
  auto command = boost::make_shared<geometry_msgs::TwistStamped>();
  command->header.stamp = stamp;
  command->header.frame_id = frames_.base_frame;
  try {
    command->twist = answer_(VelocityRequest{scan, pose, goal, *map_message_, new_episode});
  } catch (const GoalAbandoned& e) {
    auto status = boost::make_shared<actionlib_msgs::GoalStatus>();
    status->goal_id.stamp = stamp;
    status->status = actionlib_msgs::GoalStatus::ABORTED;
    status->text = e.what();
    ppp_msgs::publishHandingOver(status_, status);
    return;
  } catch (const Error& e) {
    ROS_ERROR_THROTTLE(5, "the robot stays: %s", e.what());
  }
  ppp_msgs::publishHandingOver(command_, command);
}

}  // namespace planners
}  // namespace ppp
