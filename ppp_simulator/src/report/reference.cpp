#include "ppp_simulator/report/reference.hpp"

#include <cmath>

namespace ppp {
namespace simulator {

namespace {

constexpr double kNormal95 = 1.959963984540054;  // the standard normal's 97.5th percentile

}  // namespace

bool ReferenceComparison::within() const { return measured && std::abs(mean - reference) <= margin; }

std::vector<ReferenceComparison> compareWithReference(const PassRateTable& rates,
                                                      const std::vector<ReferenceRate>& reference) {
  std::vector<ReferenceComparison> rows;
  for (const ReferenceRate& r : reference) {
    ReferenceComparison row{r.set, r.agent, r.percent / 100};
    const std::vector<double> per_problem = rates.problemRates(r.set, r.agent);
    row.measured = !per_problem.empty();
    row.problems = static_cast<int>(per_problem.size());
    if (row.measured) {
      double sum = 0;
      for (double rate : per_problem) sum += rate;
      row.mean = sum / row.problems;
      double squares = 0;
      for (double rate : per_problem) squares += (rate - row.mean) * (rate - row.mean);
      if (row.problems > 1) row.margin = kNormal95 * std::sqrt(squares / (row.problems - 1) / row.problems);
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace simulator
}  // namespace ppp
