#include "ppp_agents/protocol/continuous_responder.hpp"

#include <ros/console.h>

#include <exception>
#include <utility>

#include "ppp_core/error.hpp"

namespace ppp {
namespace protocol {

ContinuousResponder::ContinuousResponder(const agents::AgentConfig& config) : config_(config) {
  idle_.push_back(agents::makeContinuousAgent(config));  // refuses an agent that moves only on the grid
}

ppp_msgs::CommandBatch ContinuousResponder::answer(const ppp_msgs::SensingBatch& batch) {
  ++round_;
  const std::size_t n = batch.episodes.size();
  std::vector<agents::ContinuousReply> replies(n);
  for (std::size_t i = 0; i < n; ++i) {
    replies[i].episode = batch.episodes[i];
    replies[i].step = i < batch.steps.size() ? static_cast<int>(batch.steps[i]) : 0;
  }
  std::string what;
  const std::string fault = checkSensingBatch(batch, &what);
  if (!fault.empty()) {
    for (agents::ContinuousReply& reply : replies) reject(&reply, fault, what);
  } else {
    failed_starts_.clear();
    for (const ppp_msgs::ContinuousStart& s : batch.starts) {
      try {
        start(s);
      } catch (const InvalidArgument& e) {
        failed_starts_.emplace(s.episode, e);  // rejected with the episode's sensing
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      try {
        replies[i].command = command(batch, i);
      } catch (const InvalidArgument& e) {
        reject(&replies[i], e.name(), e.what());
      } catch (const std::exception& e) {
        reject(&replies[i], "agent", e.what());
      }
    }
  }
  finishAbsent();
  return encodeCommands(config_.name, batch.batch, replies);
}

void ContinuousResponder::start(const ppp_msgs::ContinuousStart& message) {
  episodes_.erase(message.episode);  // a restarted id: its earlier episode is over (its agent is not reused)
  DecodedStart decoded = decodeContinuousStart(message);
  Episode episode;
  if (idle_.empty()) {
    episode.agent = agents::makeContinuousAgent(config_);
  } else {
    episode.agent = std::move(idle_.back());
    idle_.pop_back();
  }
  episode.prior_map = std::move(decoded.prior_map);
  episode.agent->start(decoded.start);
  episodes_[message.episode] = std::move(episode);
}

BodyVelocity ContinuousResponder::command(const ppp_msgs::SensingBatch& batch, std::size_t i) {
  const std::uint32_t id = batch.episodes[i];
  if (!failed_starts_.empty()) {
    const auto failed = failed_starts_.find(id);
    if (failed != failed_starts_.end()) throw failed->second;
  }
  const auto it = episodes_.find(id);
  if (it == episodes_.end()) {
    throw InvalidArgument("episode", "episode " + std::to_string(id) + " at step " + std::to_string(batch.steps[i]) +
                                         " was never started (no ContinuousStart)");
  }
  Episode& episode = it->second;
  if (episode.round == round_) {
    throw InvalidArgument("duplicate", "episode " + std::to_string(id) + " is twice in one batch");
  }
  episode.round = round_;
  const auto first = batch.ranges.begin() + static_cast<std::ptrdiff_t>(i * batch.laser_beams);
  ranges_.assign(first, first + batch.laser_beams);
  const agents::ContinuousSensing sensing{Pose2D{batch.x[i], batch.y[i], batch.theta[i]},
                                          BodyVelocity{batch.forward[i], batch.left[i], batch.turn[i]}, batch.time[i],
                                          &ranges_};
  return episode.agent->command(sensing);
}

void ContinuousResponder::reject(agents::ContinuousReply* reply, const std::string& kind, const std::string& what) {
  reply->failure = reason::kInvalidCommand;
  if (kind != "duplicate") episodes_.erase(reply->episode);  // its run ends with this batch
  if (rejections_[kind]++ == 0) {
    ROS_WARN("agent '%s': rejected the sensing of episode %u step %d (%s); answered invalid_command. Further "
             "'%s' faults are not logged.",
             config_.name.c_str(), reply->episode, reply->step, what.c_str(), kind.c_str());
  }
}

void ContinuousResponder::finishAbsent() {
  for (auto it = episodes_.begin(); it != episodes_.end();) {
    if (it->second.round == round_) {
      ++it;
    } else {
      idle_.push_back(std::move(it->second.agent));
      it = episodes_.erase(it);
    }
  }
}

}  // namespace protocol
}  // namespace ppp
