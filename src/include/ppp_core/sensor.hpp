#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "ppp_core/grid.hpp"

namespace ppp {

class WindowAtlas;

/// Scan cell values (the same numbers as ppp_msgs/ScanBatch).
constexpr std::int8_t kScanUnknown = -1;      ///< Not in line of sight.
constexpr std::int8_t kScanFree = 0;          ///< Seen free.
constexpr std::int8_t kScanObstacle = 100;    ///< Seen obstacle.
constexpr std::int8_t kScanOutOfBounds = -2;  ///< Beyond the edge of the map.

/// Largest sensor range: a (2*7+1)^2 = 225-cell window.
constexpr int kMaxSensorRange = 7;
/// Cells in the largest window.
constexpr int kMaxScanCells = (2 * kMaxSensorRange + 1) * (2 * kMaxSensorRange + 1);

/// Most window cells kept as bit masks (WindowBits): windows of sensor range 3 or less.
constexpr int kMaxBitWindowCells = 64;

/// A scan window of at most kMaxBitWindowCells cells as masks, bit i for window cell i (row-major): reported free,
/// reported obstacle, reported off the map; a cell in none is unknown.
struct WindowBits {
  std::uint64_t free = 0;      ///< Cells reported free.
  std::uint64_t obstacle = 0;  ///< Cells reported obstacles.
  std::uint64_t off_map = 0;   ///< Cells reported off the map (kScanOutOfBounds).
};

/// The robot's range sensor: which cells it reports and how reliably.
struct SensorOptions {
  int range = 2;       ///< Chebyshev radius of the square window (2: 5x5).
  double noise = 0.0;  ///< Probability that a sensed free/obstacle cell is reported flipped.
  /// @throws InvalidArgument("sensor_range" or "sensor_noise", ...) when out of range.
  void validate() const;
};

/// Computes scans: cells within the window that are in line of sight of the robot's cell (the perfect-sensor
/// rule of lineOfSight()), each free / obstacle / out of bounds, others unknown. Noise flips a sensed on-grid
/// cell (never the robot's own) with probability `noise`, decided by a hash of (noise seed, step, cell), so
/// a scan does not depend on the order in which cells are read or on where it is computed.
class SensorModel {
 public:
  /// Precomputes the line-of-sight blockers of every window offset. @throws InvalidArgument for bad options.
  explicit SensorModel(const SensorOptions& options);
  /// The options in effect.
  const SensorOptions& options() const { return options_; }
  /// Side of the window, 2 * range + 1.
  int side() const { return 2 * options_.range + 1; }
  /// Fills `window` (side*side cells, row-major from (-range, -range), x fastest) as seen from `position`:
  /// see() then addNoise().
  void scan(const Grid& grid, Cell position, std::uint64_t noise_seed, int step, std::int8_t* window) const;
  /// Fills `window` with what a noiseless sensor reports from `position`.
  void see(const Grid& grid, Cell position, std::int8_t* window) const;
  /// Flips the sensed cells of a noiseless `window` that this sensor's noise flips at `step` of a run.
  void addNoise(std::uint64_t noise_seed, int step, std::int8_t* window) const;
  /// For windows of at most kMaxBitWindowCells cells: bit i set when the noise at `step` of a run flips window
  /// cell i if it is sensed (never the robot's own cell); 0 without noise. addNoise() flips exactly these.
  /// @throws InvalidArgument("sensor_range") for a larger window with noise.
  std::uint64_t noiseFlips(std::uint64_t noise_seed, int step) const;
  /// Flips the sensed cells of a noiseless `window` that `flips` (noiseFlips()) names.
  static void addNoise(std::uint64_t flips, std::int8_t* window);
  /// Flips the sensed cells of noiseless window masks that `flips` (noiseFlips()) names.
  static void addNoise(std::uint64_t flips, WindowBits* bits) {
    const std::uint64_t flipped = flips & (bits->free | bits->obstacle);
    bits->free ^= flipped;
    bits->obstacle ^= flipped;
  }

