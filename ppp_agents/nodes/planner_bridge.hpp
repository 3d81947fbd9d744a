#pragma once

#include <ros/ros.h>
#include <ros/callback_queue.h>
#include <tf2_ros/transform_broadcaster.h>

#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "nav_msgs/Path.h"
#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/planner_episode.hpp"
#include "ppp_msgs/MoveBatch.h"
#include "ppp_msgs/ScanBatch.h"

namespace ppp {
namespace agents {

/// The planner bridge's `~` parameters.
struct BridgeParameters {
  AgentConfig config;           ///< Agent name and memory handicap (type planner).
  double resolution = 1.0;      ///< Metres per cell of the published map.
  double plan_timeout = 5.0;    ///< Seconds the planner has to answer a plan request.
  double connect_timeout = 20.0;  ///< Seconds to wait at start-up for the planner's topics.
  std::string map_frame = "map";  ///< Frame of the map, poses and goal.
  std::string base_frame;       ///< The robot's frame (tf child, odom child, scan frame).
};

/// Reads and checks the bridge's parameters; `ns` is the node's namespace (default name and base frame).
/// @throws InvalidArgument naming the parameter.
BridgeParameters readBridgeParameters(const ros::NodeHandle& private_nh, const std::string& ns);

/// Plays one agent of type planner: for each step of the simulator's episode (ScanBatch of one scan) it
/// publishes the robot's world to an external planner (map, odom, tf, scan, goal; docs/planner-interface.md)
/// and turns the planner's nav_msgs/Path into the step's move, or into a failure with its reason.
class PlannerBridge {
 public:
  /// Advertises and subscribes in `nh`'s namespace: scans/moves towards the simulator, robot/... towards the
  /// planner. Paths are taken on a callback queue of their own, so a step can wait for one.
  PlannerBridge(ros::NodeHandle& nh, const BridgeParameters& parameters);
  ~PlannerBridge();
  /// Waits up to connect_timeout for the planner to subscribe to the goal and publish the plan topic.
  /// @throws InvalidArgument naming each topic that is missing or has the wrong type.
  void waitForPlanner();
  /// The planner-side topic names, for the log.
  std::string plannerTopics() const;

 private:
  /// What a step produced: a move, or a failure reason for the simulator.
  struct StepOutcome {
    std::uint8_t action = 0;
    std::string failure;  // "" for a move
  };
  void onScans(const ppp_msgs::ScanBatch::ConstPtr& batch);
  void onPlan(const nav_msgs::Path::ConstPtr& path);
  void start(const ppp_msgs::EpisodeStart& start);
  StepOutcome step(const ppp_msgs::ScanBatch& batch);
  void publishState(const ros::Time& stamp, Cell robot, const std::int8_t* window, int range);
  void publishGoal(const ros::Time& stamp);
  /// Waits for a path answering a request made at `stamp` (re-sending the request every second).
  std::optional<nav_msgs::Path> waitForPath(ros::Time stamp, Cell robot, const std::int8_t* window, int range);
  /// True when `path` is a usable answer for the robot at `robot`, or an empty or wrong-frame one (also final).
  bool answers(const nav_msgs::Path& path, Cell robot) const;
  /// Turns a path's poses into map points; "" or what is wrong with its frame.
  std::string pathPoints(const nav_msgs::Path& path, std::vector<MapPoint>* points) const;
  bool plannerConnected() const { return plan_.getNumPublishers() > 0; }
  /// True when the planner that answered in this episode is gone: disconnected, or its process dead
  /// (asked over XML-RPC at most every 0.2 s).
  bool plannerGone();
  void warnOnce(const std::string& kind, const std::string& text);

  BridgeParameters parameters_;
  ros::NodeHandle planner_nh_;         // robot/..., its plan subscription on plan_queue_
  ros::CallbackQueue plan_queue_;
  ros::AsyncSpinner plan_spinner_;
  ros::Publisher moves_, map_, odom_, scan_, goal_;
  ros::Subscriber scans_, plan_;
  tf2_ros::TransformBroadcaster tf_;

  // The episode being played.
  bool active_ = false;
  std::uint32_t episode_id_ = 0;
  PlannerEpisode episode_;
  bool planner_answered_ = false;  // the planner sent a path during this episode
  ros::WallTime next_probe_;       // when plannerGone() may ask the planner's process again

  // Paths from the planner (written on the plan queue's thread).
  std::mutex path_mutex_;
  std::condition_variable path_arrived_;
  std::optional<nav_msgs::Path> latest_path_;
  std::uint64_t paths_received_ = 0;
  std::uint64_t paths_used_ = 0;

  std::map<std::string, long> warnings_;
};

}  // namespace agents
}  // namespace ppp
