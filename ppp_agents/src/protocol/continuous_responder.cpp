#include "ppp_agents/protocol/continuous_responder.hpp"

#include <ros/console.h>

#include <algorithm>
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
  // The answer is written in place, a command of zeros until the episode's agent gives its own.
  ppp_msgs::CommandBatch commands;
  commands.agent = config_.name;
  commands.batch = batch.batch;
  commands.episodes = batch.episodes;
  commands.steps.resize(n);
  std::copy_n(batch.steps.begin(), std::min(n, batch.steps.size()), commands.steps.begin());
  commands.forward.resize(n);
  commands.left.resize(n);
  commands.turn.resize(n);
  std::string what;
  const std::string fault = checkSensingBatch(batch, &what);
  if (!fault.empty()) {
    for (std::size_t i = 0; i < n; ++i) reject(&commands, i, fault, what);
    finishAbsent();
    return commands;
  }
  failed_starts_.clear();
  for (const ppp_msgs::ContinuousStart& s : batch.starts) {
    try {
      start(s);
    } catch (const InvalidArgument& e) {
      failed_starts_.emplace(s.episode, e);  // rejected with the episode's sensing
    }
  }
  next_ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    try {
      const BodyVelocity command = this->command(batch, i);
      commands.forward[i] = command.forward;
      commands.left[i] = command.left;
      commands.turn[i] = command.turn;
    } catch (const InvalidArgument& e) {
      reject(&commands, i, e.name(), e.what());
    } catch (const std::exception& e) {
      reject(&commands, i, "agent", e.what());
    }
  }
  finishAbsent();
  return commands;
}

std::vector<ContinuousResponder::Episode>::iterator ContinuousResponder::firstNotBefore(std::uint32_t id) {
  return std::lower_bound(episodes_.begin(), episodes_.end(), id,
                          [](const Episode& e, std::uint32_t key) { return e.id < key; });
}

ContinuousResponder::Episode* ContinuousResponder::find(std::uint32_t id) {
  if (next_ < episodes_.size() && episodes_[next_].id == id) return &episodes_[next_++];
  const auto it = firstNotBefore(id);
  if (it == episodes_.end() || it->id != id) return nullptr;
  next_ = static_cast<std::size_t>(it - episodes_.begin()) + 1;
  return &*it;
}

void ContinuousResponder::start(const ppp_msgs::ContinuousStart& message) {
  auto it = firstNotBefore(message.episode);
  if (it != episodes_.end() && it->id == message.episode) it = episodes_.erase(it);  // a restarted id: over
  DecodedStart decoded = decodeContinuousStart(message);
  Episode episode;
  episode.id = message.episode;
  if (idle_.empty()) {
    episode.agent = agents::makeContinuousAgent(config_);
  } else {
    episode.agent = std::move(idle_.back());
    idle_.pop_back();
  }
  episode.prior_map = std::move(decoded.prior_map);
  episode.agent->start(decoded.start);
  episodes_.insert(it, std::move(episode));  // new ids are the largest: normally an append
}

BodyVelocity ContinuousResponder::command(const ppp_msgs::SensingBatch& batch, std::size_t i) {
  const std::uint32_t id = batch.episodes[i];
  if (!failed_starts_.empty()) {
    const auto failed = failed_starts_.find(id);
    if (failed != failed_starts_.end()) throw failed->second;
  }
  Episode* episode = find(id);
  if (episode == nullptr) {
    throw InvalidArgument("episode", "episode " + std::to_string(id) + " at step " + std::to_string(batch.steps[i]) +
                                         " was never started (no ContinuousStart)");
  }
  if (episode->round == round_) {
    throw InvalidArgument("duplicate", "episode " + std::to_string(id) + " is twice in one batch");
  }
  episode->round = round_;
  const auto first = batch.ranges.begin() + static_cast<std::ptrdiff_t>(i * batch.laser_beams);
  ranges_.assign(first, first + batch.laser_beams);
  const agents::ContinuousSensing sensing{Pose2D{batch.x[i], batch.y[i], batch.theta[i]},
                                          BodyVelocity{batch.forward[i], batch.left[i], batch.turn[i]}, batch.time[i],
                                          &ranges_};
  return episode->agent->command(sensing);
}

void ContinuousResponder::reject(ppp_msgs::CommandBatch* commands, std::size_t i, const std::string& kind,
                                 const std::string& what) {
  const std::uint32_t id = commands->episodes[i];
  ppp_msgs::EpisodeFailure failure;
  failure.episode = id;
  failure.reason = reason::kInvalidCommand;
  commands->failures.push_back(failure);
  if (kind != "duplicate") {  // the episode's run ends with this batch
    const auto it = firstNotBefore(id);
    if (it != episodes_.end() && it->id == id) it->round = 0;
  }
  if (rejections_[kind]++ == 0) {
    ROS_WARN("agent '%s': rejected the sensing of episode %u step %u (%s); answered invalid_command. Further "
             "'%s' faults are not logged.",
             config_.name.c_str(), id, commands->steps[i], what.c_str(), kind.c_str());
  }
}

void ContinuousResponder::finishAbsent() {
  // Episodes this batch held no (accepted) sensing of are over: their agents go back to the pool.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < episodes_.size(); ++i) {
    if (episodes_[i].round == round_) {
      if (kept != i) episodes_[kept] = std::move(episodes_[i]);
      ++kept;
    } else {
      idle_.push_back(std::move(episodes_[i].agent));
    }
  }
  episodes_.resize(kept);
}

}  // namespace protocol
}  // namespace ppp
