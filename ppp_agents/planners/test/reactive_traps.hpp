#pragma once
// The traps of MRPT's holonomic methods found with one-cell steps, shared by the grid tests that replay them
// (mrpt_reactive_navigator_test) and the continuous ones that re-judge them (mrpt_reactive_continuous_test).
#include <stdexcept>
#include <string>
#include <vector>

namespace ppp {
namespace planners {
namespace test {

/// A trap of MRPT's holonomic methods found on the grid, drawn ('#' obstacles, S start, G goal, 1 m cells).
struct ReactiveTrap {
  std::string name;
  std::vector<std::string> picture;
};

/// The traps mrpt_reactive_navigator_test replays with one-cell steps, in its order: a goal in the map's corner
/// (VFF, FullEval), a U facing away from the goal (VFF, ND), the pocket of two diagonal cells before the goal
/// (VFF), one obstacle cell diagonal to a goal in the corner (ND).
inline const std::vector<ReactiveTrap>& reactiveTraps() {
  static const std::vector<ReactiveTrap> traps = {
      {"corner", {"S.......", "........", "........", "........", "........", "........", "........", ".......G"}},
      {"u", {"....G....", ".........", "..#####..", "..#...#..", "..#.S.#..", "..#...#..", "........."}},
      {"pocket", {"S.......", "........", "........", "........", ".....#..", "....#...", "......G.", "........"}},
      {"one_cell", {"S.....", "......", "......", "......", "....#.", ".....G"}},
  };
  return traps;
}

/// The picture of the trap named `name`. @throws std::out_of_range for a name none has.
inline const std::vector<std::string>& trapPicture(const std::string& name) {
  for (const ReactiveTrap& trap : reactiveTraps()) {
    if (trap.name == name) return trap.picture;
  }
  throw std::out_of_range("no trap " + name);
}

}  // namespace test
}  // namespace planners
}  // namespace ppp
