#pragma once

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/transform_broadcaster.h>

#include "ppp_msgs/EpisodeResults.h"
#include "ppp_msgs/ProblemSet.h"
#include "ppp_agents/agent_lane.hpp"
#include "ppp_agents/continuous/continuous_lane.hpp"
#include "simulator_parameters.hpp"

namespace ppp {
namespace simulator {

/// Publishes what standard ROS tools understand about a sample of episodes (the map, tf map -> G/base_link,
/// G/path, G/scan as sensor_msgs/LaserScan, start/goal markers; G = the agent's graph name) and every result on
/// /ppp/results (grouped: one ppp_msgs/EpisodeResults per 1,000 results or 0.2 s, whichever comes first,
/// so a million results are not a million bag writes), and writes all of it to
/// <output_dir>/experiment.bag. In the bag, step k of a recorded episode
/// is stamped 0.1 s * k after the start of that episode's slot, and every agent's n-th recorded episode shares
/// slot n (they all run on the same PPP), so `rosbag play` shows the agents moving side by side on their map.
/// Thread-safe: every lane thread reports to it.
class EpisodeRecorder {
 public:
  /// Opens the bag (when recording) and advertises the topics; `action_limit` is the most actions of a grid episode,
  /// `continuous_seconds` the longest budget of a continuous one. @throws IoError when the bag cannot be opened.
  EpisodeRecorder(ros::NodeHandle& nh, const SimulatorParameters& parameters, const std::vector<agents::PreparedSet>& sets,
                  const std::vector<std::string>& agent_names, int action_limit, double continuous_seconds = 0);
  /// Publishes and records the PPP sets (latched /ppp/sets/<name>).
  void recordSets(const std::vector<ppp_msgs::ProblemSet>& sets);
  /// Publishes and records a scan sent to `agent`, if its episode is sampled.
  void recordScan(const std::string& agent, const protocol::ScanRequest& scan);
  /// Publishes and records the pose (with its heading) and laser of a continuous episode of `agent` in one
  /// control period, if its episode is sampled; its steps are stamped by its simulated time.
  void recordSensing(const std::string& agent, const agents::ContinuousRequest& sensing);
  /// Publishes and records finished episodes (grouped with those of the last moments).
  void recordResults(const std::vector<agents::EpisodeResult>& results);
  /// Publishes and records the results still grouped, then closes the bag.
  void close();

 private:
  /// The episode an agent is being recorded in.
  struct Recording {
    std::uint32_t episode = 0;
    std::string set;
    std::string problem;
    int run = 0;
    int slot = 0;
    bool done = true;
  };
  bool sampled(int problem, int run) const;
  /// The recording `agent`'s step of episode `episode` (run `run` of PPP `problem` of set `set`) belongs to,
  /// started at the episode's first step (`starting`), or null when the step is not recorded; writes the map and
  /// markers of a new slot. Called with mutex_ held.
  const Recording* recordingOf(const std::string& agent, std::uint32_t episode, int set, int problem, int run,
                               bool starting);
  /// Sends and records `transform` (map -> the agent's base_link, stamped) and appends it to the agent's path,
  /// writing the path every kPathEveryStep-th `step`.
  void recordPose(const std::string& agent, geometry_msgs::TransformStamped transform, int step);
  /// Publishes and records a scan of `agent`.
  void recordLaser(const std::string& agent, const sensor_msgs::LaserScan& laser);
  ros::Time slotTime(int slot, int step) const;
  void flushResults();
  template <typename M>
  void write(const std::string& topic, const ros::Time& time, const M& message, bool latched = false);

  SimulatorParameters parameters_;
  const std::vector<agents::PreparedSet>& sets_;
  std::mutex mutex_;
  rosbag::Bag bag_;
  bool bag_open_ = false;
  ros::Publisher map_publisher_;
  ros::Publisher markers_publisher_;
  ros::Publisher results_publisher_;
  std::map<std::string, ros::Publisher> set_publishers_;
  std::map<std::string, ros::Publisher> path_publishers_;
  std::map<std::string, ros::Publisher> scan_publishers_;
  std::map<std::string, nav_msgs::Path> paths_;
  std::map<std::string, Recording> recordings_;    // per agent: the episode being (or last) recorded
  std::map<std::string, LaserBeams> beams_;        // per agent in continuous motion: its laser's beams
  std::map<std::string, int> slots_used_;          // per agent: recorded episodes started so far
  int maps_written_ = 0;                           // slots whose map is in the bag
  double slot_seconds_;  // bag time of a slot: the longest episode, grid (0.1 s an action) or continuous
  ros::Time bag_start_;
  ros::Time latest_stamp_;  // the latest time written to the bag
  ppp_msgs::EpisodeResults pending_results_;  // not yet published
  ros::WallTime last_results_flush_;
  tf2_ros::TransformBroadcaster broadcaster_;
};

}  // namespace simulator
}  // namespace ppp
