#pragma once

#include <string>
#include <vector>

#include "ppp_agents/episode_result.hpp"
#include "ppp_simulator/report/svg_plot.hpp"

namespace ppp {
namespace simulator {

/// How much longer than the optimum one agent's passed runs on one set were: path / optimal length.
struct DetourStats {
  std::string set;          ///< PPP set name.
  std::string agent;        ///< Agent configuration name.
  int passed = 0;           ///< Passed runs with a known optimum (soft failures included).
  int soft_failures = 0;    ///< Of them, soft failures.
  BoxStats spread;          ///< Percentiles of path / optimal over the passed runs (NaN when none passed).
  double max = 0;           ///< The largest path / optimal.
  std::string worst_problem;  ///< The PPP whose passed runs were longest against its optimum, on average.
  double worst_mean = 0;      ///< That average.
  const agents::EpisodeResult* longest = nullptr;  ///< Its passed run with the largest ratio (lowest run of equals).
};

/// Detour figures per (set, agent) with passed runs, in set order then agent order; rows with no known optimum
/// (optimal_length <= 0) are left out. Pointers refer into `rows`. @throws InvalidArgument naming "results" for
/// a row whose set or agent is not in the orders.
std::vector<DetourStats> detourStats(const std::vector<agents::EpisodeResult>& rows,
                                     const std::vector<std::string>& set_order,
                                     const std::vector<std::string>& agent_order);

}  // namespace simulator
}  // namespace ppp
