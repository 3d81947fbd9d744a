// Draws MRPT's holonomic methods driven in continuous motion on the traps found with one-cell steps, as one PNG,
// each tile the disc's trajectory for 300 s and the robot at its last pose:
//   reactive_trap_pictures OUT.png              the four traps of mrpt_reactive_continuous_test: a row per trap, a
//                                               column per method (ND, VFF, FullEval)
//   reactive_trap_pictures --hunted ND OUT.png  the grid hunt's shrunk traps of ND (or VFF), each driven by the
//                                               method whose hunt found it (mrpt_hunted_traps_test), four a row
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "hunted_traps.hpp"
#include "ppp_core/picture.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/trajectory_picture.hpp"
#include "reactive_drive.hpp"

namespace {

using namespace ppp;

/// One tile: a method driven on a drawn map, logged under `name`.
struct Tile {
  std::string name;
  std::vector<std::string> picture;
  std::string method;
};

/// The tiles drawn `columns` a row, 8 white pixels apart, as PNG bytes.
std::string drawSheet(const std::vector<Tile>& tiles, int columns) {
  constexpr int kGap = 8;
  const PictureOptions options;
  int tile_width = 0, tile_height = 0;
  for (const Tile& tile : tiles) {
    tile_width = std::max(tile_width, pictureWidth(static_cast<int>(tile.picture.front().size()), options));
    tile_height = std::max(tile_height, pictureHeight(static_cast<int>(tile.picture.size()), options));
  }
  const int rows = (static_cast<int>(tiles.size()) + columns - 1) / columns;
  const int width = columns * tile_width + (columns - 1) * kGap;
  const int height = rows * tile_height + (rows - 1) * kGap;
  std::vector<std::uint8_t> sheet(static_cast<std::size_t>(width) * height * 3, 255);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const int row = static_cast<int>(i) / columns, column = static_cast<int>(i) % columns;
    const Problem problem = planners::test::pictureProblem(tiles[i].picture);
    const ContinuousOutcome outcome = planners::test::driveReactive(
        problem, tiles[i].method, planners::test::kTrapRadius, planners::test::kTrapPeriods);
    std::printf("%s %s: %s after %d control periods\n", tiles[i].name.c_str(), tiles[i].method.c_str(),
                outcome.reason, outcome.steps);
    const std::vector<std::uint8_t> tile =
        renderTrajectoryRgb(problem, outcome.poses, 1.0, planners::test::kTrapRadius, options);
    const int tw = pictureWidth(problem.width, options), th = pictureHeight(problem.height, options);
    for (int y = 0; y < th; ++y) {
      const int sy = row * (tile_height + kGap) + y;
      std::copy_n(tile.begin() + static_cast<std::ptrdiff_t>(y) * tw * 3, tw * 3,
                  sheet.begin() + (static_cast<std::ptrdiff_t>(sy) * width + column * (tile_width + kGap)) * 3);
    }
  }
  return encodePng(sheet, width, height);
}

}  // namespace

int main(int argc, char** argv) {
  const bool hunted = argc == 4 && std::string(argv[1]) == "--hunted";
  if (argc != 2 && !hunted) {
    std::fprintf(stderr, "usage: reactive_trap_pictures OUT.png | reactive_trap_pictures --hunted ND|VFF OUT.png\n");
    return 2;
  }
  std::vector<Tile> tiles;
  int columns = 3;
  if (hunted) {
    const std::string method = argv[2];
    int number = 0;
    for (const planners::test::HuntedTrap& trap : planners::test::huntedTraps()) {
      if (trap.method == method) {
        tiles.push_back({"trap " + std::to_string(++number), planners::test::huntedTrapPicture(trap), method});
      }
    }
    if (tiles.empty()) {
      std::fprintf(stderr, "reactive_trap_pictures: no hunted traps of '%s' (ND or VFF)\n", method.c_str());
      return 2;
    }
    columns = 4;
  } else {
    for (const planners::test::ReactiveTrap& trap : planners::test::reactiveTraps()) {
      for (const std::string method : {"ND", "VFF", "FullEval"}) tiles.push_back({trap.name, trap.picture, method});
    }
  }
  try {
    ppp::writeFileAtomically(argv[argc - 1], drawSheet(tiles, columns));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reactive_trap_pictures: %s\n", e.what());
    return 1;
  }
  return 0;
}
