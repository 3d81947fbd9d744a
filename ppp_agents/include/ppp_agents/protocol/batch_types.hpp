#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ppp_agents/agent.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/grid.hpp"
#include "ppp_core/window_mask.hpp"

namespace ppp {
namespace protocol {

// The simulator <-> agent batch protocol (ppp_msgs/ScanBatch, ppp_msgs/MoveBatch) as plain types: the simulator's
// lanes produce ScanRequests and take MoveReplys; batch_codec.hpp turns them into messages and back. ROS-free.
// Cells are in the core grid convention (x right, y down).

/// What an agent is told when an episode starts (sent with its first scan).
struct EpisodeStart {
  int width = 0;                       ///< Map columns.
  int height = 0;                      ///< Map rows.
  Cell start;                          ///< Start cell.
  Cell goal;                           ///< Goal cell (fixed for the episode).
  std::uint64_t agent_seed = 0;        ///< Seed of the agent's own choices.
  std::vector<std::int8_t> prior_map;  ///< The true map (kScanFree / kScanObstacle per cell) for astar; else empty.
  Connectivity connectivity = Connectivity::Four;  ///< Move model.
};

/// One scan of a batch, for one episode and step.
struct ScanRequest {
  std::uint32_t episode = 0;          ///< Episode id, unique within the lane.
  int step = 0;                       ///< Steps taken so far.
  Cell position;                      ///< The agent's cell.
  Cell goal;                          ///< The goal cell (on the wire only in the start).
  bool bumped = false;                ///< The last move bumped.
  int range = 0;                      ///< Window radius.
  bool window = false;                ///< False for agents that never read the window (random): no masks.
  std::array<std::uint64_t, kMaxWindowWords> free_cells{};      ///< The window's free cells (window_mask.hpp).
  std::array<std::uint64_t, kMaxWindowWords> obstacle_cells{};  ///< Its obstacle cells, in the same words.
  std::optional<EpisodeStart> start;  ///< Set on the episode's first scan.
  int set = 0;                        ///< Index of the PPP's set (the simulator's own; not sent).
  int problem = 0;                    ///< Index of the PPP in its set (not sent).
  int run = 0;                        ///< Run number (not sent).
};

/// Where a simulator's lane writes a batch of scans, one at a time: straight into the message to send
/// (batch_codec.hpp's ScanBatchWriter), or into a list (ScanList). A lane reuses one ScanRequest for every scan of
/// a batch, so a batch of hundreds of scans never lives as hundreds of ScanRequests.
class ScanSink {
 public:
  virtual ~ScanSink() = default;
  /// A batch of `count` scans of windows of `range` begins; `window` is false for an agent that reads no window.
  virtual void begin(std::size_t count, int range, bool window) = 0;
  /// The batch's next scan; its start may be moved from.
  virtual void add(ScanRequest& scan) = 0;
};

/// A ScanSink that keeps the batch's scans in a vector (replaced by each batch; its elements' buffers reused).
class ScanList : public ScanSink {
 public:
  explicit ScanList(std::vector<ScanRequest>* scans) : scans_(scans) {}
  void begin(std::size_t count, int, bool) override {
    scans_->resize(count);
    next_ = 0;
  }
  void add(ScanRequest& scan) override { (*scans_)[next_++] = std::move(scan); }

 private:
  std::vector<ScanRequest>* scans_;
  std::size_t next_ = 0;
};

/// One move of a batch, as an agent answers it.
struct MoveReply {
  std::uint32_t episode = 0;      ///< The episode answered.
  std::uint32_t step = 0;         ///< The step answered.
  int action = 0;                 ///< An Action number (anything else is invalid).
  const char* failure = nullptr;  ///< The agent gives the episode up for this reason (a reason:: constant).
  const char* diagnosis = nullptr;  ///< With failure no_path: diagnosis::kMissedRoute or kNoRoute, if known.
  std::uint64_t state = 0;  ///< A digest of the agent's decision state as it chose the move (0: none given).
};

/// Cells of the window of range `range`: (2 range + 1)^2.
inline std::size_t windowCells(int range) { return static_cast<std::size_t>(2 * range + 1) * (2 * range + 1); }

/// A grid as an EpisodeStart's prior_map.
std::vector<std::int8_t> priorMapCells(const Grid& grid);

/// The grid of a start's prior_map, or null when it has none. @throws InvalidArgument naming "prior_map".
std::unique_ptr<Grid> priorGrid(const EpisodeStart& start);

/// What an agent is given at the start: the start's size, cells and seed, with `prior` (may be null) as the map.
agents::EpisodeInfo episodeInfo(const EpisodeStart& start, const Grid* prior);

/// Throws InvalidArgument naming `field` unless `cell` lies on a width x height grid.
void requireOnGrid(Cell cell, int width, int height, const char* field);

}  // namespace protocol
}  // namespace ppp
