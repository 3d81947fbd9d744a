#pragma once
// The minimal traps the grid hunts of MRPT's holonomic methods found (config/planner_hunt.yaml's failure hunt of
// 1,000 matings through mrpt_reactive_node, each failing PPP shrunk through its bridge, duplicates dropped):
// ND's 8 with the default goal in the corner, VFF's 11 with the goal at (14, 12). The maps are those of
// docs/images/nd-traps.png and vff-traps.png, 20x20 cells of 1 m, the start at (0, 0).
#include <string>
#include <utility>
#include <vector>

namespace ppp {
namespace planners {
namespace test {

/// A shrunk trap: the method whose hunt found it, its goal cell and its obstacle cells (x right, y down).
struct HuntedTrap {
  std::string method;
  std::pair<int, int> goal;
  std::vector<std::pair<int, int>> obstacles;
};

/// ND's 8 traps, then VFF's 11, in the pictures' order (left to right, top to bottom).
inline const std::vector<HuntedTrap>& huntedTraps() {
  static const std::vector<HuntedTrap> traps = {
      {"ND", {19, 19}, {{18, 18}}},
      {"ND", {19, 19}, {{9, 1}, {8, 2}, {7, 3}, {6, 4}, {5, 5}, {4, 6}, {3, 7}, {2, 8}, {1, 9}}},
      {"ND", {19, 19},
       {{13, 2}, {11, 3}, {13, 3}, {10, 4}, {9, 5}, {8, 6}, {7, 7}, {6, 8}, {5, 9}, {4, 10}, {3, 11}, {2, 12}}},
      {"ND", {19, 19}, {{12, 12}, {9, 14}, {10, 14}, {11, 14}, {12, 14}}},
      {"ND", {19, 19}, {{10, 10}, {10, 11}, {10, 12}, {10, 13}, {8, 15}, {9, 15}, {10, 15}}},
      {"ND", {19, 19},
       {{10, 0}, {11, 3}, {10, 4}, {9, 5}, {8, 6}, {7, 7}, {6, 8}, {5, 9}, {4, 10}, {3, 11}, {2, 12}}},
      {"ND", {19, 19},
       {{8, 8}, {8, 9}, {9, 12}, {8, 13}, {7, 14}, {6, 15}, {8, 15}, {8, 16}, {8, 17}, {8, 18}}},
      {"ND", {19, 19},
       {{11, 1}, {11, 3}, {10, 4}, {9, 5}, {8, 6}, {7, 7}, {6, 8}, {5, 9}, {4, 10}, {3, 11}, {2, 12}}},
      {"VFF", {14, 12}, {{13, 10}, {12, 11}}},
      {"VFF", {14, 12}, {{11, 8}, {11, 9}, {11, 10}, {11, 11}}},
      {"VFF", {14, 12}, {{9, 4}, {7, 5}, {9, 5}}},
      {"VFF", {14, 12}, {{15, 11}, {13, 13}}},
      {"VFF", {14, 12}, {{12, 8}, {11, 9}, {10, 10}}},
      {"VFF", {14, 12}, {{4, 2}, {4, 3}, {4, 4}, {3, 5}}},
      {"VFF", {14, 12}, {{3, 2}, {3, 4}, {3, 5}}},
      {"VFF", {14, 12}, {{13, 10}, {13, 11}}},
      {"VFF", {14, 12}, {{3, 1}, {1, 2}, {2, 2}}},
      {"VFF", {14, 12}, {{1, 0}, {1, 1}}},
      {"VFF", {14, 12}, {{5, 2}, {5, 3}, {5, 4}, {5, 5}, {5, 6}, {5, 7}}},
  };
  return traps;
}

/// `trap` drawn as reactive_traps.hpp draws its traps ('#' obstacles, S start, G goal).
inline std::vector<std::string> huntedTrapPicture(const HuntedTrap& trap) {
  std::vector<std::string> picture(20, std::string(20, '.'));
  for (const auto& [x, y] : trap.obstacles) picture[y][x] = '#';
  picture[0][0] = 'S';
  picture[trap.goal.second][trap.goal.first] = 'G';
  return picture;
}

}  // namespace test
}  // namespace planners
}  // namespace ppp
