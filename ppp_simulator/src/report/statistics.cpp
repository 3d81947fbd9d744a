#include "ppp_simulator/report/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include "ppp_core/error.hpp"

namespace ppp {
namespace simulator {

namespace {

void checkSample(const std::vector<double>& sample, const char* name) {
  if (sample.empty()) throw InvalidArgument(name, "empty sample, expected at least one value");
  for (std::size_t i = 0; i < sample.size(); ++i) {
    if (!std::isfinite(sample[i])) {
      throw InvalidArgument(name, "value " + std::to_string(i) + " is not finite, expected a number");
    }
  }
}

void checkSet(const PassRateTable& rates, const std::string& set, const char* name) {
  if (std::find(rates.sets.begin(), rates.sets.end(), set) != rates.sets.end()) return;
  std::string known;
  for (const std::string& s : rates.sets) known += (known.empty() ? "'" : ", '") + s + "'";
  throw InvalidArgument(name, "unknown PPP set '" + set + "', expected one of: " + (known.empty() ? "(none)" : known));
}

}  // namespace

MannWhitney mannWhitneyU(const std::vector<double>& a, const std::vector<double>& b) {
  checkSample(a, "a");
  checkSample(b, "b");

  // Pool the values, remembering which sample each came from, and rank them.
  std::vector<std::pair<double, bool>> pooled;  // (value, from a)
  pooled.reserve(a.size() + b.size());
  for (const double v : a) pooled.emplace_back(v, true);
  for (const double v : b) pooled.emplace_back(v, false);
  std::sort(pooled.begin(), pooled.end(),
            [](const std::pair<double, bool>& x, const std::pair<double, bool>& y) { return x.first < y.first; });

  double rank_sum_a = 0;
  double tie_term = 0;  // Σ (t³ − t) over groups of tied values
  for (std::size_t start = 0; start < pooled.size();) {
    std::size_t end = start + 1;
    while (end < pooled.size() && pooled[end].first == pooled[start].first) ++end;
    const double t = static_cast<double>(end - start);
    const double average_rank = (static_cast<double>(start + 1) + static_cast<double>(end)) / 2;  // 1-based
    for (std::size_t k = start; k < end; ++k) {
      if (pooled[k].second) rank_sum_a += average_rank;
    }
    tie_term += t * t * t - t;
    start = end;
  }

  MannWhitney result;
  result.n_a = static_cast<int>(a.size());
  result.n_b = static_cast<int>(b.size());
  const double n_a = result.n_a;
  const double n_b = result.n_b;
  const double n = n_a + n_b;
  result.u_a = rank_sum_a - n_a * (n_a + 1) / 2;
  result.u_b = n_a * n_b - result.u_a;
  result.u = std::min(result.u_a, result.u_b);

  // N = 1 cannot happen (both samples hold a value), so N(N − 1) > 0.
  const double variance = n_a * n_b / 12 * ((n + 1) - tie_term / (n * (n - 1)));
  const double sigma = variance > 0 ? std::sqrt(variance) : 0.0;
  // Rounding can leave a tiny positive variance when every value is tied; treat that as none.
  if (sigma <= 1e-9 * n_a * n_b) {
    result.z = 0;
    result.p = 1;
    return result;
  }
  result.z = (result.u_a - n_a * n_b / 2) / sigma;
  result.p = std::min(1.0, std::erfc(std::fabs(result.z) / std::sqrt(2.0)));
  return result;
}

std::vector<AgentComparison> compareSets(const PassRateTable& rates, const std::string& set_a,
                                         const std::string& set_b) {
  checkSet(rates, set_a, "set_a");
  checkSet(rates, set_b, "set_b");
  std::vector<AgentComparison> comparisons;
  for (const std::string& agent : rates.agents) {
    const SetPassRate* on_a = rates.find(set_a, agent);
    const SetPassRate* on_b = rates.find(set_b, agent);
    if (on_a == nullptr || on_b == nullptr) continue;
    AgentComparison comparison;
    comparison.agent = agent;
    comparison.mean_a = on_a->mean_rate;
    comparison.mean_b = on_b->mean_rate;
    comparison.test = mannWhitneyU(rates.problemRates(set_a, agent), rates.problemRates(set_b, agent));
    comparisons.push_back(std::move(comparison));
  }
  return comparisons;
}

}  // namespace simulator
}  // namespace ppp
