// UPGMA of random 14-character PPPs (normalised, Euclidean), as `ppp taxonomy` builds it.

#include <benchmark/benchmark.h>

#include "ppp_core/rng.hpp"
#include "ppp_generator/taxonomy.hpp"

namespace ppp::generator {
namespace {

Eigen::MatrixXd randomCharacters(int n) {
  Rng rng(20240601);
  Eigen::MatrixXd m(n, 14);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < 14; ++c) m(r, c) = rng.uniform01() * (c + 1);
  }
  return m;
}

void BM_Distances(benchmark::State& state) {
  const Eigen::MatrixXd characters = randomCharacters(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Eigen::MatrixXd d = euclideanDistances(normaliseColumns(characters));
    benchmark::DoNotOptimize(d.data());
  }
}
BENCHMARK(BM_Distances)->Arg(120)->Arg(1000)->Unit(benchmark::kMillisecond);

void BM_Upgma(benchmark::State& state) {
  const Eigen::MatrixXd d = euclideanDistances(normaliseColumns(randomCharacters(static_cast<int>(state.range(0)))));
  for (auto _ : state) {
    Tree tree = upgma(d);
    benchmark::DoNotOptimize(tree.nodes.data());
  }
  state.counters["root_height"] = upgma(d).nodes.back().height;
}
BENCHMARK(BM_Upgma)->Arg(120)->Arg(1000)->Arg(3000)->Unit(benchmark::kMillisecond);

/// Worst case for the nearest-neighbour cache: every distance equal, so each merge invalidates most rows.
void BM_UpgmaAllTied(benchmark::State& state) {
  const Eigen::Index n = state.range(0);
  Eigen::MatrixXd d = Eigen::MatrixXd::Ones(n, n);
  d.diagonal().setZero();
  for (auto _ : state) {
    Tree tree = upgma(d);
    benchmark::DoNotOptimize(tree.nodes.data());
  }
}
BENCHMARK(BM_UpgmaAllTied)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ppp::generator
