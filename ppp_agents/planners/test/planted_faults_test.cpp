// The zoo planner's planted faults: each plans as the optimistic planner does on an open map, and each fires on a
// small map drawn for it, where the right route and the faulty planner's answer are worked out by hand.
#include "planted_faults.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "map_picture.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {
namespace {

using Cells = std::vector<Cell>;
using Picture = std::vector<std::string>;

/// A fresh faulty planner's route from S to G of a drawn map.
Cells plan(const std::string& fault, const Picture& picture, int limit = 0) {
  FaultyPlanner planner(fault, limit);
  return planner.plan(test::mapPicture(picture), test::markedCell(picture, 'S'), test::markedCell(picture, 'G'));
}

Cells optimisticPlan(const Picture& picture) {
  return optimisticAStar(test::mapPicture(picture), test::markedCell(picture, 'S'), test::markedCell(picture, 'G'));
}

TEST(PlantedFaultsTest, EveryFaultPlansTheOptimisticRouteOnAnOpenMap) {
  const Picture open = {"S.....", "......", "......", "......", "......", ".....G"};
  ASSERT_EQ(optimisticPlan(open).size(), 11u);  // 10 moves corner to corner
  for (const PlantedFault& fault : plantedFaults()) EXPECT_EQ(plan(fault.name, open), optimisticPlan(open)) << fault.name;
}

TEST(PlantedFaultsTest, SearchHorizonGivesUpOnARouteLongerThanItsLimit) {
  const Picture detour = {"S#G", "..."};  // 4 moves round the wall: 5 cells
  EXPECT_EQ(plan("search_horizon", detour, 5).size(), 5u);
  EXPECT_TRUE(plan("search_horizon", detour, 4).empty());
}

TEST(PlantedFaultsTest, ExpansionBudgetGivesUpAfterItsLimitOfExpandedCells) {
  // Along a corridor A* expands the start and the 8 cells after it before it takes the goal from the open list.
  const Picture corridor = {"S........G", "##########"};
  EXPECT_EQ(plan("expansion_budget", corridor, 9).size(), 10u);
  EXPECT_TRUE(plan("expansion_budget", corridor, 8).empty());
}

TEST(PlantedFaultsTest, WestEdgeNeverStepsBackIntoTheLeftColumn) {
  const Picture back_left = {"GS..", "##.#", "...."};  // the goal one step west, in the left column
  EXPECT_EQ(optimisticPlan(back_left), (Cells{{1, 0}, {0, 0}}));
  EXPECT_TRUE(plan("west_edge", back_left).empty());
  const Picture down_left = {"S..", ".##", "..G"};  // starting in the left column and down it: no step west
  EXPECT_EQ(plan("west_edge", down_left), optimisticPlan(down_left));
}

TEST(PlantedFaultsTest, DeadEndFilterNeverPlansToAGoalWithThreeBlockedSides) {
  // The goal in the corner: two sides off the map, the third an obstacle, the fourth open.
  const Picture pocket = {"S..", "...", ".#G"};
  EXPECT_EQ(optimisticPlan(pocket).size(), 5u);
  EXPECT_TRUE(plan("dead_end_filter", pocket).empty());
}

TEST(PlantedFaultsTest, OpenListCapGivesUpWhenTheSearchFrontIsWiderThanItsLimit) {
  // Along a corridor one cell wide the open list never holds more than the next cell; in the open, the start's two
  // free neighbours enter it at once.
  const Picture wide = {"S.....", "......", ".....G"};
  const Picture narrow = {"S.....G", "#######"};
  EXPECT_EQ(plan("open_list_cap", narrow, 1).size(), 7u);
  EXPECT_TRUE(plan("open_list_cap", wide, 1).empty());
  EXPECT_EQ(plan("open_list_cap", wide, 100), optimisticPlan(wide));
}

TEST(PlantedFaultsTest, GoalClearanceRefusesAGoalBesideAnObstacleEvenDiagonally) {
  const Picture diagonal = {"S...", "....", "..#.", "...G"};  // the obstacle touches the goal's corner only
  EXPECT_EQ(optimisticPlan(diagonal).size(), 7u);
  EXPECT_TRUE(plan("goal_clearance", diagonal).empty());
  const Picture two_away = {"S...", ".#..", "....", "...G"};
  EXPECT_EQ(plan("goal_clearance", two_away), optimisticPlan(two_away));
}

TEST(PlantedFaultsTest, NoBacktrackFindsNoWayOutOfADeadEndUntilTheEpisodeEnds) {
  const GridMap corridor = test::mapPicture({"G...", "####"});
  FaultyPlanner planner("no_backtrack", 0);
  EXPECT_EQ(planner.plan(corridor, Cell{2, 0}, Cell{0, 0}), (Cells{{2, 0}, {1, 0}, {0, 0}}));
  // The robot stepped east, into the dead end: the way back is the cell it left.
  EXPECT_TRUE(planner.plan(corridor, Cell{3, 0}, Cell{0, 0}).empty());
  planner.startEpisode();
  EXPECT_EQ(planner.plan(corridor, Cell{3, 0}, Cell{0, 0}).size(), 4u);
}

TEST(PlantedFaultsTest, ReplanLimitGivesUpOnTheRouteOneOverItsLimit) {
  const Picture open = {"S...", "....", "....", "...G"};
  const Cell start = test::markedCell(open, 'S'), goal = test::markedCell(open, 'G');
  FaultyPlanner planner("replan_limit", 2);
  Picture drawn = open;
  const Cells first = planner.plan(test::mapPicture(drawn), start, goal);  // route 1
  ASSERT_EQ(first, optimisticPlan(open));
  // Further along the same route on the same map: not a new route.
  EXPECT_EQ(planner.plan(test::mapPicture(drawn), first[1], goal), Cells(first.begin() + 1, first.end()));
  // A wall appears on the route ahead: route 2, within the limit.
  drawn[first[3].y][first[3].x] = '#';
  const Cells second = planner.plan(test::mapPicture(drawn), first[1], goal);
  ASSERT_FALSE(second.empty());
  EXPECT_EQ(second, optimisticAStar(test::mapPicture(drawn), first[1], goal));
  // Another on the new route: the third route is refused, though there is one.
  drawn[second[2].y][second[2].x] = '#';
  ASSERT_FALSE(optimisticAStar(test::mapPicture(drawn), first[1], goal).empty());
  EXPECT_TRUE(planner.plan(test::mapPicture(drawn), first[1], goal).empty());
}

TEST(PlantedFaultsTest, SeveralFaultsEachFireOnTheirOwnMapAndPlanTheOpenMapAsNone) {
  // Each fault's map of the tests above fails the planner with that fault and any others planted beside it; on the
  // open map every combination still plans the optimistic route.
  const Picture open = {"S.....", "......", "......", "......", "......", ".....G"};
  const Picture back_left = {"GS..", "##.#", "...."};
  const Picture pocket = {"S..", "...", ".#G"};
  const Picture diagonal = {"S...", "....", "..#.", "...G"};
  const Picture detour = {"S#G", "..."};
  for (const std::string faults : {"west_edge,dead_end_filter,search_horizon", "goal_clearance,west_edge,no_backtrack",
                                   "search_horizon,expansion_budget,open_list_cap"}) {
    EXPECT_EQ(plan(faults, open), optimisticPlan(open)) << faults;
  }
  EXPECT_TRUE(plan("west_edge,dead_end_filter,search_horizon", back_left).empty());
  EXPECT_TRUE(plan("west_edge,dead_end_filter,search_horizon", pocket).empty());
  EXPECT_EQ(plan("west_edge,search_horizon", pocket), optimisticPlan(pocket));  // neither minds the pocket
  EXPECT_TRUE(plan("goal_clearance,west_edge,no_backtrack", diagonal).empty());
  EXPECT_TRUE(plan("goal_clearance,west_edge,no_backtrack", back_left).empty());
  EXPECT_TRUE(plan("west_edge,search_horizon", detour, 4).empty());  // the one limit is the horizon's
  EXPECT_EQ(plan("west_edge,search_horizon", detour, 5).size(), 5u);
}

TEST(PlantedFaultsTest, ListsOfFaultsAreCheckedNameByName) {
  EXPECT_EQ(plantedFaultList("west_edge, no_backtrack,replan_limit"),
            (std::vector<std::string>{"west_edge", "no_backtrack", "replan_limit"}));
  const auto refusal = [](const std::string& list, int limit = 0) {
    try {
      FaultyPlanner(list, limit);
    } catch (const InvalidArgument& e) {
      return e.name() + ": " + e.what();
    }
    return std::string("planted");
  };
  EXPECT_NE(refusal("west_edge,no_such_fault").find("unknown fault 'no_such_fault'"), std::string::npos);
  EXPECT_NE(refusal("west_edge,west_edge").find("fault 'west_edge' is planted twice"), std::string::npos);
  EXPECT_NE(refusal("west_edge,,no_backtrack").find("an empty fault"), std::string::npos);
  EXPECT_NE(refusal("").find("an empty fault"), std::string::npos);
  EXPECT_NE(refusal("goal_clearance,dead_end_filter").find("dead_end_filter cannot be planted with goal_clearance"),
            std::string::npos);
  EXPECT_NE(refusal("search_horizon,expansion_budget", 40).find("limit"), std::string::npos);
  EXPECT_EQ(refusal("search_horizon,west_edge", 40), "planted");
  EXPECT_EQ(refusal("search_horizon,expansion_budget"), "planted");
}

TEST(PlantedFaultsTest, BadFaultsAndLimitsAreRefusedByName) {
  try {
    FaultyPlanner("no_such_fault", 0);
    FAIL() << "an unknown fault was taken";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "fault");
    EXPECT_NE(std::string(e.what()).find("search_horizon"), std::string::npos);
  }
  try {
    FaultyPlanner("search_horizon", -1);
    FAIL() << "a negative limit was taken";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "limit");
  }
}

}  // namespace
}  // namespace planners
}  // namespace ppp
