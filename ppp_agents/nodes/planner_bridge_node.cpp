// planner_bridge_node: plays an agent of type planner with an external ROS planner, one episode at a time
// (docs/reference/planner-interface.md). Start it in the agent's namespace (ns="NAME"), the planner in NAME/robot.
//   simulator side  subscribes scans (ppp_msgs/ScanBatch)   publishes moves (ppp_msgs/MoveBatch)
//   planner side    publishes robot/map (nav_msgs/OccupancyGrid, latched), robot/odom (nav_msgs/Odometry),
//                   robot/scan (sensor_msgs/LaserScan), robot/move_base_simple/goal (geometry_msgs/PoseStamped)
//                   and tf map_frame -> base_frame; subscribes robot/plan (nav_msgs/Path)
//   parameters      ~name (default: the namespace's last component), ~memory, ~sensor_noise (the simulator
//                   applies it) and the bridge's own (~plan_timeout, ~lockstep, ~connect_timeout, ~map_frame, ...):
//                   docs/reference/options.md#planner-bridge-node
// Exits with an error naming the topics when no planner connects within ~connect_timeout (default 20 s; the
// experiment's graph gives a planner the user starts by hand 300 s).
#include <ros/ros.h>

#include "planner_bridge.hpp"
#include "ppp_core/error.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "bridge");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    const ppp::agents::BridgeParameters parameters =
        ppp::agents::readBridgeParameters(private_nh, ros::this_node::getNamespace());
    ppp::agents::PlannerBridge bridge(nh, parameters);
    ROS_INFO("bridge '%s': waiting for a planner on %s", parameters.config.name.c_str(),
             bridge.plannerTopics().c_str());
    bridge.waitForPlanner();
    ROS_INFO("bridge '%s': planner connected", parameters.config.name.c_str());
    bridge.serve(nh);
    ros::spin();
  } catch (const ppp::Error& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  return 0;
}
