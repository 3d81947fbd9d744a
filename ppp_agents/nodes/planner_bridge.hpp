#pragma once

#include <ros/ros.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "nav_msgs/Path.h"
#include "planner_bridge_parameters.hpp"
#include "planner_link.hpp"
#include "ppp_agents/planner_episode.hpp"
#include "ppp_msgs/MoveBatch.h"
#include "ppp_msgs/ScanBatch.h"

namespace ppp {
namespace agents {

/// Plays one agent of type planner: for each step of the simulator's episode (ScanBatch of one scan) it
/// publishes the robot's world to an external planner (map, odom, tf, scan, goal; docs/planner-interface.md)
/// and turns the planner's nav_msgs/Path into the step's move, or into a failure with its reason.
class PlannerBridge {
 public:
  /// Advertises and subscribes in `nh`'s namespace: scans/moves towards the simulator, robot/... towards the
  /// planner (PlannerLink).
  PlannerBridge(ros::NodeHandle& nh, const BridgeParameters& parameters);
  /// Waits up to connect_timeout for the planner (PlannerLink::waitForPlanner). @throws InvalidArgument.
  void waitForPlanner() { link_.waitForPlanner(); }
  /// The planner-side topic names, for the log.
  std::string plannerTopics() const { return link_.topics(); }

 private:
  /// What a step produced: a move, or a failure reason for the simulator.
  struct StepOutcome {
    std::uint8_t action = 0;
    const char* failure = nullptr;  // a reason:: constant, or nullptr for a move
  };
  void onScans(const ppp_msgs::ScanBatch::ConstPtr& batch);
  void start(const ppp_msgs::EpisodeStart& start);
  StepOutcome step(const ppp_msgs::ScanBatch& batch);
  /// True when `path` is a usable answer for the robot at `robot`, or an empty or wrong-frame one (also final).
  bool answers(const nav_msgs::Path& path, Cell robot) const;
  void warnOnce(const std::string& kind, const std::string& text);

  BridgeParameters parameters_;
  PlannerLink link_;
  ros::Publisher moves_;
  ros::Subscriber scans_;

  // The episode being played.
  bool active_ = false;
  std::uint32_t episode_id_ = 0;
  PlannerEpisode episode_;
  std::vector<MapPoint> following_;  // the poses of the path the robot follows (a lockstep answer may keep it)
  Cell previous_{-1, -1};            // the robot's cell at the previous step (none at the first)

  std::map<std::string, long> warnings_;
};

}  // namespace agents
}  // namespace ppp
