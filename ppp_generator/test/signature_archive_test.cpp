#include "ppp_generator/signature_archive.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_generator/genetic_algorithm.hpp"

namespace ppp {
namespace generator {
namespace {

/// A PPP of score `score` showing `signatures`, told apart by `hash`.
Individual shown(std::uint64_t hash, double score, const std::vector<std::string>& signatures) {
  Individual i;
  i.grid_hash = hash;
  i.score = score;
  i.value = score;
  for (const std::string& s : signatures) i.signatures[s] = 1;
  return i;
}

TEST(SignatureArchiveTest, DistanceCountsTheDifferingParts) {
  EXPECT_EQ(signatureDistance("loop2/g4-7/s8-15/t2/w1e0", "loop2/g4-7/s8-15/t2/w1e0"), 0);
  EXPECT_EQ(signatureDistance("loop2/g4-7/s8-15/t2/w1e0", "loop2/g8-15/s8-15/t2/w1e0"), 1);
  EXPECT_EQ(signatureDistance("loop2/g4-7/s8-15/t2/w1e0", "stuck/g4-7/s2-3/t2/w0e1"), 3);
  // The goal's shape is a part of its own: absent in one, present in the other.
  EXPECT_EQ(signatureDistance("missed_route/g1/s16-31/t2/w0e0/G1e0d2", "missed_route/g4-7/s16-31/t2/w0e0"), 2);
  EXPECT_EQ(signatureDistance("missed_route/g1/s16-31/t2/w0e0/G1e0d2", "no_route/g2-3/s8-15/t1/w1e1/G0e2d3"), 6);
}

TEST(SignatureArchiveTest, EachSignatureKeepsItsFittestPPPAndTheFirstOfEquals) {
  SignatureArchive archive(100);
  EXPECT_TRUE(archive.offer(shown(1, 0.5, {"a/g1/s1/w0e0/G0e0d0"})));
  EXPECT_FALSE(archive.offer(shown(2, 0.5, {"a/g1/s1/w0e0/G0e0d0"})));  // as fit: the first stays
  EXPECT_FALSE(archive.offer(shown(3, 0.2, {"a/g1/s1/w0e0/G0e0d0"})));
  EXPECT_TRUE(archive.offer(shown(4, 0.9, {"a/g1/s1/w0e0/G0e0d0", "b/g16+/s1/w0e0"})));  // one new: novel
  EXPECT_FALSE(archive.offer(shown(5, 1.0, {})));  // a PPP it passes shows none
  const auto& entries = archive.entries();
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries.at("a/g1/s1/w0e0/G0e0d0").elite.grid_hash, 4u);  // fitter
  EXPECT_EQ(entries.at("a/g1/s1/w0e0/G0e0d0").seen, 4);
  EXPECT_EQ(entries.at("a/g1/s1/w0e0/G0e0d0").found, 0);
  EXPECT_EQ(entries.at("b/g16+/s1/w0e0").found, 3);
  EXPECT_EQ(archive.csv({{4, "ppp_007"}}),
            "signature,found,seen,value,problem\na/g1/s1/w0e0/G0e0d0,0,4,0.9,ppp_007\nb/g16+/s1/w0e0,3,1,0.9,ppp_007\n");
}

TEST(SignatureArchiveTest, ParentsAreDrawnInInverseProportionToHowOftenTheirSignatureWasSeen) {
  SignatureArchive archive(100);
  EXPECT_EQ(archive.randomElite(nullptr), nullptr);  // nothing to draw: no draw made
  archive.offer(shown(1, 1, {"common"}));
  archive.offer(shown(2, 1, {"common"}));
  archive.offer(shown(3, 1, {"common", "rare"}));
  archive.offer(shown(4, 0.3, {}));  // the hardest passed PPP
  EXPECT_EQ(archive.timesSeen(shown(9, 1, {"common"})), 3);
  EXPECT_EQ(archive.timesSeen(shown(9, 1, {"common", "rare"})), 1);  // its rarest signature
  EXPECT_EQ(archive.timesSeen(shown(9, 1, {"new"})), 0);
  EXPECT_EQ(archive.timesSeen(shown(9, 0, {})), -1);
  // Weights 1/3 (common, seen 3 times), 1 (rare, once) and 1 (the passed PPP): probabilities 1/7, 3/7 and 3/7.
  Rng rng(11);
  std::map<std::uint64_t, int> drawn;
  const int draws = 70000;
  for (int k = 0; k < draws; ++k) ++drawn[archive.randomElite(&rng)->grid_hash];
  ASSERT_EQ(drawn.size(), 3u);
  // The common signature's elite is the first that showed it; the rare one's is PPP 3. Within 4 standard errors.
  const double sd = std::sqrt(draws * (3.0 / 7) * (4.0 / 7));
  EXPECT_NEAR(drawn[1], draws / 7.0, 4 * std::sqrt(draws * (1.0 / 7) * (6.0 / 7)));
  EXPECT_NEAR(drawn[3], draws * 3.0 / 7, 4 * sd);
  EXPECT_NEAR(drawn[4], draws * 3.0 / 7, 4 * sd);
}

TEST(SignatureArchiveTest, AFullArchiveCountsNewSignaturesWithoutKeepingThem) {
  SignatureArchive archive(1);
  EXPECT_TRUE(archive.offer(shown(1, 1, {"a/g1/s1/w0e0/G0e0d0"})));
  EXPECT_FALSE(archive.offer(shown(2, 1, {"b/g16+/s1/w0e0"})));
  EXPECT_EQ(archive.entries().size(), 1u);
  EXPECT_EQ(archive.dropped(), 1);
}

TEST(SignatureArchiveTest, TheSetTakesTheFittestThenWhatDiffersMostThenThePool) {
  // By hand: the fittest (1) first; then of the rest the farthest from it: (3) differs in all 6 parts, (2) in 1, (4)
  // in 2; then (4) is 2 from (1) and 5 from (3), (2) 1 from (1): (4); then (2). A set of 6 adds the pool's fittest
  // PPPs that are not in it yet, fittest first (2 is in it already).
  SignatureArchive archive(100);
  archive.offer(shown(1, 0.9, {"loop2/g4-7/s8-15/t2/w1e0"}));
  archive.offer(shown(2, 0.5, {"loop2/g8-15/s8-15/t2/w1e0"}));
  archive.offer(shown(3, 0.4, {"missed_route/g1/s2-3/t0/w0e2/G0e2d3"}));
  archive.offer(shown(4, 0.3, {"loop3-4/g4-7/s2-3/t2/w1e0"}));
  const std::vector<Individual> pool = {shown(2, 0.5, {}), shown(7, 0.1, {}), shown(8, 0.8, {}), shown(9, 0.0, {})};
  std::vector<std::uint64_t> order;
  for (const Individual& i : archive.diverseSet(6, pool)) order.push_back(i.grid_hash);
  EXPECT_EQ(order, (std::vector<std::uint64_t>{1, 3, 4, 2, 8, 7}));
  order.clear();
  for (const Individual& i : archive.diverseSet(2, pool)) order.push_back(i.grid_hash);
  EXPECT_EQ(order, (std::vector<std::uint64_t>{1, 3}));
}

/// A panel fitness stand-in: every PPP fails; its signature is its obstacle count modulo 3, and PPPs of class 0
/// score highest, so that without an archive they take the pool.
Fitness threeWaysOfFailing() {
  Fitness fitness;
  fitness.name = "failure";
  fitness.batch_size = 16;
  fitness.batch = [](const std::vector<const Problem*>&, const std::vector<const Grid*>& grids) {
    std::vector<FitnessScore> scores;
    for (const Grid* g : grids) {
      const int kind = g->obstacleCount() % 3;
      FitnessScore s;
      s.value = s.score = kind == 0 ? 1.0 : 0.5;
      s.signatures["stuck/g" + std::string(kind == 0 ? "1" : kind == 1 ? "4-7" : "16+") + "/s1/w0e0"] = 1;
      scores.push_back(s);
    }
    return scores;
  };
  return fitness;
}

int kindsIn(const std::vector<Individual>& set) {
  std::set<int> kinds;
  for (const Individual& i : set) kinds.insert(i.grid.obstacleCount() % 3);
  return static_cast<int>(kinds.size());
}

/// A hunt of the stand-in panel: `population` PPPs, `matings` matings, seed 3, crowding window 2.
GeneratorOptions standInHunt(int population, long matings) {
  GeneratorOptions o;
  o.fitness = "failure";
  o.agents = {"stand_in"};
  o.population = population;
  o.tournament_size = std::min(4, population);
  o.matings = matings;
  o.crowding_window = 2;
  o.seed = 3;
  return o;
}

TEST(SignatureArchiveTest, AHuntWithTheArchiveKeepsEveryWayOfFailingWhereThePoolKeepsTheEasiest) {
  GeneratorOptions o = standInHunt(12, 600);
  GeneticAlgorithm plain(o, threeWaysOfFailing());
  const std::vector<Individual> pool = plain.run();
  o.archive = kSignatureArchive;
  GeneticAlgorithm hunt(o, threeWaysOfFailing());
  const std::vector<Individual> set = hunt.run();
  EXPECT_EQ(kindsIn(pool), 1);  // the fittest kind took the pool
  EXPECT_EQ(kindsIn(set), 3);
  EXPECT_EQ(set.size(), 12u);
  EXPECT_EQ(hunt.signatureArchive().entries().size(), 3u);
  std::set<std::uint64_t> grids;
  for (const Individual& i : set) grids.insert(i.grid_hash);
  EXPECT_EQ(grids.size(), set.size());  // distinct PPPs
}

TEST(SignatureArchiveTest, AChildFailingInANewWayIsCountedAndKept) {
  // A pool of two holds at most two of the three ways of failing: the third can only come from a child.
  GeneratorOptions o = standInHunt(2, 200);
  o.archive = kSignatureArchive;
  GeneticAlgorithm hunt(o, threeWaysOfFailing());
  const std::vector<Individual> set = hunt.run();
  EXPECT_EQ(hunt.signatureArchive().entries().size(), 3u);
  EXPECT_GE(hunt.stats().children_novel, 1);
  EXPECT_EQ(set.size(), 2u);  // the set is as large as the population
  EXPECT_NE(set[0].grid.obstacleCount() % 3, set[1].grid.obstacleCount() % 3);  // two ways, as different as any
}

TEST(SignatureArchiveTest, TheArchiveServesOnlyAPanelFitness) {
  GeneratorOptions o;
  o.fitness = "turns";
  o.archive = kSignatureArchive;
  try {
    o.validate();
    FAIL() << "archive: signatures taken for turns";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "archive");
    EXPECT_NE(std::string(e.what()).find("fitness 'turns' plays no panel"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace generator
}  // namespace ppp
