#include "ppp_simulator/report/detours.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "ppp_core/error.hpp"

namespace ppp {
namespace simulator {

namespace {

/// The `q` quantile of sorted values, interpolated between neighbours (as numpy's default).
double quantile(const std::vector<double>& sorted, double q) {
  const double at = q * static_cast<double>(sorted.size() - 1);
  const std::size_t low = static_cast<std::size_t>(std::floor(at));
  const std::size_t high = std::min(low + 1, sorted.size() - 1);
  return sorted[low] + (sorted[high] - sorted[low]) * (at - static_cast<double>(low));
}

/// What one (set, agent) collects: its ratios, and per PPP the sum, count and longest run.
struct Collected {
  std::vector<double> ratios;
  int soft_failures = 0;
  std::map<std::string, std::pair<double, int>> per_problem;            // PPP id -> (sum of ratios, runs)
  std::map<std::string, const agents::EpisodeResult*> longest;          // PPP id -> its longest run
};

std::map<std::string, std::size_t> positions(const std::vector<std::string>& order) {
  std::map<std::string, std::size_t> at;
  for (std::size_t i = 0; i < order.size(); ++i) at.emplace(order[i], i);
  return at;
}

}  // namespace

std::vector<DetourStats> detourStats(const std::vector<agents::EpisodeResult>& rows,
                                     const std::vector<std::string>& set_order,
                                     const std::vector<std::string>& agent_order) {
  const std::map<std::string, std::size_t> set_at = positions(set_order), agent_at = positions(agent_order);
  std::vector<Collected> collected(set_order.size() * agent_order.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const agents::EpisodeResult& r = rows[i];
    const auto set = set_at.find(r.set);
    const auto agent = agent_at.find(r.agent);
    if (set == set_at.end() || agent == agent_at.end()) {
      throw InvalidArgument("results", "result " + std::to_string(i) + " is for set '" + r.set + "' and agent '" +
                                           r.agent + "', not both in the report's orders");
    }
    if (!r.passed || r.optimal_length <= 0) continue;
    Collected& c = collected[set->second * agent_order.size() + agent->second];
    const double ratio = r.path_length / r.optimal_length;
    c.ratios.push_back(ratio);
    c.soft_failures += r.soft_failure ? 1 : 0;
    auto& sum = c.per_problem[r.problem];
    sum.first += ratio;
    ++sum.second;
    const agents::EpisodeResult*& longest = c.longest[r.problem];
    if (longest == nullptr || ratio > longest->path_length / longest->optimal_length ||
        (ratio == longest->path_length / longest->optimal_length && r.run < longest->run)) {
      longest = &r;
    }
  }
  std::vector<DetourStats> stats;
  for (std::size_t s = 0; s < set_order.size(); ++s) {
    for (std::size_t a = 0; a < agent_order.size(); ++a) {
      Collected& c = collected[s * agent_order.size() + a];
      if (c.ratios.empty()) continue;
      std::sort(c.ratios.begin(), c.ratios.end());
      DetourStats d;
      d.set = set_order[s];
      d.agent = agent_order[a];
      d.passed = static_cast<int>(c.ratios.size());
      d.soft_failures = c.soft_failures;
      d.spread = {quantile(c.ratios, 0.05), quantile(c.ratios, 0.25), quantile(c.ratios, 0.5),
                  quantile(c.ratios, 0.75), quantile(c.ratios, 0.95)};
      d.max = c.ratios.back();
      d.worst_mean = -1;
      for (const auto& [problem, sum] : c.per_problem) {  // the first of equals in id order wins
        const double mean = sum.first / sum.second;
        if (mean > d.worst_mean) d.worst_mean = mean, d.worst_problem = problem;
      }
      d.longest = c.longest.at(d.worst_problem);
      stats.push_back(std::move(d));
    }
  }
  return stats;
}

}  // namespace simulator
}  // namespace ppp
