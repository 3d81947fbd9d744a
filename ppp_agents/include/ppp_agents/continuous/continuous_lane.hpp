#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/agent_lane.hpp"
#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_agents/episode_result.hpp"
#include "ppp_agents/prepared_set.hpp"
#include "ppp_core/continuous_episode.hpp"
#include "ppp_core/episode_options.hpp"

namespace ppp {
namespace agents {

/// One control period of one active continuous episode, as the simulator sends it to its agent.
struct ContinuousRequest {
  std::uint32_t episode = 0;             ///< Episode id, unique within the lane.
  int step = 0;                          ///< Control periods played so far.
  std::optional<ContinuousStart> start;  ///< At the episode's first request: what the agent is told.
  Pose2D pose;                           ///< The robot's exact odometry.
  BodyVelocity velocity;                 ///< Its velocity during the last period, robot frame.
  double time = 0;                       ///< Simulated seconds since the episode's start.
  std::vector<float> ranges;             ///< The laser (empty for an agent that does not read it).
  int set = 0;                           ///< Index of the PPP's set (the simulator's own; not sent).
  int problem = 0;                       ///< Index of the PPP in its set (not sent).
  int run = 0;                           ///< Run number (not sent).
};

/// An agent's answer to a ContinuousRequest.
struct ContinuousReply {
  std::uint32_t episode = 0;      ///< The episode answered.
  int step = 0;                   ///< The step answered.
  BodyVelocity command;           ///< The velocity commanded for the next control period.
  const char* failure = nullptr;  ///< A reason:: constant when the agent ends the episode as failed.
};

/// All the runs of one agent configuration in continuous motion, played in lockstep batches (AgentLane's
/// counterpart, ROS-free): up to `batch_size` episodes are active at once; each round the lane hands out one
/// request per active episode and applies one velocity command per episode. The episodes, their budgets and their
/// rows are those of ContinuousRunner, so for the same seeds and commands the rows are the same.
class ContinuousLane {
 public:
  /// Queues `runs` runs of `config` on every PPP of `sets` (those of `share`), seeded by `seed_of`, except those
  /// `skip` says are done. @throws InvalidArgument (batch_size, share, or a built-in agent that moves only on the
  /// grid).
  ContinuousLane(const AgentConfig& config, const EpisodeOptions& options, const std::vector<PreparedSet>& sets,
                 AgentLane::SeedFunction seed_of, int runs, int batch_size, const AgentLane::SkipFunction& skip = {},
                 LaneShare share = {});
  /// True when no run is waiting or active.
  bool finished() const { return queue_.empty() && active_.empty(); }
  /// Runs not yet finished (active or queued).
  long remaining() const { return static_cast<long>(queue_.size() + active_.size()); }
  /// Fills the batch from the queue and writes the request of every active episode into `requests` (resized).
  /// @throws InvalidArgument naming robot_radius when a queued run's disc cannot stand at its start.
  void requests(std::vector<ContinuousRequest>* requests);
  /// Applies a batch of replies. An active episode with no reply fails with `missing_reason`; a reply for the wrong
  /// step fails it with reason::kInvalidCommand (as does a command that is not finite), a reply with a failure
  /// with that reason; replies for unknown episodes are ignored. Returns the rows of the episodes that ended.
  std::vector<EpisodeResult> answer(const std::vector<ContinuousReply>& replies, const char* missing_reason);
  /// A batch went unanswered: its episodes fail with `reason`, and once `give_up_after` batches in a row went
  /// unanswered every remaining run fails with it too (a silent agent does not hold the experiment up).
  std::vector<EpisodeResult> unanswered(const char* reason, int give_up_after);
  /// Batches in a row that went unanswered.
  int silentBatches() const { return silent_batches_; }
  /// Fails every active and queued run with `reason` (the agent is gone) and returns their rows.
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
    int optimal;
    ContinuousEpisode episode;
    bool started;
    std::vector<BodyVelocity> commands;  // a planner's run: its commands so far
  };
  EpisodeResult result(const Work& work, std::uint64_t seed, int optimal, const ContinuousOutcome& outcome) const;

  AgentConfig config_;
  EpisodeOptions options_;
  const std::vector<PreparedSet>& sets_;
  AgentLane::SeedFunction seed_of_;
  int batch_size_;
  bool reads_laser_;
  bool keeps_commands_;  // a planner: its runs cannot be replayed, so each result carries its commands
  std::deque<Work> queue_;
  std::vector<Active> active_;
  std::uint32_t next_id_ = 0;
  int silent_batches_ = 0;
};

}  // namespace agents
}  // namespace ppp
