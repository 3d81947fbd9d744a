#include "episode_recorder.hpp"
#include "recorded_messages.hpp"
#include "ppp_msgs/graph_names.h"

#include <algorithm>
#include <array>
#include <filesystem>

#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>
#include <visualization_msgs/MarkerArray.h>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/map_frame.hpp"
#include "ppp_core/window_mask.hpp"
#include "ppp_msgs/conversions.h"

namespace ppp {
namespace simulator {

namespace {

constexpr double kSecondsPerStep = 0.1;     // bag time of one recorded step
constexpr int kPathEveryStep = 10;          // a recorded path is written every this many steps (and at step 0)
constexpr std::size_t kResultsPerMessage = 1000;  // results grouped in one /ppp/results message at most
constexpr double kResultsPeriod = 0.2;            // seconds a result may wait for its group

}  // namespace

EpisodeRecorder::EpisodeRecorder(ros::NodeHandle& nh, const SimulatorParameters& parameters,
                                 const std::vector<agents::PreparedSet>& sets, const std::vector<std::string>& agent_names,
                                 int action_limit, double continuous_seconds)
    : parameters_(parameters),
      sets_(sets),
      slot_seconds_(std::max((action_limit + 10) * kSecondsPerStep, continuous_seconds + 1)) {
  map_publisher_ = nh.advertise<nav_msgs::OccupancyGrid>(ppp_msgs::topics::kRecordedMap, 1, true);
  markers_publisher_ = nh.advertise<visualization_msgs::MarkerArray>(ppp_msgs::topics::kMarkers, 1, true);
  results_publisher_ = nh.advertise<ppp_msgs::EpisodeResults>(ppp_msgs::topics::kResults, 100);
  for (const agents::PreparedSet& set : sets) {
    set_publishers_[set.name] = nh.advertise<ppp_msgs::ProblemSet>(ppp_msgs::topics::kSetsPrefix + set.name, 1, true);
  }
  for (const std::string& agent : agent_names) {
    const std::string graph_name = agents::agentGraphName(agent);
    path_publishers_[agent] = nh.advertise<nav_msgs::Path>(ppp_msgs::topics::under(graph_name, ppp_msgs::topics::kPath), 10, true);
    scan_publishers_[agent] = nh.advertise<sensor_msgs::LaserScan>(ppp_msgs::topics::under(graph_name, ppp_msgs::topics::kScan), 10);
  }
  bag_start_ = ros::Time::now();
  latest_stamp_ = bag_start_;
  if (parameters.record) {
    const std::string path = (std::filesystem::path(parameters.output_dir) / "experiment.bag").string();
    try {
      bag_.open(path, rosbag::bagmode::Write);
    } catch (const rosbag::BagException& e) {
      throw IoError(path, std::string("cannot write the bag: ") + e.what());
    }
    bag_open_ = true;
  }
}

template <typename M>
void EpisodeRecorder::write(const std::string& topic, const ros::Time& time, const M& message, bool latched) {
  if (!bag_open_) return;
  latest_stamp_ = std::max(latest_stamp_, time);
  if (!latched) {
    bag_.write(topic, time, message);
    return;
  }
  // A latching connection header, so that `rosbag play` latches the topic again for late subscribers (rviz).
  auto header = boost::make_shared<ros::M_string>();
  (*header)["type"] = ros::message_traits::datatype<M>();
  (*header)["md5sum"] = ros::message_traits::md5sum<M>();
  (*header)["message_definition"] = ros::message_traits::definition<M>();
  (*header)["callerid"] = ros::this_node::getName();
  (*header)["latching"] = "1";
  bag_.write(topic, time, message, header);
}

bool EpisodeRecorder::sampled(int problem, int run) const {
  return run < parameters_.record_runs && problem < parameters_.record_problems;
}

ros::Time EpisodeRecorder::slotTime(int slot, int step) const {
  return bag_start_ + ros::Duration(slot * slot_seconds_ + step * kSecondsPerStep);
}

void EpisodeRecorder::recordSets(const std::vector<ppp_msgs::ProblemSet>& sets) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& set : sets) {
    set_publishers_.at(set.name).publish(set);
    write("/ppp/sets/" + set.name, bag_start_, set, true);
  }
}

const EpisodeRecorder::Recording* EpisodeRecorder::recordingOf(const std::string& agent, std::uint32_t episode,
                                                                int set_index, int problem_index, int run,
                                                                bool starting) {
  // One recorded episode per agent at a time; sampled episodes starting meanwhile are not drawn.
  Recording& recording = recordings_[agent];
  const agents::PreparedSet& set = sets_[set_index];
  if (starting && recording.done) {
    recording = Recording{episode, set.name, set.set.ids[problem_index], run, slots_used_[agent]++, false};
  } else if (recording.done || recording.episode != episode) {
    return nullptr;
  }
  if (!starting) return &recording;
  const Problem& problem = set.set.problems[problem_index];
  const MapFrame frame{problem.width, problem.height, parameters_.resolution};
  const ros::Time stamp = slotTime(recording.slot, 0);
  if (recording.slot >= maps_written_) {
    // The first agent to start a slot publishes its map; every agent's slot runs on the same PPP.
    nav_msgs::OccupancyGrid map = ppp_msgs::toOccupancyGrid(set.grids[problem_index], parameters_.resolution);
    map.header.stamp = stamp;
    const visualization_msgs::MarkerArray markers = startAndGoalMarkers(frame, problem);
    map_publisher_.publish(map);
    markers_publisher_.publish(markers);
    write("/map", stamp, map, true);
    write("/ppp/markers", stamp, markers, true);
    maps_written_ = recording.slot + 1;
  }
  paths_[agent] = nav_msgs::Path();
  paths_[agent].header.frame_id = "map";
  return &recording;
}

