#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "ppp_agents/agent_host.hpp"
#include "ppp_agents/protocol/batch_codec.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace protocol {

/// The action sent for a scan the agent cannot use (malformed, or of an episode never started); not an Action,
/// so the simulator fails that episode as invalid_action.
constexpr std::uint8_t kRejectedAction = 255;

/// The agent side of the batch protocol (agent_node): answers scan batches with an AgentHost, message -> ppp types
/// -> agents -> message. An episode is started by
/// its EpisodeStart and finished when a batch no longer holds it. A malformed scan is answered with
/// kRejectedAction (and its episode dropped); each kind of fault is logged once. Never throws on input.
class BatchResponder {
 public:
  /// Agents of one configuration. @throws InvalidArgument for a bad configuration.
  explicit BatchResponder(const agents::AgentConfig& config);
  /// One move per scan of `batch`, in order, with the batch number, agent name and episode/step echoed; the
  /// header stamp is left for the caller.
  ppp_msgs::MoveBatch answer(const ppp_msgs::ScanBatch& batch);
  /// Episodes currently hosted.
  std::size_t active() const { return episodes_.size(); }
  /// Scans rejected so far, per kind of fault (the field at fault: "cells", "prior_map", "episode", ...).
  const std::map<std::string, long>& rejections() const { return rejections_; }

 private:
  struct Episode {
    std::uint32_t id;
    int width;
    int height;
    Cell goal;
    agents::Agent* agent;  // owned by host_
    std::uint32_t round;  // the last batch that held the episode's scan
    bool rejected;        // a scan of it was rejected: it ends with this batch
  };
  void start(std::uint32_t id, const EpisodeStart& start);
  std::vector<Episode>::iterator firstNotBefore(std::uint32_t id);  // in episodes_, by id
  Episode* find(std::uint32_t id);
  std::uint8_t act(const ppp_msgs::ScanBatch& batch, std::size_t i);
  void reject(std::uint32_t episode, std::uint32_t step, const std::string& kind, const std::string& what);
  void finishAbsent();

  agents::AgentConfig config_;
  bool reads_window_;
  agents::AgentHost host_;
  // Sorted by id, contiguous: the simulator sends each batch in id order, so the next scan's episode is
  // normally the one after the last found (a cache-friendly walk instead of a hash probe per step).
  std::vector<Episode> episodes_;
  std::size_t next_ = 0;  // where find() looks first
  std::unordered_map<std::uint32_t, InvalidArgument> failed_starts_;  // this batch's rejected starts
  std::vector<std::int8_t> unknown_window_;  // what an agent that reads no window is given
  std::uint32_t round_ = 0;
  std::map<std::string, long> rejections_;
};

}  // namespace protocol
}  // namespace ppp
