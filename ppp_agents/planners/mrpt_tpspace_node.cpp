#include "mrpt_tpspace_node.hpp"

#include <cmath>

#include "planner_node_parameters.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_file.hpp"

namespace ppp {
namespace planners {

namespace {

constexpr std::size_t kMaxConfigBytes = 1 << 20;

/// The configuration file ~config names, or the shipped one.
std::string configPath(const TpSpaceNodeParameters& parameters) {
  return parameters.config.empty() ? std::string(PPP_TPSPACE_DEFAULT_CONFIG) : parameters.config;
}

/// The text of the configuration at `path`. @throws InvalidArgument naming config when it cannot be read.
std::string configText(const std::string& path) {
  try {
    return readTextFile(path, kMaxConfigBytes);
  } catch (const IoError& e) {
    throw InvalidArgument("config", e.what());
  }
}

}  // namespace

TpSpaceNode::TpSpaceNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& /*node_name*/,
                         bool in_network_thread)
    : parameters_(readTpSpaceNodeParameters(private_nh)),
      config_path_(configPath(parameters_)),
      navigator_(configText(config_path_), config_path_,
                 TpSpaceRobot{parameters_.bodyRadius(), parameters_.max_linear_speed, parameters_.max_angular_speed}),
      link_(nh, readPlannerFrames(private_nh, nh.getNamespace()), readPlannerPeriod(private_nh).control_period,
            in_network_thread,
            [this](const VelocityRequest& request) { return command(request); }) {
  ROS_INFO("MRPT TP-space navigator (%s, a body of %g m): %s", config_path_.c_str(), parameters_.bodyRadius(),
           link_.topics().c_str());
}

geometry_msgs::Twist TpSpaceNode::command(const VelocityRequest& request) {
  const geometry_msgs::Pose& pose = request.pose.pose.pose;
  const geometry_msgs::Point& goal = request.goal.pose.position;
  if (!std::isfinite(goal.x) || !std::isfinite(goal.y)) throw InvalidArgument("goal", "a goal that is not finite");
  const auto& twist = request.pose.twist.twist;
  const double heading = 2 * std::atan2(pose.orientation.z, pose.orientation.w);
  TpSpaceSensing sensing{0, Pose2D{pose.position.x, pose.position.y, heading},
                         BodyVelocity{twist.linear.x, twist.linear.y, twist.angular.z},
                         laserReturns(request.scan.ranges, request.scan.angle_min, request.scan.angle_increment)};
  BodyVelocity command;
  try {  // MRPT failing to make or step its navigator ends the run as the navigator's own error does
    if (request.new_episode) {
      episode_start_ = request.scan.header.stamp;
      navigator_.start(MapPoint{goal.x, goal.y}, parameters_.target_allowed_distance);
    }
    sensing.time = (request.scan.header.stamp - episode_start_).toSec();
    command = navigator_.step(sensing);
  } catch (const Error& e) {
    throw GoalAbandoned(e.what());
  }
  const std::string error = navigator_.error();
  if (!error.empty()) throw GoalAbandoned("MRPT's navigator: " + error);
  geometry_msgs::Twist out;
  out.linear.x = command.forward;
  out.angular.z = command.turn;
  return out;
}

}  // namespace planners
}  // namespace ppp
