#include "ppp_generator/genetic_algorithm.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/random_problem.hpp"

namespace ppp {
namespace generator {

namespace {

constexpr long kMaxInitialRedraws = 1000000;

/// FNV-1a over the grid cells.
std::uint64_t hashCells(const Grid& grid) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (std::uint8_t cell : grid.cells()) hash = (hash ^ cell) * 0x100000001b3ULL;
  return hash;
}

}  // namespace

GeneticAlgorithm::GeneticAlgorithm(const GeneratorOptions& options)
    : options_(options),
      fitness_((options.validate(), makeFitness(options.fitness, FitnessParameters{options.weights, options.seed}))),
      rng_(options.seed) {
  shape_ = Problem::empty(options.width, options.height, options.max_obstacles);
  shape_.start = options.startCell();
  shape_.goal = options.goalCell();
}

bool GeneticAlgorithm::evaluate(Individual* individual) {
  individual->grid = decodeGrid(individual->problem);
  individual->grid_hash = hashCells(individual->grid);
  const DpaResult& dpa = dpa_.solve(individual->grid, individual->problem.start, individual->problem.goal);
  if (!dpa.reachable) return false;
  individual->value = fitness_.value(individual->problem, individual->grid, dpa);
  individual->score = fitness_.score(individual->value);
  return true;
}

bool GeneticAlgorithm::inPool(const std::vector<Individual>& pool, const Individual& candidate) const {
  for (const Individual& member : pool) {
    if (member.grid_hash == candidate.grid_hash && member.grid == candidate.grid) return true;
  }
  return false;
}

Problem GeneticAlgorithm::randomChromosome() {
  Problem problem = shape_;
  const int count = options_.max_obstacles == 0 ? 0 : static_cast<int>(rng_.uniformInt(1, options_.max_obstacles));
  for (int i = 0; i < count; ++i) {
    problem.obstacles.push_back(randomObstacle(rng_, shape_.width, shape_.height, options_.obstacle_shapes));
  }
  return problem;
}

void GeneticAlgorithm::crossover(const Problem& a, const Problem& b, Problem* child_a, Problem* child_b) {
  // One-point crossover of variable-length lists: child_a = a[0, i) + b[j, end), child_b = b[0, j) + a[i, end).
  const auto cut_a = static_cast<std::size_t>(rng_.below(a.obstacles.size() + 1));
  const auto cut_b = static_cast<std::size_t>(rng_.below(b.obstacles.size() + 1));
  *child_a = shape_;
  *child_b = shape_;
  child_a->obstacles.assign(a.obstacles.begin(), a.obstacles.begin() + cut_a);
  child_a->obstacles.insert(child_a->obstacles.end(), b.obstacles.begin() + cut_b, b.obstacles.end());
  child_b->obstacles.assign(b.obstacles.begin(), b.obstacles.begin() + cut_b);
  child_b->obstacles.insert(child_b->obstacles.end(), a.obstacles.begin() + cut_a, a.obstacles.end());
  for (Problem* child : {child_a, child_b}) {
    if (static_cast<int>(child->obstacles.size()) > options_.max_obstacles) {
      child->obstacles.resize(static_cast<std::size_t>(options_.max_obstacles));
    }
  }
}

void GeneticAlgorithm::mutate(Problem* problem) {
  if (options_.max_obstacles == 0 || !rng_.bernoulli(options_.mutation_rate)) return;
  auto& genes = problem->obstacles;
  const bool can_add = static_cast<int>(genes.size()) < options_.max_obstacles;
  const bool can_remove = !genes.empty();
  // 0: change one descriptor, 1: add one, 2: remove one; impossible kinds fall back to change or add.
  int kind = static_cast<int>(rng_.below(3));
  if (kind == 2 && !can_remove) kind = 1;
  if (kind == 1 && !can_add) kind = 0;
  if (kind == 0 && genes.empty()) kind = 1;
  const Obstacle fresh = randomObstacle(rng_, shape_.width, shape_.height, options_.obstacle_shapes);
  if (kind == 0) {
    genes[rng_.below(genes.size())] = fresh;
  } else if (kind == 1) {
    genes.insert(genes.begin() + static_cast<long>(rng_.below(genes.size() + 1)), fresh);
  } else {
    genes.erase(genes.begin() + static_cast<long>(rng_.below(genes.size())));
  }
}

std::vector<Individual> GeneticAlgorithm::run(const ProgressCallback& progress, long progress_interval) {
  stats_ = GenerationStats{};
  std::vector<Individual> pool;
  pool.reserve(static_cast<std::size_t>(options_.population));
  while (static_cast<int>(pool.size()) < options_.population) {
    Individual individual;
    individual.problem = randomChromosome();
    if (evaluate(&individual) && !inPool(pool, individual)) {
      pool.push_back(std::move(individual));
    } else if (++stats_.initial_redraws > kMaxInitialRedraws) {
      throw InvalidArgument("population", "only " + std::to_string(pool.size()) + " distinct solvable PPPs in " +
                                              std::to_string(kMaxInitialRedraws) +
                                              " random draws; lower the population, the obstacle budget or sizes, "
                                              "or enlarge the grid");
    }
  }
  const int tournament_size = std::min(options_.tournament_size, options_.population);
  std::vector<int> order(pool.size());
  std::vector<int> tournament;
  Individual children[2];
  auto best = [&]() {
    double value = pool[0].value;
    double score = pool[0].score;
    for (const Individual& i : pool) {
      if (i.score > score) score = i.score, value = i.value;
    }
    return value;
  };
  for (long mating = 0; mating < options_.matings; ++mating) {
    // Tournament: distinct members by a partial Fisher-Yates shuffle of the pool indices.
    std::iota(order.begin(), order.end(), 0);
    tournament.clear();
    for (int i = 0; i < tournament_size; ++i) {
      const auto j = i + static_cast<int>(rng_.below(order.size() - i));
      std::swap(order[i], order[j]);
      tournament.push_back(order[i]);
    }
    // Fittest first; ties keep the draw order.
    std::stable_sort(tournament.begin(), tournament.end(),
                     [&](int a, int b) { return pool[a].score > pool[b].score; });
    crossover(pool[tournament[0]].problem, pool[tournament[1]].problem, &children[0].problem,
              &children[1].problem);
    int replaced = 0;
    for (Individual& child : children) {
      mutate(&child.problem);
      if (!evaluate(&child)) {
        ++stats_.children_pruned;  // Wei's pruning: an unsolvable child never enters the pool
        continue;
      }
      if (inPool(pool, child)) {
        ++stats_.children_duplicate;
        continue;
      }
      ++stats_.children_accepted;
      pool[tournament[tournament_size - 1 - replaced]] = child;
      ++replaced;
    }
    ++stats_.matings;
    if (progress && progress_interval > 0 && (mating + 1) % progress_interval == 0) {
      progress(mating + 1, options_.matings, best());
    }
  }
  if (progress) progress(options_.matings, options_.matings, best());
  return pool;
}

}  // namespace generator
}  // namespace ppp
