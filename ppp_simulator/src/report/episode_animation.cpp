#include "ppp_simulator/report/episode_animation.hpp"

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "ppp_agents/agent_memory.hpp"
#include "ppp_agents/agent_registry.hpp"
#include "ppp_core/canvas.hpp"
#include "ppp_core/diagnosis.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/gif_animation.hpp"
#include "ppp_core/optimum.hpp"

namespace ppp {
namespace simulator {

namespace {

/// Palette indices of a frame.
enum Ink : std::uint8_t {
  kGridLineInk,
  kFreeInk,
  kObstacleInk,
  kUnsensedFreeInk,
  kUnsensedObstacleInk,
  kScannedInk,
  kWindowInk,
  kStartInk,
  kGoalInk,
  kTrailInk,
  kAgentInk,
  kBumpInk,
  kCycleInk,
};

const std::vector<Rgb> kPalette = {kGridLineColour, kFreeColour,  kObstacleColour, kUnsensedColour,
                                   Rgb{128, 128, 136}, kScannedColour, Rgb{235, 180, 40}, kStartColour,
                                   kGoalColour,     kPathColour,  kAgentColour,    kBumpColour,
                                   kMarkedColour};

void checkMilliseconds(int ms, const char* name) {
  if (ms < 20 || ms > 10000 || ms % 10 != 0) {
    throw InvalidArgument(name, "expected a multiple of 10 ms (GIF's unit) in [20, 10000], got " + std::to_string(ms));
  }
}

/// A blocked move: the agent's cell and the action that bumped.
struct Bump {
  Cell cell;
  Action action;
};

/// What one frame shows.
struct FrameState {
  Cell position;
  const std::vector<std::pair<Cell, Cell>>* trail;  // the distinct moves so far (from, to)
  const std::vector<Bump>* bumps;                   // the distinct bumps so far
  const Scan* scan;
  const agents::AgentMemory* memory;  // null: the agent knows the map
  const std::vector<bool>* cycle;     // per cell, whether it is on the loop's cycle (null: none shown)
};

/// A loop's cycle, to be marked from the step it began.
struct CycleMarks {
  std::vector<bool> cells;  // per cell (row-major), on the cycle; empty when the run is no loop
  int from = 0;             // the loop's first step
};

/// The cycle of `outcome` on `problem` when the run ended in a loop (diagnoseRun()).
CycleMarks cycleMarks(const Problem& problem, const EpisodeOutcome& outcome) {
  CycleMarks marks;
  const Diagnosis d = diagnoseRun(outcome.passed, false, outcome.reason, outcome.cells);
  const std::vector<Cell> cycle = cycleCells(d, outcome.cells);
  if (cycle.empty()) return marks;
  marks.cells.assign(static_cast<std::size_t>(problem.width) * problem.height, false);
  for (const Cell c : cycle) marks.cells[static_cast<std::size_t>(c.y) * problem.width + c.x] = true;
  marks.from = d.step;
  return marks;
}

/// Records each distinct item once, in the order first seen; `key` maps an item to a number below `keys`.
template <typename Item>
class DistinctList {
 public:
  explicit DistinctList(std::size_t keys) : seen_(keys, false) {}
  void add(const Item& item, std::size_t key) {
    if (seen_[key]) return;
    seen_[key] = true;
    items_.push_back(item);
  }
  const std::vector<Item>& items() const { return items_; }

 private:
  std::vector<bool> seen_;
  std::vector<Item> items_;
};

/// The number of a move or bump from `cell` with `action` among a map's cells x 9 actions.
std::size_t moveKey(const Problem& problem, Cell cell, Action action) {
  return (static_cast<std::size_t>(cell.y) * problem.width + cell.x) * 9 + static_cast<std::size_t>(action);
}

/// The cell size for `options` on `problem`: as given, or chosen by map size.

/// Draws frames of one problem as palette indices.
class FramePainter {
 public:
  FramePainter(const Problem& problem, const Grid& grid, int cell_pixels)
      : problem_(problem), grid_(grid), picture_{cell_pixels, true},
        width_(pictureWidth(problem.width, picture_)), height_(pictureHeight(problem.height, picture_)) {}
  int width() const { return width_; }
  int height() const { return height_; }

