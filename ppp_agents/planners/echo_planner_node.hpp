#pragma once

// The echo planner: a local planner that answers every control period at once with a robot standing still, so
// what a benchmark of it measures is what the planner interface costs a period, none of a planner's own work
// (every run spends its whole budget). It reads and matches the period's messages as this repository's other local
// planners do (topics: velocity_planner_link.hpp). It runs as a process of its own (echo_planner_node) or as the
// nodelet ppp_agents/EchoPlanner.

#include <string>

#include "velocity_planner_link.hpp"

namespace ppp {
namespace planners {

/// Answers each request with a zero velocity.
class EchoPlannerNode {
 public:
  EchoPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
                  bool in_network_thread);

 private:
  VelocityPlannerLink link_;
};

}  // namespace planners
}  // namespace ppp
