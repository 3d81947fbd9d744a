#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <set>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/episode_result.hpp"
#include "ppp_agents/prepared_set.hpp"
#include "ppp_agents/protocol/batch_types.hpp"
#include "ppp_core/episode.hpp"
#include "ppp_core/episode_options.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {

// The lane speaks the batch protocol's plain types (ppp_agents/protocol/batch_types.hpp).
using protocol::EpisodeStart;
using protocol::MoveReply;
using protocol::ScanRequest;

/// Which of an agent's runs a lane plays when several instances share them: every `count`-th run of the lane's
/// order (set, PPP, run), starting at run `index`.
struct LaneShare {
  int index = 0;  ///< This lane's instance, in [0, count).
  int count = 1;  ///< Instances sharing the runs.
};

/// All the runs of one agent configuration in an experiment, played in lockstep batches: up to `batch_size`
/// episodes are active at once; each round the lane hands out one scan per active episode and takes one move
/// per episode back. Episodes that finish are replaced from the queue of remaining runs. The moves applied
/// are the agent's own, so the results equal the in-process runner's for the same seeds.
class AgentLane {
 public:
  /// The seed of run `run` of the lane's agent on PPP `problem` of set `set` (indices into the lane's sets).
  using SeedFunction = std::function<std::uint64_t(int set, int problem, int run)>;
  /// Whether run `run` on PPP `problem` of set `set` is already done and is not played (a resumed experiment).
  using SkipFunction = std::function<bool(int set, int problem, int run)>;
  /// Queues `runs` runs of `config` on every PPP of `sets` (those of `share`), seeded by `seed_of`, except those
  /// `skip` says are done. @throws InvalidArgument.
  AgentLane(const AgentConfig& config, const EpisodeOptions& options, const std::vector<PreparedSet>& sets,
            SeedFunction seed_of, int runs, int batch_size, const SkipFunction& skip = {}, LaneShare share = {});
  /// True when no run is waiting or active.
  bool finished() const { return queue_.empty() && active_.empty(); }
  /// Runs not yet finished (active or queued).
  long remaining() const { return static_cast<long>(queue_.size() + active_.size()); }
  /// Fills the batch from the queue and writes the scans of every active episode to `sink`, in episode order.
  void scans(protocol::ScanSink* sink);
  /// As above, into `requests` (resized; its elements' buffers are reused).
  void scans(std::vector<ScanRequest>* requests) {
    protocol::ScanList list(requests);
    scans(&list);
  }
  /// Applies a batch of moves. An active episode with no move gets `missing_reason`; a move for the wrong step
  /// or with an unknown action fails its episode with reason::kInvalidAction, a move with a failure fails it
  /// with that reason, and a planner agent's move that bumps a robot with a body (robot_radius) fails it with
  /// reason::kCollision, as a real robot's run would end; moves for unknown episodes are ignored. A planner's
  /// decision states (MoveReply::state) are kept to prove its loops endless, unless its sensor is noisy (the
  /// next scan is then not a function of the state). Returns the results of the episodes that ended.
  std::vector<EpisodeResult> answer(const std::vector<MoveReply>& moves, const char* missing_reason);
  /// A batch went unanswered: its episodes fail with `reason`, and once `give_up_after` batches in a row went
  /// unanswered every remaining run fails with it too (a silent agent does not hold the experiment up).
  std::vector<EpisodeResult> unanswered(const char* reason, int give_up_after);
  /// Batches in a row that went unanswered.
  int silentBatches() const { return silent_batches_; }
  /// Fails every active and queued run with `reason` (the agent is gone) and returns their results.
  std::vector<EpisodeResult> failAll(const char* reason);
  /// The configuration served.
  const AgentConfig& config() const { return config_; }

 private:
  struct Work {
    int set;
    int problem;
    int run;
  };
  struct Active {
    std::uint32_t id;
    Work work;
    std::uint64_t seed;
    Episode episode;
    bool started;
    std::vector<Action> actions;  // a planner's run: its actions so far
    std::vector<std::uint64_t> states;  // the agent's decision state per action, when it proves loops
    const char* reported_kind;          // the diagnosis the agent gave for its own ending, if any
  };
  EpisodeResult result(const Work& work, std::uint64_t seed, const EpisodeOutcome& outcome,
                       const std::vector<std::uint64_t>& states = {}, const char* reported_kind = nullptr) const;

  AgentConfig config_;
  EpisodeOptions options_;
  const std::vector<PreparedSet>& sets_;
  SeedFunction seed_of_;
  int batch_size_;
  bool reads_window_;
  bool collisions_end_;  // a planner driving a robot with a body: a bump is a collision that ends the run
  bool keeps_actions_;   // a planner: its runs cannot be replayed, so each result carries its actions
  bool keeps_states_;    // a planner without sensor noise: its decision states can prove a loop endless
  SensorModel sensor_;
  std::deque<Work> queue_;
  std::vector<Active> active_;
  std::uint32_t next_id_ = 0;
  int silent_batches_ = 0;
  ScanRequest request_;  // the scan being written to a sink
};

}  // namespace agents
}  // namespace ppp
