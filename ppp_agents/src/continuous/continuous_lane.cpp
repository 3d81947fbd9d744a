#include "ppp_agents/continuous/continuous_lane.hpp"

#include <string>
#include <unordered_map>
#include <utility>

#include "ppp_agents/continuous/continuous_runner.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace agents {

ContinuousLane::ContinuousLane(const AgentConfig& config, const EpisodeOptions& options,
                               const std::vector<PreparedSet>& sets, AgentLane::SeedFunction seed_of, int runs,
                               int batch_size, const AgentLane::SkipFunction& skip, LaneShare share)
    : config_((config.validate(), config)),
      options_((options.validate(), options)),
      sets_(sets),
      seed_of_(std::move(seed_of)),
      batch_size_(isPlanner(config) ? 1 : batch_size),
      reads_laser_(isPlanner(config) || makeContinuousAgent(config)->readsLaser()),
      keeps_commands_(isPlanner(config)) {
  if (batch_size < 1) throw InvalidArgument("batch_size", "expected at least 1, got " + std::to_string(batch_size));
  if (share.count < 1 || share.index < 0 || share.index >= share.count) {
    throw InvalidArgument("share", "expected instance " + std::to_string(share.index) + " of " +
                                       std::to_string(share.count) + " to be in [0, " + std::to_string(share.count) + ")");
  }
  long position = 0;  // in the lane's order over every run, played or skipped: a share does not depend on `skip`
  for (int s = 0; s < static_cast<int>(sets.size()); ++s) {
    for (int p = 0; p < static_cast<int>(sets[s].set.ids.size()); ++p) {
      for (int run = 0; run < runs; ++run, ++position) {
        if (position % share.count == share.index && (!skip || !skip(s, p, run))) queue_.push_back({s, p, run});
      }
    }
  }
}

void ContinuousLane::requests(std::vector<ContinuousRequest>* requests) {
  while (static_cast<int>(active_.size()) < batch_size_ && !queue_.empty()) {
    const Work work = queue_.front();
    queue_.pop_front();
    const PreparedSet& set = sets_[work.set];
    const Problem& problem = set.set.problems[work.problem];
    const Grid& grid = set.grids[work.problem];
    const std::uint64_t seed = seed_of_(work.set, work.problem, work.run);
    const int optimal = continuousOptimalMoves(problem, grid, options_, set.moves[work.problem]);
    active_.push_back({next_id_++, work, seed, optimal, continuousEpisode(problem, grid, options_, optimal, seed),
                       false, {}});
  }
  requests->resize(active_.size());
  for (std::size_t i = 0; i < active_.size(); ++i) {
    Active& a = active_[i];
    ContinuousRequest& r = (*requests)[i];
    r.episode = a.id;
    r.step = a.episode.outcome().steps;
    r.start.reset();
    if (!a.started) {
      const PreparedSet& set = sets_[a.work.set];
      r.start = continuousStart(a.episode, options_, config_, set.grids[a.work.problem], a.seed);
      a.started = true;
    }
    r.pose = a.episode.pose();
    r.velocity = a.episode.velocity();
    r.time = a.episode.time();
    r.set = a.work.set;
    r.problem = a.work.problem;
    r.run = a.work.run;
    if (reads_laser_) {
      a.episode.scan(&r.ranges);
    } else {
      r.ranges.clear();
    }
  }
}

EpisodeResult ContinuousLane::result(const Work& work, std::uint64_t seed, int optimal,
                                     const ContinuousOutcome& outcome) const {
  return continuousResult(sets_[work.set], work.problem, config_.name, work.run, seed, optimal, outcome, options_);
}

std::vector<EpisodeResult> ContinuousLane::answer(const std::vector<ContinuousReply>& replies,
                                                  const char* missing_reason) {
  if (!replies.empty()) silent_batches_ = 0;
  // Agents answer in request order, so reply i is normally episode i's; the index is built only when not.
  std::unordered_map<std::uint32_t, const ContinuousReply*> by_episode;
  const auto reply_of = [&](std::size_t i, std::uint32_t id) -> const ContinuousReply* {
    if (by_episode.empty() && i < replies.size() && replies[i].episode == id) return &replies[i];
    if (by_episode.empty()) {
      for (const ContinuousReply& reply : replies) by_episode.emplace(reply.episode, &reply);
    }
    const auto it = by_episode.find(id);
    return it == by_episode.end() ? nullptr : it->second;
  };
  std::vector<EpisodeResult> finished;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < active_.size(); ++i) {
    Active& a = active_[i];
    const ContinuousReply* reply = reply_of(i, a.id);
    if (reply == nullptr) {
      a.episode.fail(missing_reason);
    } else if (reply->failure != nullptr) {
      a.episode.fail(reply->failure);
    } else if (reply->step != a.episode.outcome().steps) {
      a.episode.fail(reason::kInvalidCommand);
    } else {
      if (keeps_commands_) a.commands.push_back(reply->command);
      a.episode.apply(reply->command);
    }
    if (a.episode.done()) {
      finished.push_back(result(a.work, a.seed, a.optimal, a.episode.outcome()));
      finished.back().commands = std::move(a.commands);
    } else {
      if (kept != i) active_[kept] = std::move(a);
      ++kept;
    }
  }
  active_.erase(active_.begin() + static_cast<std::ptrdiff_t>(kept), active_.end());
  return finished;
}

std::vector<EpisodeResult> ContinuousLane::unanswered(const char* why, int give_up_after) {
  std::vector<EpisodeResult> ended = answer({}, why);
  if (++silent_batches_ >= give_up_after) {
    for (EpisodeResult& r : failAll(why)) ended.push_back(std::move(r));
  }
  return ended;
}

std::vector<EpisodeResult> ContinuousLane::failAll(const char* why) {
  std::vector<EpisodeResult> failed;
  for (Active& a : active_) {
    a.episode.fail(why);
    failed.push_back(result(a.work, a.seed, a.optimal, a.episode.outcome()));
    failed.back().commands = std::move(a.commands);
  }
  active_.clear();
  for (const Work& work : queue_) {
    const PreparedSet& set = sets_[work.set];
    const int optimal = continuousOptimalMoves(set.set.problems[work.problem], set.grids[work.problem], options_,
                                               set.moves[work.problem]);
    ContinuousOutcome outcome;
    outcome.reason = why;
    failed.push_back(result(work, seed_of_(work.set, work.problem, work.run), optimal, outcome));
  }
  queue_.clear();
  return failed;
}

}  // namespace agents
}  // namespace ppp
