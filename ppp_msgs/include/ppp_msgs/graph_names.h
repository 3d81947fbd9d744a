#pragma once

#include <string>

// Every node, topic, service and frame name of PPP Lab's ROS graph, in one place (header-only, no ROS headers:
// the graph writer and the nodes share it).
namespace ppp_msgs {

namespace nodes {
constexpr const char* kSimulator = "simulator";        ///< The simulator node (/simulator).
constexpr const char* kManager = "nodelet_manager";    ///< The experiment's nodelet manager (/nodelet_manager).
constexpr const char* kShrink = "shrink";              ///< The shrink node of launch/shrink.launch (/shrink).
constexpr const char* kCheck = "check";                ///< The check node of launch/check.launch (/check).
constexpr const char* kGeneratorPrefix = "gen_";       ///< + set name: the generator node of an experiment's set.
constexpr const char* kGenerator = "generator";        ///< A generator node started on its own (generate.launch).
constexpr const char* kBridge = "bridge";              ///< A planner agent's bridge, in the agent's namespace.
constexpr const char* kPlanner = "planner";            ///< A planner agent's planner, in /NAME/robot.
}  // namespace nodes

namespace frames {
constexpr const char* kMap = "map";              ///< The fixed frame of maps, poses, goals and plans.
constexpr const char* kOdom = "odom";            ///< A robot's odometry frame in continuous motion (NAME/robot/odom).
constexpr const char* kBaseLink = "base_link";   ///< A robot's frame, under its namespace (NAME/robot/base_link).

/// `frame` under the namespace `ns` as tf names it, without leading slashes
/// ("/ompl/robot" -> "ompl/robot/base_link", "/" -> "base_link").
inline std::string under(const std::string& ns, const char* frame) {
  const std::size_t first = ns.find_first_not_of('/');
  return first == std::string::npos ? frame : ns.substr(first) + "/" + frame;
}
}  // namespace frames

namespace topics {

// An agent's namespace /NAME (NAME = ppp::agents::agentGraphName of the agent's name).
constexpr const char* kScans = "scans";  ///< ppp_msgs/ScanBatch, simulator -> agent node or planner bridge.
constexpr const char* kMoves = "moves";  ///< ppp_msgs/MoveBatch, agent node or planner bridge -> simulator.
constexpr const char* kSensing = "sensing";    ///< ppp_msgs/SensingBatch (continuous motion), simulator -> agent.
constexpr const char* kCommands = "commands";  ///< ppp_msgs/CommandBatch (continuous motion), agent -> simulator.
constexpr const char* kPath = "path";    ///< nav_msgs/Path of a recorded episode (simulator).
constexpr const char* kScan = "scan";    ///< sensor_msgs/LaserScan of a recorded episode (simulator).

// The planner interface, relative to the planner's namespace /NAME/robot (docs/reference/planner-interface.md).
constexpr const char* kRobotNamespace = "robot";           ///< The planner's namespace inside the agent's.
constexpr const char* kPlannerMap = "map";                 ///< nav_msgs/OccupancyGrid, bridge -> planner.
constexpr const char* kPlannerOdom = "odom";               ///< nav_msgs/Odometry, bridge -> planner.
constexpr const char* kPlannerScan = "scan";               ///< sensor_msgs/LaserScan, bridge -> planner.
constexpr const char* kPlannerGoal = "move_base_simple/goal";  ///< geometry_msgs/PoseStamped, bridge -> planner.
constexpr const char* kPlannerPath = "plan";               ///< nav_msgs/Path, planner -> bridge.
constexpr const char* kPlannerCommand = "cmd_vel";         ///< geometry_msgs/TwistStamped, local planner -> bridge.
/// actionlib_msgs/GoalStatus, local planner -> bridge: ABORTED instead of a command when it gives up.
constexpr const char* kPlannerStatus = "planner_status";
constexpr const char* kPlannerRobotRadius = "robot_radius";  ///< Parameter: the robot's radius in metres.
constexpr const char* kPlannerFootprint = "footprint";       ///< Parameter: its footprint polygon, [[x, y], ...].
/// rosgraph_msgs/Clock, bridge -> planner in continuous motion: the episode's simulated time (the planner's /clock
/// remapped here, with /use_sim_time set).
constexpr const char* kPlannerClock = "clock";

// A generator node (private names once remapped to ~, as the experiment's graph does).
constexpr const char* kProblemSet = "problem_set";  ///< ppp_msgs/ProblemSet (latched).
constexpr const char* kMap = "map";                 ///< nav_msgs/OccupancyGrid of one PPP (latched).
constexpr const char* kGenerate = "generate";       ///< ppp_msgs/Generate service (private).

// The simulator node.
constexpr const char* kEvaluate = "evaluate";                       ///< ppp_msgs/EvaluateProblems service (private).
constexpr const char* kEvaluator = "/simulator/evaluate";           ///< ...its full name, as hunting generators call it.
constexpr const char* kRecordedMap = "/map";                        ///< The recorded episode's map (latched).
constexpr const char* kMarkers = "/ppp/markers";                    ///< Start and goal markers (latched).
constexpr const char* kResults = "/ppp/results";                    ///< ppp_msgs/EpisodeResults as runs end.
constexpr const char* kSetsPrefix = "/ppp/sets/";                   ///< + set name: the played ppp_msgs/ProblemSet.

/// `/<graph_name>/<topic>`: a topic in an agent's (or node's) namespace.
inline std::string under(const std::string& graph_name, const char* topic) { return "/" + graph_name + "/" + topic; }

}  // namespace topics
}  // namespace ppp_msgs
