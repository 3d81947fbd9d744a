#include "ppp_agents/agent_lane.hpp"

#include <string>
#include <unordered_map>

#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_agents/episode_runner.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/window_mask.hpp"

namespace ppp {
namespace agents {

namespace {

constexpr std::size_t kPrefetchAhead = 8;  // episodes between fetching an episode's state and using it

/// Asks the processor to fetch `*object` whole: a pass over hundreds of episodes reads each one's state once, long
/// after the last pass evicted it, at a stride too large for the hardware to foresee.
template <typename T>
void prefetchWhole(const T& object) {
  const char* bytes = reinterpret_cast<const char*>(&object);
  for (std::size_t line = 0; line < sizeof(T); line += 64) __builtin_prefetch(bytes + line);
}

}  // namespace

AgentLane::AgentLane(const AgentConfig& config, const EpisodeOptions& options,
                     const std::vector<PreparedSet>& sets, SeedFunction seed_of, int runs, int batch_size,
                     const SkipFunction& skip, LaneShare share)
    : config_((config.validate(), config)),
      options_((options.validate(), refuseContinuous(config, options), options)),
      sets_(sets),
      seed_of_(std::move(seed_of)),
      batch_size_(isPlanner(config) ? 1 : batch_size),
      reads_window_(readsScanWindow(config)),
      collisions_end_(isPlanner(config) && !isPointRobot(options.robot_radius)),
      keeps_actions_(isPlanner(config)),
      keeps_states_(isPlanner(config) && config.sensor_noise == 0),
      sensor_(SensorOptions{options.sensor_range, config.sensor_noise}) {
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

void AgentLane::scans(protocol::ScanSink* sink) {
  while (static_cast<int>(active_.size()) < batch_size_ && !queue_.empty()) {
    const Work work = queue_.front();
    queue_.pop_front();
    const PreparedSet& set = sets_[work.set];
    const std::uint64_t seed = seed_of_(work.set, work.problem, work.run);
    active_.push_back({next_id_++, work, seed,
                       Episode(set.set.problems[work.problem], set.grids[work.problem], sensor_, seed,
                               options_.budgetRule(set.budgets[work.problem]), options_.connectivity, false,
                               windowsOf(set, work.problem),
                               motionOf(set, work.problem)),
                       false, {}, {}, nullptr});
  }
  sink->begin(active_.size(), options_.sensor_range, reads_window_);
  ScanRequest& r = request_;  // one for every scan: it stays in cache
  for (std::size_t i = 0; i < active_.size(); ++i) {
    if (i + kPrefetchAhead < active_.size()) prefetchWhole(active_[i + kPrefetchAhead]);
    Active& a = active_[i];
    const Scan scan = a.episode.scan();
    r.start.reset();
    r.episode = a.id;
    r.step = scan.step();
    r.position = scan.position();
    r.goal = scan.goal();
    r.bumped = scan.bumped();
    r.range = scan.range();
    r.set = a.work.set;
    r.problem = a.work.problem;
    r.run = a.work.run;
    r.window = reads_window_;
    if (reads_window_) {
      WindowBits bits;
      if (scan.bits(&bits)) {  // the atlas's masks, noise included: no cell is built
        packWindow(bits, &r.free_cells[0], &r.obstacle_cells[0]);
      } else {
        packWindow(scan.cells(), r.range, r.free_cells.data(), r.obstacle_cells.data());
      }
    }
    if (!a.started) {
      const PreparedSet& set = sets_[a.work.set];
      const Grid& grid = set.grids[a.work.problem];
      const EpisodeInfo info = episodeInfo(set.set.problems[a.work.problem], grid, config_, a.seed, options_.connectivity,
                                           motionOf(set, a.work.problem));
      EpisodeStart start{info.width, info.height, info.start, info.goal, info.seed, {}, info.connectivity};
      if (info.prior_map != nullptr) start.prior_map = protocol::priorMapCells(*info.prior_map);
      r.start = std::move(start);
      a.started = true;
    }
    sink->add(r);
  }
}

EpisodeResult AgentLane::result(const Work& work, std::uint64_t seed, const EpisodeOutcome& outcome,
                               const std::vector<std::uint64_t>& states, const char* reported_kind) const {
  return episodeResult(sets_[work.set], work.problem, config_.name, work.run, seed, outcome, states, reported_kind);
}

std::vector<EpisodeResult> AgentLane::unanswered(const char* reason, int give_up_after) {
  std::vector<EpisodeResult> ended = answer({}, reason);
  if (++silent_batches_ >= give_up_after) {
    for (EpisodeResult& r : failAll(reason)) ended.push_back(std::move(r));
  }
  return ended;
}

std::vector<EpisodeResult> AgentLane::answer(const std::vector<MoveReply>& moves, const char* missing_reason) {
  if (!moves.empty()) silent_batches_ = 0;
  // Agents answer in scan order, so move i is normally episode i's; the index is built only when not.
  std::unordered_map<std::uint32_t, const MoveReply*> by_episode;
  const auto move_of = [&](std::size_t i, std::uint32_t id) -> const MoveReply* {
    if (by_episode.empty() && i < moves.size() && moves[i].episode == id) return &moves[i];
    if (by_episode.empty()) {
      for (const MoveReply& m : moves) by_episode.emplace(m.episode, &m);
    }
    const auto it = by_episode.find(id);
    return it == by_episode.end() ? nullptr : it->second;
  };
  std::vector<EpisodeResult> finished;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < active_.size(); ++i) {
    if (i + 2 * kPrefetchAhead < active_.size()) prefetchWhole(active_[i + 2 * kPrefetchAhead]);
    if (i + kPrefetchAhead < active_.size()) active_[i + kPrefetchAhead].episode.prefetchNextStep();
    Active& a = active_[i];
    const MoveReply* move = move_of(i, a.id);
    if (move == nullptr) {
      a.episode.fail(missing_reason);
    } else if (move->failure != nullptr) {
      a.episode.fail(move->failure);
      a.reported_kind = move->diagnosis;
    } else if (static_cast<int>(move->step) != a.episode.step() || !isAction(move->action, options_.connectivity)) {
      a.episode.fail(reason::kInvalidAction);
    } else {
      const int bumps = a.episode.outcome().bumps;
      a.episode.apply(static_cast<Action>(move->action));
      if (keeps_actions_) a.actions.push_back(static_cast<Action>(move->action));
      if (keeps_states_) a.states.push_back(move->state);
      if (collisions_end_ && a.episode.outcome().bumps > bumps) a.episode.fail(reason::kCollision);
    }
    if (a.episode.done()) {
      finished.push_back(result(a.work, a.seed, a.episode.outcome(), a.states, a.reported_kind));
      finished.back().actions = std::move(a.actions);
    } else {
      if (kept != i) active_[kept] = std::move(a);
      ++kept;
    }
  }
  active_.erase(active_.begin() + static_cast<std::ptrdiff_t>(kept), active_.end());
  return finished;
}

std::vector<EpisodeResult> AgentLane::failAll(const char* why) {
  std::vector<EpisodeResult> failed;
  for (Active& a : active_) {
    a.episode.fail(why);
    failed.push_back(result(a.work, a.seed, a.episode.outcome()));
    failed.back().actions = std::move(a.actions);
  }
  active_.clear();
  for (const Work& work : queue_) {
    EpisodeOutcome outcome;
    outcome.reason = why;
    failed.push_back(result(work, seed_of_(work.set, work.problem, work.run), outcome));
  }
  queue_.clear();
  return failed;
}

}  // namespace agents
}  // namespace ppp
