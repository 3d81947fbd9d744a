#include "scan_batch_checks.hpp"

#include "ppp_core/error.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {

namespace {

std::string cellText(Cell c) { return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")"; }

}  // namespace

void requireOnGrid(Cell cell, int width, int height, const char* field) {
  if (cell.x < 0 || cell.y < 0 || cell.x >= width || cell.y >= height) {
    throw InvalidArgument(field, cellText(cell) + " is off the " + std::to_string(width) + "x" +
                                     std::to_string(height) + " map");
  }
}

std::string checkBatchShape(const ppp_msgs::ScanBatch& batch, bool reads_window, std::string* what) {
  const std::size_t n = batch.episodes.size();
  if (batch.steps.size() != n || batch.positions.size() != n || batch.bumped.size() != n) {
    *what = "episodes, steps, positions and bumped differ in length (" + std::to_string(n) + ", " +
            std::to_string(batch.steps.size()) + ", " + std::to_string(batch.positions.size()) + ", " +
            std::to_string(batch.bumped.size()) + ")";
    return "batch";
  }
  if (batch.range < 1 || batch.range > kMaxSensorRange) {
    *what = "range " + std::to_string(batch.range) + " is outside [1, " + std::to_string(kMaxSensorRange) + "]";
    return "range";
  }
  const std::size_t window = static_cast<std::size_t>(2 * batch.range + 1) * (2 * batch.range + 1);
  if (reads_window && batch.cells.size() != n * window) {
    *what = "expected " + std::to_string(n) + " windows of " + std::to_string(window) + " cells, got " +
            std::to_string(batch.cells.size()) + " cells";
    return "cells";
  }
  return "";
}

ParsedStart parseEpisodeStart(const ppp_msgs::EpisodeStart& start) {
  const auto side_ok = [](std::uint32_t side) { return side >= kMinGridSide && side <= kMaxGridSide; };
  if (!side_ok(start.width) || !side_ok(start.height)) {
    throw InvalidArgument("size", "the map size " + std::to_string(start.width) + "x" +
                                      std::to_string(start.height) + " is outside [" +
                                      std::to_string(kMinGridSide) + ", " + std::to_string(kMaxGridSide) + "]");
  }
  ParsedStart parsed;
  EpisodeInfo& info = parsed.info;
  info.width = static_cast<int>(start.width);
  info.height = static_cast<int>(start.height);
  info.start = toCell(start.start);
  info.goal = toCell(start.goal);
  info.seed = start.agent_seed;
  requireOnGrid(info.start, info.width, info.height, "start");
  requireOnGrid(info.goal, info.width, info.height, "goal");
  if (start.prior_map.empty()) return parsed;
  const std::size_t cells = static_cast<std::size_t>(info.width) * static_cast<std::size_t>(info.height);
  if (start.prior_map.size() != cells) {
    throw InvalidArgument("prior_map", "expected " + std::to_string(cells) + " cells for a " +
                                           std::to_string(info.width) + "x" + std::to_string(info.height) +
                                           " map, got " + std::to_string(start.prior_map.size()));
  }
  parsed.prior = std::make_unique<Grid>(info.width, info.height);
  for (std::size_t i = 0; i < cells; ++i) {
    const std::int8_t value = start.prior_map[i];
    if (value != kScanFree && value != kScanObstacle) {
      throw InvalidArgument("prior_map", "cell " + std::to_string(i) + " is " + std::to_string(value) +
                                             "; expected FREE (0) or OBSTACLE (100)");
    }
    parsed.prior->setObstacle(parsed.prior->cellAt(static_cast<int>(i)), value == kScanObstacle);
  }
  return parsed;
}

}  // namespace agents
}  // namespace ppp
