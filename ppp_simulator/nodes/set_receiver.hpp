#pragma once

#include <vector>

#include <ros/ros.h>

#include "ppp_msgs/ProblemSet.h"
#include "ppp_simulator/experiment_config.hpp"
#include "ppp_simulator/experiment_runner.hpp"
#include "lane_runner.hpp"
#include "simulator_parameters.hpp"

namespace ppp {
namespace simulator {

/// An experiment's sets ready to play, with the messages recorded for them.
struct ReceivedSets {
  std::vector<agents::PreparedSet> sets;                  ///< In the config's order.
  std::vector<ppp_msgs::ProblemSet> messages;     ///< One per set: what its generator node published.
};

/// Takes every evolved set of `config` from its generator node (setTopic(name)), serving ~evaluate (on
/// `services_nh`) for hunting generators meanwhile, and reads the sets given as directories from disk. Waits as long
/// as each set's generator node runs; a topic without a publisher for ~set_timeout seconds is an error naming the
/// node. Returns an empty `sets` when the node stops first. @throws IoError, ParseError, InvalidArgument.
ReceivedSets receiveSets(ros::NodeHandle& nh, ros::NodeHandle& services_nh, const ExperimentConfig& config,
                         const SimulatorParameters& parameters, const NodeControl& control);

}  // namespace simulator
}  // namespace ppp
