#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ppp_agents/continuous/continuous_lane.hpp"
#include "ppp_msgs/CommandBatch.h"
#include "ppp_msgs/ContinuousStart.h"
#include "ppp_msgs/SensingBatch.h"

namespace ppp {
namespace protocol {

// The continuous-motion batch protocol's messages (ppp_msgs/SensingBatch, ppp_msgs/CommandBatch), the
// counterpart of batch_codec.hpp: what the simulator's ContinuousLane sends (encodeSensing) and the agent side reads
// (checkSensingBatch, decodeContinuousStart), what the agent side answers (encodeCommands) and the simulator reads
// (decodeCommands). Poses, velocities and the robot's limits cross as float64, so an agent reads exactly the
// values of the in-process runner.

/// A ContinuousStart as the message that starts episode `episode`.
ppp_msgs::ContinuousStart toStartMessage(std::uint32_t episode, const agents::ContinuousStart& start);

/// A start message as the agent side keeps it: the start, whose prior_map (astar only) points at `prior_map`.
struct DecodedStart {
  agents::ContinuousStart start;
  std::unique_ptr<Grid> prior_map;
};

/// Reads a start message. @throws InvalidArgument naming the field at fault ("size", "resolution", "start",
/// "goal", "robot_radius", "kinematics", a limit, "control_period", "laser_beams", "prior_map").
DecodedStart decodeContinuousStart(const ppp_msgs::ContinuousStart& message);

/// Writes a lane's requests into `message` (its header, agent and batch are left to the caller): a start message
/// for each episode that begins, and the ranges of every request when the first one has any.
void encodeSensing(std::vector<agents::ContinuousRequest>& requests, ppp_msgs::SensingBatch* message);

/// Checks that a batch's per-episode arrays agree in length and it holds laser_beams ranges per episode. Returns
/// the field at fault ("batch", "ranges") and sets `what`, or returns "" when the batch is well formed.
std::string checkSensingBatch(const ppp_msgs::SensingBatch& batch, std::string* what);

/// The answer to batch number `batch` of agent `agent`: one command per reply, in order, and the episodes given up.
ppp_msgs::CommandBatch encodeCommands(const std::string& agent, std::uint32_t batch,
                                      const std::vector<agents::ContinuousReply>& replies);

/// What a CommandBatch says, for the simulator's lane.
struct DecodedCommands {
  std::vector<agents::ContinuousReply> replies;      ///< One per command of the batch, failures attached.
  const char* missing_reason = reason::kTimeout;  ///< Why an episode the batch does not answer fails.
  std::string fault;                              ///< What was wrong with the batch ("" when nothing was).
};

/// Reads an answer. A batch whose arrays differ in length answers nothing and fails every episode as
/// invalid_command; a failure reason an agent may not give is recorded as invalid_command. Never throws.
DecodedCommands decodeCommands(const ppp_msgs::CommandBatch& message);

}  // namespace protocol
}  // namespace ppp
