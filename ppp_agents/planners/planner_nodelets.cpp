// The example planners as nodelets (planner_nodelet_plugins.xml): each the node class its executable runs, in a
// nodelet manager, planning in the thread of a bridge of the same manager that asked.
#include <pluginlib/class_list_macros.hpp>

#include "dwa_planner_node.hpp"
#include "echo_planner_node.hpp"
#include "mrpt_planner_node.hpp"
#include "mrpt_reactive_node.hpp"
#include "ompl_planner_node.hpp"
#include "optimistic_planner_node.hpp"
#include "ppp_msgs/nodelet_of.h"
#include "zoo_planner_node.hpp"

namespace ppp {
namespace planners {

class OptimisticPlannerNodelet : public ppp_msgs::NodeletOf<OptimisticPlannerNode> {};
class OmplPlannerNodelet : public ppp_msgs::NodeletOf<OmplPlannerNode> {};
class MrptPlannerNodelet : public ppp_msgs::NodeletOf<MrptPlannerNode> {};
class MrptReactiveNodelet : public ppp_msgs::NodeletOf<ReactiveNode> {};
class DwaPlannerNodelet : public ppp_msgs::NodeletOf<DwaPlannerNode> {};
class ZooPlannerNodelet : public ppp_msgs::NodeletOf<ZooPlannerNode> {};
class EchoPlannerNodelet : public ppp_msgs::NodeletOf<EchoPlannerNode> {};

}  // namespace planners
}  // namespace ppp

PLUGINLIB_EXPORT_CLASS(ppp::planners::OptimisticPlannerNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(ppp::planners::OmplPlannerNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(ppp::planners::MrptPlannerNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(ppp::planners::MrptReactiveNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(ppp::planners::DwaPlannerNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(ppp::planners::ZooPlannerNodelet, nodelet::Nodelet)
PLUGINLIB_EXPORT_CLASS(ppp::planners::EchoPlannerNodelet, nodelet::Nodelet)
