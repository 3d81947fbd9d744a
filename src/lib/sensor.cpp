#include "ppp_core/sensor.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/visibility.hpp"
#include "ppp_core/window_atlas.hpp"
#include "ppp_core/window_mask.hpp"

namespace ppp {

namespace {

/// A uniform 53-bit number from (seed, step, index), independent of any call order: the noise draw of a cell
/// is this times 2^-53, in [0, 1).
std::uint64_t noiseBits(std::uint64_t seed, int step, int index) {
  std::uint64_t z = seed ^ (static_cast<std::uint64_t>(step) * 0x9E3779B97F4A7C15ULL) ^
                    (static_cast<std::uint64_t>(index) * 0xD1B54A32D192ED03ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return z >> 11;
}

/// noiseBits() of window cells 0 .. count-1 at `step`, in 64-bit lanes only so that the vectoriser hashes
/// eight (AVX-512) or four (AVX2) cells at once. Built for those instruction sets as well as the baseline,
/// chosen when the library loads; the draws are the same on every one.
__attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default"))) void noiseDraws(
    std::uint64_t seed, int step, int count, std::uint64_t* draws) {
  for (int i = 0; i < count; ++i) draws[i] = noiseBits(seed, step, i);
}

}  // namespace

void SensorOptions::validate() const {
  if (range < 1 || range > kMaxSensorRange) {
    throw InvalidArgument("sensor_range", "expected an integer in [1, " + std::to_string(kMaxSensorRange) +
                                              "], got " + std::to_string(range));
  }
  if (!(noise >= 0.0 && noise <= 1.0)) {
    throw InvalidArgument("sensor_noise", "expected a probability in [0, 1], got " + std::to_string(noise));
  }
}

SensorModel::SensorModel(const SensorOptions& options) : options_(options) {
  options_.validate();
  // A cell flips when its draw bits * 2^-53 < noise, i.e. (both sides scaled by 2^53, exactly) when the bits
  // are below ceil(noise * 2^53).
  noise_threshold_ = static_cast<std::uint64_t>(std::ceil(options_.noise * 0x1.0p53));
  const int r = options_.range;
  const int s = side();
  blockers_.resize(static_cast<std::size_t>(s) * s);
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      for (Cell c : cellsCrossed(Cell{0, 0}, Cell{dx, dy})) {
        blockers_[(dy + r) * s + (dx + r)].push_back((c.y + r) * s + (c.x + r));
      }
    }
  }
  if (s * s <= 64) {
    for (const auto& blockers : blockers_) {
      std::uint64_t mask = 0;
      for (int b : blockers) mask |= std::uint64_t{1} << b;
      blocker_masks_.push_back(mask);
    }
  }
}

void SensorModel::scan(const Grid& grid, Cell position, std::uint64_t noise_seed, int step,
                       std::int8_t* window) const {
  see(grid, position, window);
  addNoise(noise_seed, step, window);
}

void SensorModel::see(const Grid& grid, Cell position, std::int8_t* window) const {
  const int r = options_.range;
  const int s = side();
  // Physical truth first: the line of sight depends on the real obstacles.
  std::array<std::int8_t, kMaxScanCells> truth;
  std::uint64_t obstacles = 0;  // bit i: window cell i is an obstacle (windows of at most 64 cells)
  const std::uint8_t* cells = grid.cells().data();
  const int x0 = std::max(position.x - r, 0) - position.x + r;  // first window column on the grid
  const int x1 = std::min(position.x + r, grid.width() - 1) - position.x + r;  // last one
  for (int row = 0, i = 0; row < s; ++row, i += s) {
    const int y = position.y - r + row;
    if (y < 0 || y >= grid.height() || x0 > x1) {
      std::fill(truth.begin() + i, truth.begin() + i + s, kScanOutOfBounds);
      continue;
    }
    std::fill(truth.begin() + i, truth.begin() + i + x0, kScanOutOfBounds);
    const std::uint8_t* grid_row = cells + static_cast<std::size_t>(y) * grid.width();
    for (int col = x0; col <= x1; ++col) {
      const bool obstacle = grid_row[position.x - r + col] != 0;
      truth[i + col] = obstacle ? kScanObstacle : kScanFree;
      if (obstacle && i + col < 64) obstacles |= std::uint64_t{1} << (i + col);
    }
    std::fill(truth.begin() + i + x1 + 1, truth.begin() + i + s, kScanOutOfBounds);
  }
  if (!blocker_masks_.empty()) {
    for (int i = 0; i < s * s; ++i) window[i] = (obstacles & blocker_masks_[i]) == 0 ? truth[i] : kScanUnknown;
    return;
  }
  for (int i = 0; i < s * s; ++i) {
    bool visible = true;
    for (int blocker : blockers_[i]) visible = visible && truth[blocker] != kScanObstacle;
    window[i] = visible ? truth[i] : kScanUnknown;
  }
}

std::uint64_t SensorModel::noiseFlips(std::uint64_t noise_seed, int step) const {
  if (options_.noise <= 0.0) return 0;
  const int centre = options_.range * side() + options_.range;
  const int count = side() * side();
  if (count > kMaxBitWindowCells) {
    throw InvalidArgument("sensor_range", "noise flips as a mask need a window of at most 64 cells, got " +
                                              std::to_string(count));
  }
  std::array<std::uint64_t, kMaxBitWindowCells> draws;
  noiseDraws(noise_seed, step, count, draws.data());
  std::uint64_t flips = 0;
  for (int i = 0; i < count; ++i) flips |= static_cast<std::uint64_t>(draws[i] < noise_threshold_) << i;
  return flips & ~(std::uint64_t{1} << centre);
}