  std::vector<std::uint8_t> paint(const FrameState& s) const {
    Canvas<std::uint8_t> canvas(width_, height_, kGridLineInk);
    for (int y = 0; y < problem_.height; ++y) {
      for (int x = 0; x < problem_.width; ++x) {
        const Cell c{x, y};
        const bool known = s.memory == nullptr || s.memory->at(c) != kScanUnknown;
        std::uint8_t ink = grid_.isObstacle(c) ? (known ? kObstacleInk : kUnsensedObstacleInk)
                                               : (known ? kFreeInk : kUnsensedFreeInk);
        const int dx = x - s.position.x, dy = y - s.position.y;
        const int range = s.scan->range();
        if (!grid_.isObstacle(c) && std::abs(dx) <= range && std::abs(dy) <= range && s.scan->at(dx, dy) != kScanUnknown) {
          ink = kScannedInk;
        } else if (s.cycle != nullptr && (*s.cycle)[static_cast<std::size_t>(y) * problem_.width + x]) {
          ink = kCycleInk;
        }
        canvas.fillCell(c, ink, picture_);
      }
    }
    const int cp = picture_.cell_pixels;
    const int thickness = std::max(1, cp / 8);
    for (const auto& [from, to] : *s.trail) {
      canvas.line(cellCentre(from, picture_), cellCentre(to, picture_), thickness, kTrailInk);
    }
    canvas.fillCell(problem_.start, kStartInk, picture_);
    canvas.fillCell(problem_.goal, kGoalInk, picture_);
    const int bar = std::max(2, cp / 5);
    for (const Bump& b : *s.bumps) {
      const Pixel o = cellOrigin(b.cell, picture_);
      const Cell d = offset(b.action);
      // A bar along the side the move was blocked at (a corner square for a diagonal).
      const int x0 = d.x > 0 ? o.x + cp - bar : o.x + 1, x1 = d.x < 0 ? o.x + 1 + bar : o.x + cp;
      const int y0 = d.y > 0 ? o.y + cp - bar : o.y + 1, y1 = d.y < 0 ? o.y + 1 + bar : o.y + cp;
      canvas.fill(x0, y0, x1, y1, kBumpInk);
    }
    outlineWindow(canvas, s.position, s.scan->range());
    canvas.disc(cellCentre(s.position, picture_), std::max(1, cp / 3), kAgentInk);
    return canvas.release();
  }

 private:
  /// A one-pixel frame on the grid lines around the scan window, clipped to the map.
  void outlineWindow(Canvas<std::uint8_t>& canvas, Cell at, int range) const {
    const Cell lo{std::max(at.x - range, 0), std::max(at.y - range, 0)};
    const Cell hi{std::min(at.x + range, problem_.width - 1) + 1, std::min(at.y + range, problem_.height - 1) + 1};
    const Pixel a = cellOrigin(lo, picture_), b = cellOrigin(hi, picture_);
    canvas.fill(a.x, a.y, b.x + 1, a.y + 1, kWindowInk);
    canvas.fill(a.x, b.y, b.x + 1, b.y + 1, kWindowInk);
    canvas.fill(a.x, a.y, a.x + 1, b.y + 1, kWindowInk);
    canvas.fill(b.x, a.y, b.x + 1, b.y + 1, kWindowInk);
  }