 private:
  SensorOptions options_;
  std::uint64_t noise_threshold_ = 0;  // a cell flips when its noise draw is below this
  std::vector<std::vector<int>> blockers_;  // per window index: window indices that must be free
  std::vector<std::uint64_t> blocker_masks_;  // the same as bit masks, for windows of at most 64 cells
};

/// What an agent receives each step: its cell, the goal, whether its last move bumped, and the scan window.
/// In-process the window is computed on first read (agents that never look cost nothing); from a message it
/// is filled in advance. Either way the values are the same.
class Scan {
 public:
  /// A scan computed lazily by `sensor` from `grid`, or copied from `windows` (the grid's atlas at the sensor's
  /// range) with the sensor's noise added; all must outlive the scan.
  Scan(const SensorModel& sensor, const Grid& grid, Cell position, Cell goal, bool bumped, int step,
       std::uint64_t noise_seed, const WindowAtlas* windows = nullptr);
  /// A scan from received window cells. @throws InvalidArgument when the count is not (2*range+1)^2.
  Scan(int range, const std::vector<std::int8_t>& cells, Cell position, Cell goal, bool bumped, int step);
  /// A scan from `count` received window cells at `cells`. @throws InvalidArgument as above.
  Scan(int range, const std::int8_t* cells, std::size_t count, Cell position, Cell goal, bool bumped, int step);
  /// A scan from a received window of at most kMaxBitWindowCells cells as masks. @throws InvalidArgument for a
  /// range whose window is larger.
  Scan(int range, WindowBits bits, Cell position, Cell goal, bool bumped, int step);

  Cell position() const { return position_; }  ///< The agent's cell (grid coordinates, y down).
  Cell goal() const { return goal_; }          ///< The goal cell.
  bool bumped() const { return bumped_; }      ///< True when the previous action hit an obstacle or the edge.
  int step() const { return step_; }           ///< Steps taken so far in the episode.
  int range() const { return range_; }         ///< Window radius.
  /// The reported value at offset (dx, dy) from the agent, |dx|, |dy| <= range.
  std::int8_t at(int dx, int dy) const {
    const int i = (dy + range_) * (2 * range_ + 1) + (dx + range_);
    if (received_bits_) return bitCell(i);  // a cell or two of masks is read without building every cell
    if (!filled_) fill();
    return cells_[i];
  }
  /// The reported value of an absolute cell, or kScanUnknown outside the window.
  std::int8_t atCell(Cell c) const;
  /// All window cells, row-major; kMaxScanCells bytes may be read from it (those past the window are
  /// unspecified), so that a reader may load whole words.
  const std::int8_t* cells() const {
    if (!filled_) fill();
    return cells_.data();
  }
  /// The window as bit masks, when the scan came as masks or from an atlas that keeps them (windows of at most
  /// kMaxBitWindowCells cells): the same values as cells(), without building the cells. False otherwise.
  bool bits(WindowBits* out) const;

 private:
  void fill() const;
  /// Window cell `i` of the received masks.
  std::int8_t bitCell(int i) const {
    const std::uint64_t bit = std::uint64_t{1} << i;
    return (bits_.off_map & bit) != 0    ? kScanOutOfBounds
           : (bits_.free & bit) != 0     ? kScanFree
           : (bits_.obstacle & bit) != 0 ? kScanObstacle
                                         : kScanUnknown;
  }
  /// The noise flips of this scan (SensorModel::noiseFlips), computed once.
  std::uint64_t flips() const;

  const SensorModel* sensor_ = nullptr;
  const Grid* grid_ = nullptr;
  const WindowAtlas* windows_ = nullptr;
  bool received_bits_ = false;  // the window came as masks (bits_)
  WindowBits bits_;
  std::uint64_t noise_seed_ = 0;
  Cell position_;
  Cell goal_;
  bool bumped_ = false;
  int step_ = 0;
  int range_ = 0;
  mutable bool filled_ = false;
  mutable bool flips_known_ = false;
  mutable std::uint64_t flips_ = 0;
  mutable std::array<std::int8_t, kMaxScanCells> cells_;  // only the first (2*range+1)^2 are used, once filled
};

}  // namespace ppp
