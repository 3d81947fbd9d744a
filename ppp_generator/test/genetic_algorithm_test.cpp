#include "ppp_generator/genetic_algorithm.hpp"

#include <gtest/gtest.h>

#include "ppp_core/evaluation.hpp"
#include "ppp_core/reachability.hpp"

namespace ppp {
namespace generator {
namespace {

GeneratorOptions smallRun(const std::string& fitness, std::uint64_t seed, long matings) {
  GeneratorOptions o;
  o.fitness = fitness;
  o.seed = seed;
  o.matings = matings;
  o.population = 30;
  return o;
}

/// Mean of one evaluation field over a pool.
template <typename Field>
double meanOf(const std::vector<Individual>& pool, Field field) {
  Evaluator evaluator;
  double total = 0;
  for (const Individual& i : pool) total += field(evaluator.evaluate(i.problem));
  return total / pool.size();
}

/// Means of one evaluation field over the final pools of seeds 1-3 (population 30, 2,000 matings on 20x20).
struct SelectionEffect {
  double selected = 0;  ///< Evolved with the fitness under test.
  double baseline = 0;  ///< Evolved with the `random` fitness.
};

template <typename Field>
SelectionEffect selectionEffect(const std::string& fitness, Field field) {
  SelectionEffect effect;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    GeneticAlgorithm chosen(smallRun(fitness, seed, 2000)), random(smallRun("random", seed, 2000));
    effect.selected += meanOf(chosen.run(), field) / 3;
    effect.baseline += meanOf(random.run(), field) / 3;
  }
  return effect;
}

TEST(GeneticAlgorithmTest, NoInvalidOrDuplicatePppEverInThePool) {
  // Tight maps (many long bars on 8x8) make most children unsolvable, so pruning is exercised.
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    for (const char* fitness : {"turns", "difficulty", "random"}) {
      GeneratorOptions o = smallRun(fitness, seed, 300);
      o.width = 8;
      o.height = 8;
      o.max_obstacles = 12;
      GeneticAlgorithm ga(o);
      const auto pool = ga.run();
      ASSERT_EQ(pool.size(), 30u);
      for (const Individual& i : pool) {
        EXPECT_NO_THROW(validateProblem(i.problem));
        EXPECT_TRUE(isReachable(decodeGrid(i.problem), i.problem.start, i.problem.goal)) << fitness << seed;
        EXPECT_LE(static_cast<int>(i.problem.obstacles.size()), o.max_obstacles);
      }
      EXPECT_EQ(ga.stats().matings, 300);
      EXPECT_EQ(ga.stats().children_accepted + ga.stats().children_pruned + ga.stats().children_duplicate +
                    ga.stats().children_rejected,
                600);
      for (std::size_t a = 0; a < pool.size(); ++a) {
        for (std::size_t b = a + 1; b < pool.size(); ++b) {
          EXPECT_NE(decodeGrid(pool[a].problem), decodeGrid(pool[b].problem)) << "duplicate PPPs " << a << ", " << b;
        }
      }
      EXPECT_GT(ga.stats().children_pruned, 0) << "pruning never happened: the test map is too easy";
    }
  }
}

TEST(GeneticAlgorithmTest, SameSeedSamePoolDifferentSeedDifferentPool) {
  GeneticAlgorithm a(smallRun("turns", 7, 400)), b(smallRun("turns", 7, 400)), c(smallRun("turns", 8, 400));
  const auto pa = a.run(), pb = b.run(), pc = c.run();
  bool all_same_as_c = true;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    EXPECT_EQ(pa[i].problem, pb[i].problem);
    all_same_as_c &= pa[i].problem == pc[i].problem;
  }
  EXPECT_FALSE(all_same_as_c);
}

TEST(GeneticAlgorithmTest, TurnsFitnessSelectsForTurns) {
  // Fixed seeds 1-3, population 30, 2,000 matings on 20x20: measured mean fewest turns 20.2 with `turns`
  // and 1.4 with `random` (the values are printed). The assertion asks for half of that gap.
  const auto [selected, baseline] = selectionEffect("turns", [](const Evaluation& e) { return e.turns; });
  std::printf("mean turns: turns fitness %.3f, random fitness %.3f\n", selected, baseline);
  EXPECT_GT(selected, baseline + 10.0);
}

TEST(GeneticAlgorithmTest, DifficultyFitnessLowersTheDifficultyScore) {
  // Same seeds and sizes: measured mean difficulty 4.2 with `difficulty` and 10.0 with `random`;
  // the assertion asks for about half of that gap.
  const auto [selected, baseline] =
      selectionEffect("difficulty", [](const Evaluation& e) { return e.difficulty; });
  std::printf("mean difficulty: difficulty fitness %.3f, random fitness %.3f\n", selected, baseline);
  EXPECT_LT(selected, baseline - 3.0);
}

TEST(GeneticAlgorithmTest, ProgressIsReported) {
  std::vector<long> calls;
  GeneticAlgorithm ga(smallRun("turns", 1, 250));
  ga.run([&](long done, long total, double) {
    EXPECT_EQ(total, 250);
    calls.push_back(done);
  }, 100);
  EXPECT_EQ(calls, (std::vector<long>{100, 200, 250}));
}

TEST(GeneticAlgorithmTest, ZeroMatingsReturnsTheInitialPool) {
  GeneticAlgorithm ga(smallRun("turns", 3, 0));
  EXPECT_EQ(ga.run().size(), 30u);
  EXPECT_EQ(ga.stats().matings, 0);
}

}  // namespace
}  // namespace generator
}  // namespace ppp
