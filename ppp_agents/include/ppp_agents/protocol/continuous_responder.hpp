#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_agents/protocol/continuous_codec.hpp"

namespace ppp {
namespace protocol {

/// The agent side of the continuous-motion batch protocol (agent_node): answers sensing batches with one
/// ContinuousAgent per episode, message -> ppp types -> agent -> message. An episode is started by its
/// ContinuousStart and finished when a batch no longer holds it; agents are reused, so a long experiment makes only
/// a batch's worth. A malformed batch, start or episode is answered with the failure invalid_command (the episode
/// ends there); each kind of fault is logged once. Never throws on input.
class ContinuousResponder {
 public:
  /// Agents of one configuration. @throws InvalidArgument naming "motion" for an agent that moves only on the grid.
  explicit ContinuousResponder(const agents::AgentConfig& config);
  /// One command per episode of `batch`, in order, with the batch number, agent name and episode/step echoed; the
  /// header stamp is left for the caller.
  ppp_msgs::CommandBatch answer(const ppp_msgs::SensingBatch& batch);
  /// Episodes currently hosted.
  std::size_t active() const { return episodes_.size(); }
  /// Episodes rejected so far, per kind of fault (the field at fault: "ranges", "start", "episode", ...).
  const std::map<std::string, long>& rejections() const { return rejections_; }

 private:
  struct Episode {
    std::uint32_t id = 0;
    std::unique_ptr<agents::ContinuousAgent> agent;
    std::unique_ptr<Grid> prior_map;  // what the agent's start points at
    std::uint32_t round = 0;          // the last batch that held the episode
  };
  void start(const ppp_msgs::ContinuousStart& message);
  std::vector<Episode>::iterator firstNotBefore(std::uint32_t id);
  Episode* find(std::uint32_t id);
  BodyVelocity command(const ppp_msgs::SensingBatch& batch, std::size_t i);
  void reject(ppp_msgs::CommandBatch* commands, std::size_t i, const std::string& kind, const std::string& what);
  void finishAbsent();

  agents::AgentConfig config_;
  // Sorted by id: the simulator sends each batch in id order, so the next episode is normally the one after the
  // last found (a walk instead of a search per step).
  std::vector<Episode> episodes_;
  std::size_t next_ = 0;  // where find() looks first
  std::vector<std::unique_ptr<agents::ContinuousAgent>> idle_;
  std::unordered_map<std::uint32_t, InvalidArgument> failed_starts_;  // this batch's rejected starts
  std::vector<float> ranges_;  // the episode's scan being answered
  std::uint32_t round_ = 0;
  std::map<std::string, long> rejections_;
};

}  // namespace protocol
}  // namespace ppp