  const Problem& problem_;
  const Grid& grid_;
  PictureOptions picture_;
  int width_;
  int height_;
};

}  // namespace

int animationCellPixels(const Problem& problem, const AnimationOptions& options) {
  const int cell_pixels = options.cell_pixels != 0
                              ? options.cell_pixels
                              : std::clamp(kAnimationTargetPixels / std::max(problem.width, problem.height), 3, 12);
  const PictureOptions picture{cell_pixels, true};
  if (pictureWidth(problem.width, picture) > kMaxPictureSide || pictureHeight(problem.height, picture) > kMaxPictureSide) {
    const int most = (kMaxPictureSide - 1) / cell_pixels;
    throw InvalidArgument("map", "a " + std::to_string(problem.width) + "x" + std::to_string(problem.height) +
                                     " map is too large to animate at " + std::to_string(cell_pixels) +
                                     " pixels per cell (at most " + std::to_string(most) + " cells a side, " +
                                     std::to_string(kMaxPictureSide) + " pixels); draw its path as a .png");
  }
  return cell_pixels;
}

void AnimationOptions::validate() const {
  if (cell_pixels != 0 && (cell_pixels < 3 || cell_pixels > 64)) {
    throw InvalidArgument("cell_pixels", "expected an integer in [3, 64], or 0 (by map size), got " +
                                             std::to_string(cell_pixels));
  }
  if (max_frames < 2 || max_frames > kMaxAnimationFrames) {
    throw InvalidArgument("max_frames", "expected an integer in [2, " + std::to_string(kMaxAnimationFrames) +
                                            "], got " + std::to_string(max_frames));
  }
  checkMilliseconds(frame_ms, "frame_ms");
  checkMilliseconds(last_frame_ms, "last_frame_ms");
}

namespace {

/// The action for a step's scan, or nothing when a recorded run ended there for its recorded reason.
using NextAction = std::function<std::optional<Action>(const Scan&)>;

/// Plays the episode whose actions `next` gives (ending it with `end_reason` where `next` gives none) and draws
/// it frame by frame, with frames spread over its `steps` steps. @throws Error when it takes another number of
/// steps; as animateEpisode otherwise.
EpisodeAnimation drawEpisode(const Problem& problem, const Grid& grid, const agents::AgentConfig& config,
                             const EpisodeOptions& options, std::uint64_t run_seed, int steps, const NextAction& next,
                             const char* end_reason, const AnimationOptions& animation, const CycleMarks& marks,
                             const StopCheck& stop) {
  const FramePainter painter(problem, grid, animationCellPixels(problem, animation));
  const agents::EpisodeRunner runner(config, options);
  EpisodeAnimation result;
  result.stride = std::max(1, (steps + animation.max_frames - 2) / (animation.max_frames - 1));

  Grid space;
  const Grid* motion = &motionGrid(grid, options.robot_radius, &space);
  const agents::EpisodeInfo info = agents::episodeInfo(problem, grid, config, run_seed, options.connectivity, motion);
  Episode episode(problem, grid, runner.sensor(), run_seed, options.budgetRule(episodeBudget(options, problem, grid)),
                  options.connectivity, true, nullptr, motion);
  std::unique_ptr<agents::AgentMemory> memory;
  if (info.prior_map == nullptr) {
    memory = std::make_unique<agents::AgentMemory>();
    const agents::AgentBehaviour behaviour = agents::agentBehaviour(config);
    memory->reset(problem.width, problem.height, behaviour.memory_window, behaviour.memory_scans);
  }
  GifAnimation gif(painter.width(), painter.height(), kPalette);
  const std::size_t keys = static_cast<std::size_t>(problem.width) * problem.height * 9;
  DistinctList<std::pair<Cell, Cell>> trail(keys);
  DistinctList<Bump> bumps(keys);
  Cell position = problem.start;
  for (;;) {
    const Scan scan = episode.scan();
    std::optional<Action> action;
    if (!episode.done()) {
      action = next(scan);
      if (!action && end_reason == nullptr) {
        throw Error("the recorded run of " + config.name + " with seed " + std::to_string(run_seed) +
                    " ends at step " + std::to_string(episode.step()) + " before its episode does");
      }
      if (!action) episode.fail(end_reason);
    }
    const bool last = episode.done();
    if (memory != nullptr) memory->update(scan);  // the last one only for the picture: the agent never acts on it
    if (last || episode.step() % result.stride == 0) {
      stopIfAsked(stop);
      const bool looping = !marks.cells.empty() && episode.step() >= marks.from;
      const FrameState state{position, &trail.items(), &bumps.items(), &scan, memory.get(),
                             looping ? &marks.cells : nullptr};
      gif.addFrame(painter.paint(state), (last ? animation.last_frame_ms : animation.frame_ms) / 10);
    }
    if (last) break;
    const int bumps_before = episode.outcome().bumps;
    episode.apply(*action);
    const Cell now = episode.outcome().path.back();
    if (episode.outcome().bumps > bumps_before) bumps.add(Bump{position, *action}, moveKey(problem, position, *action));
    if (now != position) trail.add({position, now}, moveKey(problem, position, *action));
    position = now;
  }
  if (episode.outcome().steps != steps) {
    throw Error("the animated replay of " + config.name + " with seed " + std::to_string(run_seed) + " took " +
                std::to_string(episode.outcome().steps) + " steps where its run took " + std::to_string(steps));
  }
  result.outcome = episode.outcome();
  result.frames = gif.frames();
  result.width = painter.width();
  result.height = painter.height();
  result.gif = gif.encode();
  return result;
}

}  // namespace

EpisodeAnimation animateEpisode(const Problem& problem, const Grid& grid, const agents::AgentConfig& config,
                                const EpisodeOptions& options, std::uint64_t run_seed,
                                const AnimationOptions& animation, const StopCheck& stop) {
  animation.validate();
  agents::EpisodeRunner runner(config, options);
  std::unique_ptr<agents::Agent> agent = agents::makeAgent(config);
  // A first run counts the steps, so the frames can be spread over the episode before any is drawn, and finds a
  // loop's cycle, marked from the step the loop began.
  const EpisodeOutcome first = runner.run(problem, grid, *agent, run_seed);
  Grid space;
  agent->reset(agents::episodeInfo(problem, grid, config, run_seed, options.connectivity,
                                   &motionGrid(grid, options.robot_radius, &space)));
  return drawEpisode(problem, grid, config, options, run_seed, first.steps,
                     [&agent](const Scan& scan) { return std::optional<Action>(agent->act(scan)); }, nullptr,
                     animation, cycleMarks(problem, first), stop);
}

EpisodeAnimation animateRecordedEpisode(const Problem& problem, const Grid& grid, const agents::AgentConfig& config,
                                        const EpisodeOptions& options, std::uint64_t run_seed,
                                        const std::vector<Action>& actions, const std::string& reason,
                                        const AnimationOptions& animation, const StopCheck& stop) {
  animation.validate();
  const char* end_reason = reason::reasonNamed(reason);
  if (end_reason == nullptr) throw InvalidArgument("reason", "not a reason an episode ends for: '" + reason + "'");
  // The world ends a run on the goal, at the budget or at the action limit: the actions must take the replay
  // there by themselves.
  if (reason == reason::kGoalReached || reason == reason::kBudgetExhausted || reason == reason::kActionLimit) {
    end_reason = nullptr;
  }
  std::size_t next = 0;
  const NextAction recorded = [&](const Scan&) {
    return next < actions.size() ? std::optional<Action>(actions[next++]) : std::nullopt;
  };
  const int steps = static_cast<int>(actions.size());
  // A first play, drawn in two frames, finds a loop's cycle (as animateEpisode's first run does).
  AnimationOptions sketch = animation;
  sketch.max_frames = 2;
  const EpisodeOutcome first =
      drawEpisode(problem, grid, config, options, run_seed, steps, recorded, end_reason, sketch, {}, stop).outcome;
  next = 0;
  return drawEpisode(problem, grid, config, options, run_seed, steps, recorded, end_reason, animation,
                     cycleMarks(problem, first), stop);
}

}  // namespace simulator
}  // namespace ppp