void SensorModel::addNoise(std::uint64_t noise_seed, int step, std::int8_t* window) const {
  if (options_.noise <= 0.0) return;
  if (side() * side() <= kMaxBitWindowCells) return addNoise(noiseFlips(noise_seed, step), window);
  // Branch-free: a flip turns free (0) into obstacle (100) and back by XOR.
  const int centre = options_.range * side() + options_.range;
  for (int i = 0; i < side() * side(); ++i) {
    const std::int8_t value = window[i];
    const bool sensed = i != centre && (value == kScanFree || value == kScanObstacle);
    const bool flip = sensed & (noiseBits(noise_seed, step, i) < noise_threshold_);
    window[i] = static_cast<std::int8_t>(value ^ (flip ? kScanFree ^ kScanObstacle : 0));
  }
}

void SensorModel::addNoise(std::uint64_t flips, std::int8_t* window) {
  for (std::uint64_t f = flips; f != 0; f &= f - 1) {
    std::int8_t& value = window[__builtin_ctzll(f)];
    if (value == kScanFree || value == kScanObstacle) value = static_cast<std::int8_t>(value ^ (kScanFree ^ kScanObstacle));
  }
}

Scan::Scan(const SensorModel& sensor, const Grid& grid, Cell position, Cell goal, bool bumped, int step,
           std::uint64_t noise_seed, const WindowAtlas* windows)
    : sensor_(&sensor),
      grid_(&grid),
      windows_(windows),
      noise_seed_(noise_seed),
      position_(position),
      goal_(goal),
      bumped_(bumped),
      step_(step),
      range_(sensor.options().range) {}

Scan::Scan(int range, const std::vector<std::int8_t>& cells, Cell position, Cell goal, bool bumped, int step)
    : Scan(range, cells.data(), cells.size(), position, goal, bumped, step) {}

Scan::Scan(int range, const std::int8_t* cells, std::size_t count, Cell position, Cell goal, bool bumped, int step)
    : position_(position), goal_(goal), bumped_(bumped), step_(step), range_(range), filled_(true) {
  if (range < 1 || range > kMaxSensorRange) throw InvalidArgument("range", "outside [1, 7]: " + std::to_string(range));
  const std::size_t expected = static_cast<std::size_t>(2 * range + 1) * (2 * range + 1);
  if (count != expected) {
    throw InvalidArgument("cells", "expected " + std::to_string(expected) + " window cells for range " +
                                       std::to_string(range) + ", got " + std::to_string(count));
  }
  std::copy(cells, cells + count, cells_.begin());
}

Scan::Scan(int range, WindowBits bits, Cell position, Cell goal, bool bumped, int step)
    : received_bits_(true),
      bits_(bits),
      position_(position),
      goal_(goal),
      bumped_(bumped),
      step_(step),
      range_(range) {
  if (range < 1 || range > kMaxSensorRange) throw InvalidArgument("range", "outside [1, 7]: " + std::to_string(range));
  if ((2 * range + 1) * (2 * range + 1) > kMaxBitWindowCells) {
    throw InvalidArgument("range", "a window of range " + std::to_string(range) + " has more than " +
                                       std::to_string(kMaxBitWindowCells) + " cells: give its cells, not one mask");
  }
}

std::int8_t Scan::atCell(Cell c) const {
  const int dx = c.x - position_.x;
  const int dy = c.y - position_.y;
  if (dx < -range_ || dx > range_ || dy < -range_ || dy > range_) return kScanUnknown;
  return at(dx, dy);
}

std::uint64_t Scan::flips() const {
  if (!flips_known_) {
    flips_ = sensor_->noiseFlips(noise_seed_, step_);
    flips_known_ = true;
  }
  return flips_;
}

bool Scan::bits(WindowBits* out) const {
  if (received_bits_) {
    *out = bits_;
    return true;
  }
  if (windows_ == nullptr) return false;
  const WindowBits* seen = windows_->bits(position_);
  if (seen == nullptr) return false;
  *out = *seen;
  SensorModel::addNoise(flips(), out);
  return true;
}

void Scan::fill() const {
  if (received_bits_) {
    std::uint64_t free = 0, obstacle = 0;
    packWindow(bits_, &free, &obstacle);  // the wire's two masks, which unpackWindow reads
    unpackWindow(&free, &obstacle, range_, cells_.data());
  } else if (windows_ != nullptr) {
    const std::int8_t* seen = windows_->window(position_);
    std::copy(seen, seen + windows_->cells(), cells_.begin());
    if (windows_->bits(position_) != nullptr) {
      SensorModel::addNoise(flips(), cells_.data());  // the mask bits() uses too, drawn once per scan
    } else {
      sensor_->addNoise(noise_seed_, step_, cells_.data());
    }
  } else {
    sensor_->scan(*grid_, position_, noise_seed_, step_, cells_.data());
  }
  filled_ = true;
}

}  // namespace ppp
