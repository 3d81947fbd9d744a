#pragma once

// The zoo planner: the optimistic example planner (optimistic_planner_node.hpp) with one classic fault planted
// (planted_faults.hpp), for measuring how well a hunt finds a planner's fault (scripts/bench-hunt.sh). Topics and
// frames as the optimistic planner's; besides them
//   parameters  ~fault (required), ~limit: docs/reference/options.md#example-planner-nodes
// It runs as a process of its own (zoo_planner_node) or as the nodelet ppp_agents/ZooPlanner.

#include <ros/ros.h>

#include <memory>
#include <string>

#include "planner_node.hpp"
#include "planted_faults.hpp"

namespace ppp {
namespace planners {

class ZooPlannerNode {
 public:
  /// @throws InvalidArgument naming a bad parameter.
  ZooPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::string& node_name,
                 bool in_network_thread);

 private:
  ZooPlannerNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh, const std::shared_ptr<FaultyPlanner>& planner,
                 bool in_network_thread);

  PlannerNode node_;
};

}  // namespace planners
}  // namespace ppp
