// The nodelet ppp_simulator/Simulator: the simulator node (simulator_node.hpp) in a nodelet manager, taking the
// agents' replies from the manager's threads; when its experiment is finished it shuts the manager down.
#include <pluginlib/class_list_macros.hpp>

#include "ppp_msgs/job_nodelet_of.h"
#include "simulator_node.hpp"

namespace ppp {
namespace simulator {

class SimulatorNodelet : public ppp_msgs::JobNodeletOf<SimulatorNode> {};

}  // namespace simulator
}  // namespace ppp

PLUGINLIB_EXPORT_CLASS(ppp::simulator::SimulatorNodelet, nodelet::Nodelet)
