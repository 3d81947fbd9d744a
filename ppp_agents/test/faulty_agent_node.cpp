// faulty_agent_node: a misbehaving agent node for the simulator's fault tests (built only with tests).
//   subscribes  scans (ppp_msgs/ScanBatch)    publishes  moves (ppp_msgs/MoveBatch)
//   parameters  ~mode   silent      never answers
//                       garbage     answers every scan with action 200 and the wrong step number
//                       stop_after  answers like the random agent for ~steps batches, then never again
//               ~steps  batches answered in stop_after mode (required there, >= 0)
//               ~name   agent name in the answers (default: the node's name)
#include <ros/ros.h>

#include <memory>
#include <string>

#include "agent_node_parameters.hpp"
#include "ppp_agents/protocol/batch_responder.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace agents {

/// The ways the node misbehaves.
enum class FaultMode { Silent, Garbage, StopAfter };

/// Answers scan batches wrongly, or not at all, as its mode says.
class FaultyAgentNode {
 public:
  /// Reads ~mode, ~steps and ~name. @throws InvalidArgument naming the parameter.
  FaultyAgentNode(ros::NodeHandle& nh, const ros::NodeHandle& private_nh) {
    std::string mode;
    if (!private_nh.getParam("mode", mode)) {
      throw InvalidArgument("~mode", "required: silent, garbage or stop_after");
    }
    name_ = baseName(ros::this_node::getName());
    if (private_nh.hasParam("name") && !private_nh.getParam("name", name_)) {
      throw InvalidArgument("~name", "expected a string");
    }
    if (mode == "silent") {
      mode_ = FaultMode::Silent;
    } else if (mode == "garbage") {
      mode_ = FaultMode::Garbage;
    } else if (mode == "stop_after") {
      mode_ = FaultMode::StopAfter;
      if (!private_nh.getParam("steps", steps_) || steps_ < 0) {
        throw InvalidArgument("~steps", "required in stop_after mode: batches to answer (an integer >= 0)");
      }
      AgentConfig config;
      config.name = name_;
      config.type = "random";
      responder_ = std::make_unique<protocol::BatchResponder>(config);
    } else {
      throw InvalidArgument("~mode", "unknown mode '" + mode + "'; valid: silent, garbage, stop_after");
    }
    moves_ = nh.advertise<ppp_msgs::MoveBatch>("moves", 10);
    scans_ = nh.subscribe("scans", 10, &FaultyAgentNode::onScans, this, ros::TransportHints().tcpNoDelay());
    ROS_INFO("faulty agent '%s': mode %s on %s", name_.c_str(), mode.c_str(), scans_.getTopic().c_str());
  }

 private:
  void onScans(const ppp_msgs::ScanBatch::ConstPtr& batch) {
    ppp_msgs::MoveBatch moves;
    switch (mode_) {
      case FaultMode::Silent:
        return;
      case FaultMode::Garbage:
        moves.agent = name_;
        moves.batch = batch->batch;
        moves.episodes = batch->episodes;
        for (std::uint32_t step : batch->steps) moves.steps.push_back(step + 1);
        moves.actions.assign(batch->episodes.size(), 200);
        break;
      case FaultMode::StopAfter:
        if (answered_ >= steps_) return;
        ++answered_;
        moves = responder_->answer(*batch);
        break;
    }
    moves.header.stamp = ros::Time::now();
    moves_.publish(moves);
  }

  FaultMode mode_ = FaultMode::Silent;
  std::string name_;
  int steps_ = 0;
  int answered_ = 0;
  std::unique_ptr<protocol::BatchResponder> responder_;
  ros::Publisher moves_;
  ros::Subscriber scans_;
};

}  // namespace agents
}  // namespace ppp

int main(int argc, char** argv) {
  ros::init(argc, argv, "faulty_agent");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    ppp::agents::FaultyAgentNode node(nh, private_nh);
    ros::spin();
  } catch (const ppp::Error& e) {
    ROS_FATAL("%s", e.what());
    return 1;
  }
  return 0;
}
