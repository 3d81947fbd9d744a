#pragma once

#include <ros/ros.h>

#include <array>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "nav_msgs/Path.h"
#include "planner_bridge_parameters.hpp"
#include "planner_link.hpp"
#include "ppp_agents/planner_episode.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_msgs/MoveBatch.h"
#include "ppp_msgs/ScanBatch.h"
#include "ppp_msgs/lockstep_queue.h"

namespace ppp {
namespace agents {

/// Plays one agent of type planner: for each step of the simulator's episode (ScanBatch of one scan) it
/// publishes the robot's world to an external planner (map, odom, tf, scan, goal; docs/reference/planner-interface.md)
/// and turns the planner's nav_msgs/Path (or, from a local planner, its velocity command) into the step's move, or
/// into a failure with its reason.
/// In a process of its own (`in_network_thread`), a step that needs no plan request is answered in roscpp's network
/// thread as its scan is read; a plan request is handed to a worker thread, which waits for the planner's path (read
/// in the network thread) and answers. As a nodelet, each step is played where its scan arrives: in the thread of
/// a simulator of the same manager (ppp_msgs/lockstep_queue.h), where a planner nodelet of the manager answers the
/// request before its publish returns, so a step wakes no thread.
class PlannerBridge {
 public:
  /// Advertises and subscribes the planner's topics robot/... in `nh`'s namespace (PlannerLink).
  PlannerBridge(ros::NodeHandle& nh, const BridgeParameters& parameters, bool in_network_thread);
  /// Stops the worker.
  ~PlannerBridge();
  /// Waits up to connect_timeout for the planner (PlannerLink::waitForPlanner): false when stopped.
  /// @throws InvalidArgument.
  bool waitForPlanner() { return link_.waitForPlanner(); }
  /// Ends waitForPlanner() and any wait for the planner's answer: the node is going.
  void stop() { link_.stop(); }
  /// Once the planner is there: connects to the simulator in `nh`'s namespace (scans in, moves out), which
  /// waits for both topics before it plays this agent, so no step waits on a planner that is not there yet.
  void serve(ros::NodeHandle& nh);
  /// The planner-side topic names, for the log.
  std::string plannerTopics() const { return link_.topics(); }
  /// The link to the planner (which the continuous-motion bridge shares).
  PlannerLink* link() { return &link_; }

 private:
  /// What a step produced: a move, or a failure reason for the simulator.
  struct StepOutcome {
    std::uint8_t action = 0;
    const char* failure = nullptr;  // a reason:: constant, or nullptr for a move
    const char* diagnosis = nullptr;  // for no_path: diagnosis::kMissedRoute or kNoRoute
  };
  /// The state a plan request is made for.
  struct Request {
    Cell robot;
    int range = 0;
    std::array<std::int8_t, kMaxScanCells> cells;  // the window, which the planner's LaserScan shows too
    ros::Time stamp;
  };
  void onScans(const ppp_msgs::ScanBatch::ConstPtr& batch);
  /// Plays a batch (mutex_ held): answers it, or hands its plan request to the worker.
  void play(const ppp_msgs::ScanBatch::ConstPtr& batch);
  /// Publishes the moves for `batch`: its first scan's `outcome`, every other scan (all of them without one)
  /// rejected.
  void reply(const ppp_msgs::ScanBatch& batch, const StepOutcome* outcome);
  /// The worker thread: asks the planner for each step handed over, and replies.
  void askPlanner();
  void start(const ppp_msgs::EpisodeStart& start);
  /// The step's outcome, or nothing when it is a plan request (request_ then holds its state).
  std::optional<StepOutcome> step(const ppp_msgs::ScanBatch& batch);
  /// Asks the planner for request_'s state and waits for the answer.
  StepOutcome request();
  /// Judges a path answering request_.
  StepOutcome followPath(const nav_msgs::Path& path);
  /// Judges a velocity command answering request_.
  StepOutcome takeCommand(const geometry_msgs::TwistStamped& command);
  /// Ends the episode as failed for `reason`.
  StepOutcome fail(const char* reason, const std::string& detail);
  /// True when `path` is a usable answer for the robot at `robot`, or an empty or wrong-frame one (also final).
  bool answers(const nav_msgs::Path& path, Cell robot) const;
  void warnOnce(const std::string& kind, const std::string& text);

  BridgeParameters parameters_;
  PlannerLink link_;
  ros::Publisher moves_;

  // Hand-over of plan requests between the network thread and the worker. While asking_ is set only the worker
  // touches the episode; scans that arrive meanwhile wait in order for the worker.
  std::mutex mutex_;
  std::condition_variable work_;
  ppp_msgs::ScanBatch::ConstPtr asking_;
  std::deque<ppp_msgs::ScanBatch::ConstPtr> waiting_;
  bool stopping_ = false;
  Request request_;
  std::thread worker_;  // a process of its own's
  ppp_msgs::LockstepQueue scans_queue_;
  ros::Subscriber scans_;  // after scans_queue_: unsubscribes before the queue goes

  // The episode being played.
  bool active_ = false;
  std::uint32_t episode_id_ = 0;
  ros::Time episode_stamp_;  // the stamp of the episode's first step (zero before it)
  PlannerEpisode episode_;
  // The planner's last answer: the poses of the path the robot follows (a lockstep answer may keep it), or the
  // velocity command as one point.
  std::vector<MapPoint> following_;

  std::map<std::string, long> warnings_;
};

}  // namespace agents
}  // namespace ppp
