// planner_bridge_node: plays an agent of type planner with an external ROS planner, one episode at a time
// (docs/reference/planner-interface.md). Start it in the agent's namespace (ns="NAME"), the planner in NAME/robot.
//   simulator side  subscribes scans (ppp_msgs/ScanBatch)   publishes moves (ppp_msgs/MoveBatch)
//   planner side    publishes robot/map (nav_msgs/OccupancyGrid, latched), robot/odom (nav_msgs/Odometry),
//                   robot/scan (sensor_msgs/LaserScan), robot/move_base_simple/goal (geometry_msgs/PoseStamped)
//                   and tf map_frame -> base_frame; subscribes robot/plan (nav_msgs/Path)
//   parameters      ~name (default: the namespace's last component), ~memory ("KxK" or "full"),
//                   ~sensor_noise (logged; the simulator applies it), ~resolution (metres per cell, 1),
//                   ~plan_timeout (s, 5), ~connect_timeout (s, 20), ~map_frame ("map"),
//                   ~base_frame (default "<namespace>/robot/base_link")
// Exits with an error naming the topics when no planner connects within ~connect_timeout.
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
    bridge.serve();
    ros::spin();
  } catch (const ppp::Error& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  return 0;
}
