#pragma once

#include <ros/node_handle.h>

#include <string>

#include "planner_node_options.hpp"

namespace ppp {
namespace planners {

/// Reads ~map_frame and ~base_frame (default defaultBaseFrame(node_namespace)) from their declarations.
/// @throws InvalidArgument naming the parameter when it is not a non-empty tf frame name (no leading slash).
PlannerFrames readPlannerFrames(const ros::NodeHandle& private_nh, const std::string& node_namespace);

/// Reads ~inflation from its declaration. @throws InvalidArgument naming the parameter and what was expected.
PlannerBody readPlannerBody(const ros::NodeHandle& private_nh);

/// A local planner's `~control_period`. @throws InvalidArgument naming it when it is out of range.
PlannerPeriod readPlannerPeriod(const ros::NodeHandle& private_nh);

/// Reads the OMPL planner node's declared parameters (omplNodeOptionSpecs()).
/// @throws InvalidArgument naming the parameter and what was expected.
OmplNodeParameters readOmplNodeParameters(const ros::NodeHandle& private_nh);

/// Reads the MRPT planner node's declared parameters (mrptNodeOptionSpecs()).
/// @throws InvalidArgument naming the parameter and what was expected.
MrptNodeParameters readMrptNodeParameters(const ros::NodeHandle& private_nh);

/// Reads the MRPT reactive navigator node's declared parameters (reactiveNodeOptionSpecs()).
/// @throws InvalidArgument naming the parameter and what was expected.
ReactiveNodeParameters readReactiveNodeParameters(const ros::NodeHandle& private_nh);

/// The DWA example node's `~` parameters besides its frames. @throws InvalidArgument naming a bad one.
DwaNodeParameters readDwaNodeParameters(const ros::NodeHandle& private_nh);

/// The TP-space example node's `~` parameters besides its frames. @throws InvalidArgument naming a bad one.
TpSpaceNodeParameters readTpSpaceNodeParameters(const ros::NodeHandle& private_nh);

/// The zoo planner node's `~` parameters besides its frames. @throws InvalidArgument naming a bad one.
ZooNodeParameters readZooNodeParameters(const ros::NodeHandle& private_nh);

}  // namespace planners
}  // namespace ppp
