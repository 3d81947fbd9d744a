#include "ppp_agents/protocol/batch_responder.hpp"

#include <ros/console.h>

#include <algorithm>
#include <array>
#include <exception>

#include "ppp_core/error.hpp"
#include "ppp_core/sensor.hpp"
#include "ppp_core/window_mask.hpp"

namespace ppp {
namespace protocol {

namespace {

constexpr std::size_t kPrefetchAhead = 2;  // scans between fetching an agent into cache and acting on it

}  // namespace

BatchResponder::BatchResponder(const agents::AgentConfig& config)
    : config_(config), reads_window_(agents::readsScanWindow(config)), host_(config) {}

ppp_msgs::MoveBatch BatchResponder::answer(const ppp_msgs::ScanBatch& batch) {
  ++round_;
  const std::size_t n = batch.episodes.size();
  // The answer is written in place: every scan's move starts as kRejectedAction until its agent acts.
  ppp_msgs::MoveBatch moves;
  moves.agent = config_.name;
  moves.batch = batch.batch;
  moves.episodes = batch.episodes;
  moves.steps.resize(n);
  std::copy_n(batch.steps.begin(), std::min(n, batch.steps.size()), moves.steps.begin());
  moves.actions.assign(n, kRejectedAction);
  std::string what;
  const std::string fault = checkScanBatch(batch, reads_window_, &what);
  if (!fault.empty()) {
    for (std::size_t i = 0; i < n; ++i) reject(moves.episodes[i], moves.steps[i], fault, what);
    finishAbsent();
    return moves;
  }
  failed_starts_.clear();
  for (const ppp_msgs::EpisodeStart& s : batch.starts) {
    try {
      start(s.episode, decodeEpisodeStart(s));
    } catch (const InvalidArgument& e) {
      failed_starts_.emplace(s.episode, e);  // rejected with the episode's scan
    }
  }
  if (!reads_window_) unknown_window_.assign(windowCells(batch.range), kScanUnknown);
  next_ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // Scans come in id order, so the agents acted on a few scans from now are known: their state is fetched
    // into cache meanwhile (a thousand agents' memories do not fit).
    if (next_ + 2 * kPrefetchAhead < episodes_.size()) __builtin_prefetch(episodes_[next_ + 2 * kPrefetchAhead].agent);
    if (next_ + kPrefetchAhead < episodes_.size() && i + kPrefetchAhead < n) {
      episodes_[next_ + kPrefetchAhead].agent->prefetch(toCell(batch.positions[i + kPrefetchAhead]));
    }
    try {
      moves.actions[i] = act(batch, i);
    } catch (const InvalidArgument& e) {
      reject(batch.episodes[i], batch.steps[i], e.name(), e.what());
    } catch (const std::exception& e) {
      reject(batch.episodes[i], batch.steps[i], "agent", e.what());
    }
  }
  finishAbsent();
  return moves;
}

std::vector<BatchResponder::Episode>::iterator BatchResponder::firstNotBefore(std::uint32_t id) {
  return std::lower_bound(episodes_.begin(), episodes_.end(), id,
                          [](const Episode& e, std::uint32_t key) { return e.id < key; });
}

BatchResponder::Episode* BatchResponder::find(std::uint32_t id) {
  if (next_ < episodes_.size() && episodes_[next_].id == id) return &episodes_[next_++];
  const auto it = firstNotBefore(id);
  if (it == episodes_.end() || it->id != id) return nullptr;
  next_ = static_cast<std::size_t>(it - episodes_.begin()) + 1;
  return &*it;
}

std::uint8_t BatchResponder::act(const ppp_msgs::ScanBatch& batch, std::size_t i) {
  const std::uint32_t id = batch.episodes[i];
  const std::uint32_t step = batch.steps[i];
  if (!failed_starts_.empty()) {
    const auto failed = failed_starts_.find(id);
    if (failed != failed_starts_.end()) throw failed->second;
  }
  Episode* episode = find(id);
  if (episode == nullptr || episode->rejected) {
    throw InvalidArgument("episode", "episode " + std::to_string(id) + " at step " + std::to_string(step) +
                                         " was never started (no EpisodeStart)");
  }
  if (episode->round == round_) {
    throw InvalidArgument("duplicate", "episode " + std::to_string(id) + " has two scans in one batch");
  }
  episode->round = round_;
  const Cell position = toCell(batch.positions[i]);
  requireOnGrid(position, episode->width, episode->height, "position");
  const bool bumped = batch.bumped[i] != 0;
  if (!reads_window_) {
    const Scan view(batch.range, unknown_window_.data(), unknown_window_.size(), position, episode->goal, bumped,
                    static_cast<int>(step));
    return static_cast<std::uint8_t>(episode->agent->act(view));
  }
  const int words = windowWords(batch.range);
  const std::uint64_t* free = batch.free_cells.data() + i * words;
  const std::uint64_t* obstacle = batch.obstacle_cells.data() + i * words;
  if (words == 1) {  // the agent reads the masks as they came, as it reads an atlas's in process
    const Scan view(batch.range, unpackWindow(*free, *obstacle), position, episode->goal, bumped,
                    static_cast<int>(step));
    return static_cast<std::uint8_t>(episode->agent->act(view));
  }
  std::array<std::int8_t, kMaxScanCells> cells;
  unpackWindow(free, obstacle, batch.range, cells.data());
  const Scan view(batch.range, cells.data(), windowCells(batch.range), position, episode->goal, bumped,
                  static_cast<int>(step));
  return static_cast<std::uint8_t>(episode->agent->act(view));
}

void BatchResponder::start(std::uint32_t id, const EpisodeStart& start) {
  const std::unique_ptr<Grid> prior = priorGrid(start);
  const auto it = firstNotBefore(id);
  agents::Agent* agent = nullptr;
  try {
    agent = &host_.start(id, episodeInfo(start, nullptr), prior.get());  // a restarted id: a fresh one
  } catch (const InvalidArgument&) {
    // The host ended the id's earlier episode, if any: its entry (and agent pointer) goes too.
    if (it != episodes_.end() && it->id == id) episodes_.erase(it);
    throw;
  }
  const Episode episode{id, start.width, start.height, start.goal, agent, 0, false};
  if (it != episodes_.end() && it->id == id) {
    *it = episode;
  } else {
    episodes_.insert(it, episode);  // new ids are the largest: normally an append
  }
}

void BatchResponder::finishAbsent() {
  // Episodes this batch held no (accepted) scan of are over.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < episodes_.size(); ++i) {
    const Episode& e = episodes_[i];
    if (e.round == round_ && !e.rejected) {
      // Copied only when an earlier one went: copying an entry onto itself stalls on its own overlapping stores.
      if (kept != i) episodes_[kept] = e;
      ++kept;
    } else {
      host_.finish(e.id);
    }
  }
  episodes_.resize(kept);
}

void BatchResponder::reject(std::uint32_t episode, std::uint32_t step, const std::string& kind,
                            const std::string& what) {
  // A duplicate scan leaves its episode alone: the first scan was answered. Otherwise the episode ends with
  // this batch (finishAbsent frees its agent).
  if (kind != "duplicate") {
    const auto it = firstNotBefore(episode);
    if (it != episodes_.end() && it->id == episode) it->rejected = true;
  }
  if (rejections_[kind]++ == 0) {
    ROS_WARN("agent '%s': rejected the scan of episode %u step %u (%s); answered with action %d, which is no "
             "move. Further '%s' faults are not logged.",
             config_.name.c_str(), episode, step, what.c_str(), kRejectedAction, kind.c_str());
  }
}

}  // namespace protocol
}  // namespace ppp
