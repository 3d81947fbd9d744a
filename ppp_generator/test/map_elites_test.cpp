// The MAP-Elites archive: bins and the replacement rule on hand-worked cases, then whole searches.

#include "ppp_generator/map_elites.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "ppp_core/barn_metrics.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/evaluation.hpp"

namespace ppp {
namespace generator {
namespace {

Individual withScore(int obstacle_x, double score) {
  Individual i;
  i.problem = Problem::empty(4, 4, 1);
  i.problem.goal = Cell{3, 3};
  i.grid = Grid(4, 4);
  i.grid.setObstacle(Cell{obstacle_x, 1}, true);
  i.grid_hash = i.grid.hash();
  i.value = score;
  i.score = score;
  return i;
}

TEST(MapElitesTest, BinsAreEqualWidthAndClamped) {
  const FeatureRange unit{0.0, 1.0};
  EXPECT_EQ(binOf(0.0, unit, 4), 0);
  EXPECT_EQ(binOf(0.2499, unit, 4), 0);
  EXPECT_EQ(binOf(0.25, unit, 4), 1);
  EXPECT_EQ(binOf(0.99, unit, 4), 3);
  EXPECT_EQ(binOf(1.0, unit, 4), 3);   // the top end belongs to the last bin
  EXPECT_EQ(binOf(-0.5, unit, 4), 0);  // outside: clamped
  EXPECT_EQ(binOf(7.0, unit, 4), 3);
  EXPECT_EQ(binOf(38.0, FeatureRange{38.0, 200.0}, 8), 0);
  EXPECT_EQ(binOf(59.0, FeatureRange{38.0, 200.0}, 8), 1);  // (59 - 38) / 162 * 8 = 1.04
}

TEST(MapElitesTest, FeatureRangesFollowTheGridAndBudget) {
  GeneratorOptions o;  // 20x20, (0,0) to (19,19), 10 descriptors, default weights summing to 15
  EXPECT_EQ(featureRange("turns", o).high, 40.0);
  EXPECT_EQ(featureRange("advances", o).low, 38.0);
  EXPECT_EQ(featureRange("advances", o).high, 200.0);
  EXPECT_EQ(featureRange("obstacles", o).high, 10.0);
  EXPECT_EQ(featureRange("difficulty", o).high, 15.0);
  EXPECT_EQ(featureRange("visibility_goal", o).high, 1.0);
  EXPECT_THROW(featureRange("width", o), InvalidArgument);
  EXPECT_EQ(featureRange("barn_closest_obstacle", o).high, 10.0);
  EXPECT_EQ(featureRange("barn_visibility", o).high, 10.0);
  EXPECT_EQ(featureRange("barn_dispersion", o).high, 8.0);  // half of the 16 rays
  EXPECT_EQ(featureRange("barn_characteristic_dimension", o).high, 20.0);
  // The advances' range, 38 ... 200, over the start-to-goal distance 19*sqrt2.
  EXPECT_DOUBLE_EQ(featureRange("barn_tortuosity", o).low, 38 / (19 * std::sqrt(2.0)));
  EXPECT_DOUBLE_EQ(featureRange("barn_tortuosity", o).high, 200 / (19 * std::sqrt(2.0)));
}

TEST(MapElitesTest, EachCellKeepsItsFittestAndTheFirstOfEquals) {
  // Two features on [0, 10], two bins each: cells 0 (low, low), 1 (low, high), 2 (high, low), 3 (high, high).
  Archive archive({{0, 10}, {0, 10}}, 2);
  EXPECT_EQ(archive.cellOf({1, 1}), 0);
  EXPECT_EQ(archive.cellOf({1, 6}), 1);
  EXPECT_EQ(archive.cellOf({6, 1}), 2);
  EXPECT_EQ(archive.cellOf({6, 6}), 3);
  EXPECT_TRUE(archive.offer(withScore(0, 0.5), {1, 1}));   // empty cell: taken
  EXPECT_FALSE(archive.offer(withScore(1, 0.5), {2, 3}));  // same cell, equally fit: the first stays
  EXPECT_FALSE(archive.offer(withScore(2, 0.4), {4, 4}));  // less fit: refused
  EXPECT_TRUE(archive.offer(withScore(3, 0.7), {0, 0}));   // fitter: replaces
  EXPECT_TRUE(archive.offer(withScore(1, 0.1), {9, 9}));   // another cell
  ASSERT_EQ(archive.elites().size(), 2u);
  EXPECT_EQ(archive.elites().at(0).individual.score, 0.7);
  EXPECT_EQ(archive.elites().at(0).bins, (std::vector<int>{0, 0}));
  EXPECT_EQ(archive.elites().at(3).bins, (std::vector<int>{1, 1}));
  EXPECT_TRUE(archive.holds(withScore(3, 0.0)));
  EXPECT_FALSE(archive.holds(withScore(0, 0.0)));  // replaced
}

GeneratorOptions smallSearch(std::uint64_t seed) {
  GeneratorOptions o;
  o.fitness = "turns";
  o.archive = kMapElitesArchive;
  o.features = {"turns", "obstacles"};
  o.bins = 6;
  o.population = 20;
  o.matings = 600;
  o.seed = seed;
  return o;
}

TEST(MapElitesTest, ASearchReturnsDistinctElitesInTheirCellsFittestFirst) {
  const GeneratorOptions o = smallSearch(3);
  MapElites search(o, makeFitness(o.fitness));
  const std::vector<Individual> elites = search.run();
  ASSERT_GT(search.archive().elites().size(), 10u);
  EXPECT_EQ(elites.size(), std::min<std::size_t>(20, search.archive().elites().size()));
  Evaluator evaluator;
  std::set<std::uint64_t> hashes;
  for (std::size_t i = 0; i < elites.size(); ++i) {
    EXPECT_TRUE(hashes.insert(elites[i].grid.hash()).second) << "copy at " << i;
    if (i > 0) EXPECT_GE(elites[i - 1].score, elites[i].score);
  }
  for (const auto& [cell, elite] : search.archive().elites()) {
    const Evaluation e = evaluator.evaluate(elite.individual.problem);
    EXPECT_EQ(search.archive().cellOf({static_cast<double>(e.turns), static_cast<double>(e.obstacles)}), cell);
    EXPECT_EQ(elite.individual.value, e.turns);
  }
  const std::string csv = archiveCsv(search.archive(), o.features, {});
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')), search.archive().elites().size() + 1);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "cell,turns_bin,obstacles_bin,turns,obstacles,fitness_value,id");
  const std::string svg = archiveHeatMapSvg(search.archive(), o.features, {{0, 40}, {0, 10}}, "test");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find(">obstacles<"), std::string::npos);
  EXPECT_EQ(static_cast<std::size_t>(std::count(svg.begin(), svg.end(), '\n')) > 36u, true);
}

TEST(MapElitesTest, BarnCharactersAreFeatures) {
  GeneratorOptions o = smallSearch(4);
  o.features = {"turns", "barn_dispersion", "barn_tortuosity"};
  o.bins = 4;
  o.matings = 200;
  MapElites search(o, makeFitness(o.fitness));
  search.run();
  ASSERT_GT(search.archive().elites().size(), 1u);
  for (const auto& [cell, elite] : search.archive().elites()) {
    const Problem& p = elite.individual.problem;
    const std::vector<double> barn = barnCharacterVector(barnMetrics(p, decodeGrid(p)));
    EXPECT_EQ(elite.features, (std::vector<double>{elite.individual.value, barn[2], barn[4]}));
    EXPECT_EQ(search.archive().cellOf(elite.features), cell);
  }
}

TEST(MapElitesTest, SameSeedSameElites) {
  const GeneratorOptions o = smallSearch(5);
  MapElites a(o, makeFitness(o.fitness)), b(o, makeFitness(o.fitness));
  const auto ea = a.run(), eb = b.run();
  ASSERT_EQ(ea.size(), eb.size());
  for (std::size_t i = 0; i < ea.size(); ++i) EXPECT_EQ(ea[i].problem, eb[i].problem);
}

TEST(MapElitesTest, ABatchFitnessIsCalledInBatchesAndDecides) {
  // A batch scorer that counts obstacle cells: every call gets at most batch_size PPPs.
  Fitness fitness;
  fitness.name = "obstacle_cells";
  fitness.batch_size = 5;
  int calls = 0;
  fitness.batch = [&](const std::vector<const Problem*>& problems, const std::vector<const Grid*>& grids) {
    ++calls;
    EXPECT_LE(problems.size(), 5u);
    EXPECT_EQ(problems.size(), grids.size());
    std::vector<FitnessScore> scores;
    for (const Grid* g : grids) scores.push_back({double(g->obstacleCount()), double(g->obstacleCount())});
    return scores;
  };
  GeneratorOptions o = smallSearch(7);
  MapElites search(o, fitness);
  const auto elites = search.run();
  EXPECT_GT(calls, 600 / 5);
  for (const Individual& i : elites) EXPECT_EQ(i.value, i.grid.obstacleCount());
}

}  // namespace
}  // namespace generator
}  // namespace ppp
