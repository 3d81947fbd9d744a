#include "ppp_generator/genetic_algorithm.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_generator/diversity.hpp"
#include "ppp_generator/initial_pool.hpp"

namespace ppp {
namespace generator {

std::vector<int> drawDistinct(Rng* rng, int size, int count) {
  std::vector<int> order(static_cast<std::size_t>(size));
  std::iota(order.begin(), order.end(), 0);
  count = std::min(count, size);
  for (int i = 0; i < count; ++i) {
    const auto j = i + static_cast<int>(rng->below(static_cast<std::uint64_t>(size - i)));
    std::swap(order[i], order[j]);
  }
  order.resize(static_cast<std::size_t>(count));
  return order;
}

GeneticAlgorithm::GeneticAlgorithm(const GeneratorOptions& options)
    : GeneticAlgorithm(options, (options.validate(),
                                 makeFitness(options.fitness, FitnessParameters{options.weights, options.seed}))) {}

GeneticAlgorithm::GeneticAlgorithm(const GeneratorOptions& options, Fitness fitness)
    : options_((options.validate(), options)),
      fitness_(std::move(fitness)),
      rng_(options.seed),
      breeder_(options_, fitness_, &rng_) {}

bool GeneticAlgorithm::keepsSignatures() const { return options_.archive == kSignatureArchive; }

std::vector<Individual> GeneticAlgorithm::initialPool(const StopCheck& stop) {
  std::vector<Individual> pool = initialPoolIndividuals(options_, &breeder_);
  pool.reserve(static_cast<std::size_t>(options_.population));
  while (static_cast<int>(pool.size()) < options_.population) {
    stopIfAsked(stop);
    Individual individual = breeder_.randomSolvable(&stats_.initial_redraws);
    if (!gridInPool(pool, individual)) {
      pool.push_back(std::move(individual));
    } else if (++stats_.initial_redraws > kMaxRandomRedraws) {
      throw InvalidArgument("population", "only " + std::to_string(pool.size()) + " distinct solvable PPPs in " +
                                              std::to_string(kMaxRandomRedraws) +
                                              " random draws; lower the population, the obstacle budget or sizes, "
                                              "or enlarge the grid");
    }
  }
  std::vector<Individual*> members;
  for (Individual& i : pool) members.push_back(&i);
  breeder_.score(members);
  if (keepsSignatures()) {
    for (const Individual& i : pool) signatures_.offer(i);
  }
  return pool;
}

void GeneticAlgorithm::replace(std::vector<Individual>* pool, const std::vector<int>& tournament, Individual* child,
                               int* replaced) {
  if (gridInPool(*pool, *child)) {
    ++stats_.children_duplicate;
    return;
  }
  const bool novel = keepsSignatures() && signatures_.offer(*child);
  if (novel) ++stats_.children_novel;
  if (options_.replacement == kTournamentReplacement) {
    const int slot = tournament[tournament.size() - 1 - static_cast<std::size_t>(*replaced)];
    (*pool)[static_cast<std::size_t>(slot)] = *child;
    ++*replaced;
    ++stats_.children_accepted;
    return;
  }
  // Restricted tournament replacement: the most similar of a random window competes with the child.
  const std::vector<int> window = drawDistinct(&rng_, static_cast<int>(pool->size()), options_.crowding_window);
  int nearest = window[0];
  double nearest_difference = 2.0;
  for (int member : window) {
    const double d = cellDifference((*pool)[static_cast<std::size_t>(member)].grid, child->grid);
    if (d < nearest_difference) nearest_difference = d, nearest = member;
  }
  Individual& rival = (*pool)[static_cast<std::size_t>(nearest)];
  if (novel || child->score >= rival.score) {
    rival = *child;
    ++stats_.children_accepted;
  } else {
    ++stats_.children_rejected;
  }
}

std::vector<Individual> GeneticAlgorithm::run(const ProgressCallback& progress, long progress_interval,
                                             const StopCheck& stop) {
  stats_ = GenerationStats{};
  signatures_ = SignatureArchive(maxSignatureElites(options_));
  std::vector<Individual> pool = initialPool(stop);
  const int tournament_size = std::min(options_.tournament_size, options_.population);
  auto best = [&]() {
    const auto fittest = std::max_element(pool.begin(), pool.end(), [](const Individual& a, const Individual& b) {
      return a.score < b.score;
    });
    return fittest->value;
  };
  struct Mating {
    std::vector<int> tournament;  // fittest first
    Individual children[2];
    bool valid[2] = {false, false};
    bool unscored[2] = {false, false};  // a batch fitness skipped it: its grid was already in the pool
  };
  const long round_size = breeder_.roundSize();
  std::vector<Mating> round;
  for (long begin = 0; begin < options_.matings; begin += round_size) {
    stopIfAsked(stop);
    const long count = std::min(round_size, options_.matings - begin);
    round.assign(static_cast<std::size_t>(count), Mating{});
    std::vector<Individual*> to_score;
    for (Mating& m : round) {
      m.tournament = drawDistinct(&rng_, static_cast<int>(pool.size()), tournament_size);
      // Fittest first; under the archive, of equally fit ones the one failing in the rarest way (a new way of
      // failing is worth breeding from more than one more copy of a known one); then the draw order.
      std::stable_sort(m.tournament.begin(), m.tournament.end(), [&](int a, int b) {
        if (pool[a].score != pool[b].score || !keepsSignatures()) return pool[a].score > pool[b].score;
        const long seen_a = signatures_.timesSeen(pool[a]), seen_b = signatures_.timesSeen(pool[b]);
        return seen_a >= 0 && (seen_b < 0 || seen_a < seen_b);
      });
      const Problem* parents[2] = {&pool[m.tournament[0]].problem, &pool[m.tournament[1]].problem};
      if (keepsSignatures() && rng_.below(2) == 0) {
        for (const Problem*& parent : parents) {
          const Individual* elite = signatures_.randomElite(&rng_);
          if (elite != nullptr) parent = &elite->problem;
        }
      }
      breeder_.crossover(*parents[0], *parents[1], &m.children[0].problem, &m.children[1].problem);
      for (int c = 0; c < 2; ++c) {
        breeder_.mutate(&m.children[c].problem);
        m.valid[c] = breeder_.decode(&m.children[c]);
        if (!m.valid[c]) {
          ++stats_.children_pruned;  // Wei's pruning: an unsolvable child never enters the pool
        } else if (breeder_.batched()) {
          m.unscored[c] = gridInPool(pool, m.children[c]);
          if (!m.unscored[c]) to_score.push_back(&m.children[c]);
        }
      }
    }
    breeder_.score(to_score);
    for (long k = 0; k < count; ++k) {
      Mating& m = round[static_cast<std::size_t>(k)];
      int replaced = 0;
      for (int c = 0; c < 2; ++c) {
        if (m.unscored[c]) {
          ++stats_.children_duplicate;
        } else if (m.valid[c]) {
          replace(&pool, m.tournament, &m.children[c], &replaced);
        }
      }
      ++stats_.matings;
      const long done = begin + k + 1;
      if (progress && progress_interval > 0 && done % progress_interval == 0) progress(done, options_.matings, best());
    }
  }
  if (progress) progress(options_.matings, options_.matings, best());
  return keepsSignatures() ? signatures_.diverseSet(options_.population, pool) : pool;
}

}  // namespace generator
}  // namespace ppp
