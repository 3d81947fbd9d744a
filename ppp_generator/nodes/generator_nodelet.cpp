// The nodelet ppp_generator/Generator: the generator node (generator_node.hpp) in a nodelet manager; with
// ~exit_when_done it shuts the manager down once its set is published (a hunt's graph ends with its set).
#include <pluginlib/class_list_macros.hpp>

#include "generator_node.hpp"
#include "ppp_msgs/job_nodelet_of.h"

namespace ppp {
namespace generator {

class GeneratorNodelet : public ppp_msgs::JobNodeletOf<GeneratorNode> {};

}  // namespace generator
}  // namespace ppp

PLUGINLIB_EXPORT_CLASS(ppp::generator::GeneratorNodelet, nodelet::Nodelet)
