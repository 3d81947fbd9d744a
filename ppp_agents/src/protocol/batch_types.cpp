#include "ppp_agents/protocol/batch_types.hpp"

#include "ppp_core/error.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace protocol {

std::vector<std::int8_t> priorMapCells(const Grid& grid) {
  std::vector<std::int8_t> cells;
  cells.reserve(grid.cells().size());
  for (std::uint8_t cell : grid.cells()) cells.push_back(cell != 0 ? kScanObstacle : kScanFree);
  return cells;
}

std::unique_ptr<Grid> priorGrid(const EpisodeStart& start) {
  if (start.prior_map.empty()) return nullptr;
  const std::size_t cells = static_cast<std::size_t>(start.width) * static_cast<std::size_t>(start.height);
  if (start.prior_map.size() != cells) {
    throw InvalidArgument("prior_map", "expected " + std::to_string(cells) + " cells for a " +
                                           std::to_string(start.width) + "x" + std::to_string(start.height) +
                                           " map, got " + std::to_string(start.prior_map.size()));
  }
  auto grid = std::make_unique<Grid>(start.width, start.height);
  for (std::size_t i = 0; i < cells; ++i) {
    const std::int8_t value = start.prior_map[i];
    if (value != kScanFree && value != kScanObstacle) {
      throw InvalidArgument("prior_map", "cell " + std::to_string(i) + " is " + std::to_string(value) +
                                             "; expected FREE (0) or OBSTACLE (100)");
    }
    grid->setObstacle(grid->cellAt(static_cast<int>(i)), value == kScanObstacle);
  }
  return grid;
}

agents::EpisodeInfo episodeInfo(const EpisodeStart& start, const Grid* prior) {
  return agents::EpisodeInfo{start.width, start.height, start.start, start.goal, start.agent_seed, prior,
                             start.connectivity};
}

void requireOnGrid(Cell cell, int width, int height, const char* field) {
  if (cell.x < 0 || cell.y < 0 || cell.x >= width || cell.y >= height) {
    throw InvalidArgument(field, cellText(cell) + " is off the " +
                                     std::to_string(width) + "x" + std::to_string(height) + " map");
  }
}

}  // namespace protocol
}  // namespace ppp
