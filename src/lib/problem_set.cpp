#include "ppp_core/problem_set.hpp"

namespace ppp {

std::vector<double> ProblemSet::hardness() const {
  std::vector<double> h;
  for (double v : fitness_values) h.push_back(maximise ? v : -v);
  return h;
}

}  // namespace ppp
