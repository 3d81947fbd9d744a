#include "recorded_messages.hpp"

#include <ros/time.h>

#include <string>

namespace ppp {
namespace simulator {

namespace {

visualization_msgs::Marker cellMarker(const MapFrame& frame, Cell cell, int id, float r, float g, float b,
                                      const std::string& ns) {
  visualization_msgs::Marker m;
  m.header.frame_id = "map";
  m.header.stamp = ros::Time::now();
  m.ns = ns;
  m.id = id;
  m.type = visualization_msgs::Marker::CUBE;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.position.x = frame.centreX(cell);
  m.pose.position.y = frame.centreY(cell);
  m.pose.position.z = 0.1 * frame.resolution;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = 0.8 * frame.resolution;
  m.scale.z = 0.2 * frame.resolution;
  m.color.r = r;
  m.color.g = g;
  m.color.b = b;
  m.color.a = 1.0;
  return m;
}

}  // namespace

visualization_msgs::MarkerArray startAndGoalMarkers(const MapFrame& frame, const Problem& problem) {
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(cellMarker(frame, problem.start, 0, 0.1f, 0.8f, 0.1f, "start"));
  markers.markers.push_back(cellMarker(frame, problem.goal, 1, 0.9f, 0.1f, 0.1f, "goal"));
  return markers;
}

ppp_msgs::EpisodeResult resultMessage(const agents::EpisodeResult& r) {
  ppp_msgs::EpisodeResult m;
  m.set = r.set;
  m.problem = r.problem;
  m.agent = r.agent;
  m.run = static_cast<std::uint32_t>(r.run);
  m.seed = r.seed;
  m.passed = r.passed;
  m.steps = static_cast<std::uint32_t>(r.steps);
  m.bumps = static_cast<std::uint32_t>(r.bumps);
  m.path_length = r.path_length;
  m.optimal_length = r.optimal_length;
  m.reason = r.reason;
  return m;
}

}  // namespace simulator
}  // namespace ppp
