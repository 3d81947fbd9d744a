#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>

#include "ppp_agents/agent_host.hpp"
#include "ppp_msgs/MoveBatch.h"
#include "ppp_msgs/ScanBatch.h"

namespace ppp {
namespace agents {

/// The action sent for a scan the agent cannot use (malformed, or of an episode never started); not an Action,
/// so the simulator fails that episode as invalid_action.
constexpr std::uint8_t kRejectedAction = 255;

/// Answers scan batches with an AgentHost: message -> ppp types -> agents -> message. An episode is started by
/// its step-0 scan and finished when a batch no longer holds it. A malformed scan is answered with
/// kRejectedAction (and its episode dropped); each kind of fault is logged once. Never throws on input.
class BatchResponder {
 public:
  /// Agents of one configuration. @throws InvalidArgument for a bad configuration.
  explicit BatchResponder(const AgentConfig& config);
  /// One move per scan of `batch`, in order, with the batch number, agent name and episode/step echoed; the
  /// header stamp is left for the caller.
  ppp_msgs::MoveBatch answer(const ppp_msgs::ScanBatch& batch);
  /// Episodes currently hosted.
  std::size_t active() const { return episodes_.size(); }
  /// Scans rejected so far, per kind of fault (the field at fault: "cells", "prior_map", "episode", ...).
  const std::map<std::string, long>& rejections() const { return rejections_; }

 private:
  struct Episode {
    int width;
    int height;
    std::uint32_t round;  // the last batch that held the episode
  };
  std::uint8_t act(const ppp_msgs::EpisodeScan& scan);
  void start(const ppp_msgs::EpisodeScan& scan);
  void reject(const ppp_msgs::EpisodeScan& scan, const std::string& kind, const std::string& what);

  AgentConfig config_;
  AgentHost host_;
  std::unordered_map<std::uint32_t, Episode> episodes_;
  std::uint32_t round_ = 0;
  std::map<std::string, long> rejections_;
};

}  // namespace agents
}  // namespace ppp
