#include "ppp_generator/breeder.hpp"

#include <algorithm>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/footprint.hpp"

#include "ppp_core/random_problem.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace generator {

Breeder::Breeder(const GeneratorOptions& options, const Fitness& fitness, Rng* rng)
    : options_(options), fitness_(fitness), rng_(rng) {
  shape_ = Problem::empty(options.width, options.height, options.max_obstacles);
  shape_.start = options.startCell();
  shape_.goal = options.goalCell();
  // A robot that cannot stand at the start or the goal of an empty map has no solvable PPP to find.
  const Grid open_space = configurationSpace(Grid(options.width, options.height), options.robot_radius);
  for (const auto& [name, cell] : {std::pair<const char*, Cell>{"start", shape_.start}, {"goal", shape_.goal}}) {
    if (!open_space.isFree(cell)) {
      throw InvalidArgument(name, "cell " + cellText(cell) + " is within robot_radius " +
                                      formatShortest(options.robot_radius) +
                                      " of the map's edge: the robot does not fit there; move it further in");
    }
  }
}

Problem Breeder::randomChromosome() {
  Problem problem = shape_;
  const int most = options_.max_obstacles;
  const int count = most == 0 ? 0 : static_cast<int>(rng_->uniformInt(std::min(options_.min_obstacles, most), most));
  for (int i = 0; i < count; ++i) {
    problem.obstacles.push_back(randomObstacle(*rng_, shape_.width, shape_.height, options_.obstacle_shapes));
  }
  return problem;
}

void Breeder::crossover(const Problem& a, const Problem& b, Problem* child_a, Problem* child_b) {
  const auto cut_a = static_cast<std::size_t>(rng_->below(a.obstacles.size() + 1));
  const auto cut_b = static_cast<std::size_t>(rng_->below(b.obstacles.size() + 1));
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

void Breeder::mutate(Problem* problem) {
  if (options_.max_obstacles == 0 || !rng_->bernoulli(options_.mutation_rate)) return;
  auto& genes = problem->obstacles;
  const bool can_add = static_cast<int>(genes.size()) < options_.max_obstacles;
  const bool can_remove = !genes.empty();
  // 0: change one descriptor, 1: add one, 2: remove one; impossible kinds fall back to change or add.
  int kind = static_cast<int>(rng_->below(3));
  if (kind == 2 && !can_remove) kind = 1;
  if (kind == 1 && !can_add) kind = 0;
  if (kind == 0 && genes.empty()) kind = 1;
  const Obstacle fresh = randomObstacle(*rng_, shape_.width, shape_.height, options_.obstacle_shapes);
  if (kind == 0) {
    genes[rng_->below(genes.size())] = fresh;
  } else if (kind == 1) {
    genes.insert(genes.begin() + static_cast<long>(rng_->below(genes.size() + 1)), fresh);
  } else {
    genes.erase(genes.begin() + static_cast<long>(rng_->below(genes.size())));
  }
}

Individual Breeder::randomSolvable(long* redraws) {
  for (;;) {
    Individual individual;
    individual.problem = randomChromosome();
    if (decode(&individual)) return individual;
    if (++*redraws > kMaxRandomRedraws) {
      throw InvalidArgument("population", "no solvable random PPP in " + std::to_string(kMaxRandomRedraws) +
                                              " draws; lower the obstacle budget or sizes, or enlarge the grid");
    }
  }
}

bool Breeder::decode(Individual* individual) {
  individual->grid = decodeGrid(individual->problem);
  individual->grid_hash = individual->grid.hash();
  // With a body the robot's routes are those of its configuration space.
  Grid space;
  const Grid& motion = motionGrid(individual->grid, options_.robot_radius, &space);
  const DpaResult& dpa = dpa_.solve(motion, individual->problem.start, individual->problem.goal);
  if (!dpa.reachable) return false;
  if (!batched()) {
    individual->value = fitness_.value(individual->problem, individual->grid, dpa);
    individual->score = fitness_.score(individual->value);
  }
  return true;
}

void Breeder::score(const std::vector<Individual*>& individuals) {
  if (!batched()) return;
  const auto size = static_cast<std::size_t>(std::max(1, fitness_.batch_size));
  for (std::size_t begin = 0; begin < individuals.size(); begin += size) {
    const std::size_t end = std::min(individuals.size(), begin + size);
    std::vector<const Problem*> problems;
    std::vector<const Grid*> grids;
    for (std::size_t i = begin; i < end; ++i) {
      problems.push_back(&individuals[i]->problem);
      grids.push_back(&individuals[i]->grid);
    }
    const std::vector<FitnessScore> scores = fitness_.batch(problems, grids);
    if (scores.size() != problems.size()) {
      throw InvalidArgument("fitness", fitness_.name + " answered " + std::to_string(scores.size()) + " scores for " +
                                           std::to_string(problems.size()) + " PPPs");
    }
    for (std::size_t i = begin; i < end; ++i) {
      individuals[i]->value = scores.at(i - begin).value;
      individuals[i]->score = scores.at(i - begin).score;
      individuals[i]->signatures = scores.at(i - begin).signatures;
    }
  }
}

bool gridInPool(const std::vector<Individual>& pool, const Individual& candidate) {
  for (const Individual& member : pool) {
    if (member.grid_hash == candidate.grid_hash && member.grid == candidate.grid) return true;
  }
  return false;
}

}  // namespace generator
}  // namespace ppp