void EpisodeRecorder::recordPose(const std::string& agent, geometry_msgs::TransformStamped transform, int step) {
  const ros::Time stamp = transform.header.stamp;
  transform.header.stamp = ros::Time::now();
  broadcaster_.sendTransform(transform);
  transform.header.stamp = stamp;
  tf2_msgs::TFMessage tf;
  tf.transforms.push_back(transform);
  write("/tf", stamp, tf);

  nav_msgs::Path& path = paths_[agent];
  geometry_msgs::PoseStamped pose;
  pose.header = transform.header;
  pose.pose.position.x = transform.transform.translation.x;
  pose.pose.position.y = transform.transform.translation.y;
  pose.pose.orientation = transform.transform.rotation;
  path.header.stamp = stamp;
  path.poses.push_back(pose);
  if (step % kPathEveryStep == 0) {
    path_publishers_.at(agent).publish(path);
    write("/" + agents::agentGraphName(agent) + "/path", stamp, path);
  }
}

void EpisodeRecorder::recordLaser(const std::string& agent, const sensor_msgs::LaserScan& laser) {
  scan_publishers_.at(agent).publish(laser);
  write("/" + agents::agentGraphName(agent) + "/scan", laser.header.stamp, laser);
}

void EpisodeRecorder::recordScan(const std::string& agent, const protocol::ScanRequest& s) {
  if (!sampled(s.problem, s.run)) return;  // most scans: they go by without the lock every lane shares
  std::lock_guard<std::mutex> lock(mutex_);
  const Recording* recording = recordingOf(agent, s.episode, s.set, s.problem, s.run, s.start.has_value());
  if (recording == nullptr) return;
  const Problem& problem = sets_[s.set].set.problems[s.problem];
  const MapFrame frame{problem.width, problem.height, parameters_.resolution};
  const std::string base_link = agents::agentGraphName(agent) + "/base_link";
  geometry_msgs::TransformStamped transform = ppp_msgs::cellTransform(frame, s.position, "map", base_link);
  transform.header.stamp = slotTime(recording->slot, s.step);
  recordPose(agent, transform, s.step);

  if (!s.window) return;  // an agent that reads no window (random) is sent none: no scan to show
  std::array<std::int8_t, kMaxScanCells> cells;
  unpackWindow(s.free_cells.data(), s.obstacle_cells.data(), s.range, cells.data());
  sensor_msgs::LaserScan laser = ppp_msgs::toLaserScan(cells.data(), s.range, parameters_.resolution, base_link);
  laser.header.stamp = transform.header.stamp;
  recordLaser(agent, laser);
}

void EpisodeRecorder::recordSensing(const std::string& agent, const agents::ContinuousRequest& s) {
  if (!sampled(s.problem, s.run)) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const Recording* recording = recordingOf(agent, s.episode, s.set, s.problem, s.run, s.start.has_value());
  if (recording == nullptr) return;
  if (s.start) beams_[agent] = s.start->beams;
  const std::string base_link = agents::agentGraphName(agent) + "/base_link";
  geometry_msgs::TransformStamped transform = ppp_msgs::poseTransform(s.pose, "map", base_link);
  transform.header.stamp = slotTime(recording->slot, 0) + ros::Duration(s.time);
  recordPose(agent, transform, s.step);
  if (s.ranges.empty()) return;  // an agent that reads no laser (astar) is cast none
  sensor_msgs::LaserScan laser = ppp_msgs::toLaserScan(s.ranges, beams_.at(agent), base_link);
  laser.header.stamp = transform.header.stamp;
  recordLaser(agent, laser);
}

void EpisodeRecorder::recordResults(const std::vector<agents::EpisodeResult>& results) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const agents::EpisodeResult& r : results) {
    // The recorded episode of this agent ended: write its whole path and free the agent for the next one.
    const auto recording = recordings_.find(r.agent);
    if (recording != recordings_.end() && !recording->second.done && recording->second.set == r.set &&
        recording->second.problem == r.problem && recording->second.run == r.run) {
      recording->second.done = true;
      const nav_msgs::Path& path = paths_[r.agent];
      path_publishers_.at(r.agent).publish(path);
      write("/" + agents::agentGraphName(r.agent) + "/path", path.header.stamp, path);
    }
    pending_results_.results.push_back(resultMessage(r));
  }
  if (pending_results_.results.size() >= kResultsPerMessage ||
      (ros::WallTime::now() - last_results_flush_).toSec() >= kResultsPeriod) {
    flushResults();
  }
}

void EpisodeRecorder::flushResults() {
  last_results_flush_ = ros::WallTime::now();
  if (pending_results_.results.empty()) return;
  pending_results_.header.stamp = ros::Time::now();
  results_publisher_.publish(pending_results_);
  // Stamped with the latest bag time so far: results follow the recorded episodes, and the bag's last chunk
  // ends at its latest time (`rosbag info` takes the bag's end from its last chunk).
  write("/ppp/results", latest_stamp_, pending_results_);
  pending_results_.results.clear();
}

void EpisodeRecorder::close() {
  std::lock_guard<std::mutex> lock(mutex_);
  flushResults();
  if (bag_open_) bag_.close();
  bag_open_ = false;
}

}  // namespace simulator
}  // namespace ppp
