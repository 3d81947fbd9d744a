// Draws MRPT's holonomic methods driven in continuous motion on the traps found with one-cell steps
// (mrpt_reactive_continuous_test), as one PNG: a row per trap, a column per method (ND, VFF, FullEval), each the
// disc's trajectory for 300 s and the robot at its last pose.
//   reactive_trap_pictures OUT.png
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "ppp_core/picture.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/trajectory_picture.hpp"
#include "reactive_drive.hpp"

int main(int argc, char** argv) {
  using namespace ppp;
  if (argc != 2) {
    std::fprintf(stderr, "usage: reactive_trap_pictures OUT.png\n");
    return 2;
  }
  const std::vector<std::string> methods = {"ND", "VFF", "FullEval"};
  const PictureOptions options;
  constexpr int kGap = 8;  // white pixels between pictures
  int tile_width = 0, tile_height = 0;
  for (const planners::test::ReactiveTrap& trap : planners::test::reactiveTraps()) {
    tile_width = std::max(tile_width, pictureWidth(static_cast<int>(trap.picture.front().size()), options));
    tile_height = std::max(tile_height, pictureHeight(static_cast<int>(trap.picture.size()), options));
  }
  const int columns = static_cast<int>(methods.size());
  const int rows = static_cast<int>(planners::test::reactiveTraps().size());
  const int width = columns * tile_width + (columns - 1) * kGap;
  const int height = rows * tile_height + (rows - 1) * kGap;
  std::vector<std::uint8_t> sheet(static_cast<std::size_t>(width) * height * 3, 255);
  try {
    for (int row = 0; row < rows; ++row) {
      const planners::test::ReactiveTrap& trap = planners::test::reactiveTraps()[row];
      const Problem problem = planners::test::pictureProblem(trap.picture);
      for (int column = 0; column < columns; ++column) {
        const ContinuousOutcome outcome = planners::test::driveReactive(
            problem, methods[column], planners::test::kTrapRadius, planners::test::kTrapPeriods);
        std::printf("%s %s: %s after %d control periods\n", trap.name.c_str(), methods[column].c_str(),
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
    }
    writeFileAtomically(argv[1], encodePng(sheet, width, height));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reactive_trap_pictures: %s\n", e.what());
    return 1;
  }
  return 0;
}
