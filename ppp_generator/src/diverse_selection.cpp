#include "ppp_generator/diverse_selection.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "ppp_core/error.hpp"

namespace ppp::generator {

namespace {

int medoid(const std::vector<int>& members, const Eigen::MatrixXd& distances) {
  int best = members.front();
  double best_total = 0;
  bool first = true;
  for (const int candidate : members) {
    double total = 0;  // the mean over the same member count, so the sum ranks alike
    for (const int other : members) total += distances(candidate, other);
    if (first || total < best_total) {
      best = candidate;
      best_total = total;
      first = false;
    }
  }
  return best;
}

int hardest(const std::vector<int>& members, const std::vector<double>& hardness) {
  int best = members.front();
  for (const int candidate : members) {
    if (hardness[static_cast<std::size_t>(candidate)] > hardness[static_cast<std::size_t>(best)]) best = candidate;
  }
  return best;
}

}  // namespace

std::vector<int> selectDiverse(const Tree& tree, const Eigen::MatrixXd& distances, int k,
                               const std::vector<double>* hardness) {
  validateTree(tree);
  const int n = tree.leafCount();
  if (distances.rows() != n || distances.cols() != n) {
    throw InvalidArgument("distances", "matrix is " + std::to_string(distances.rows()) + " x " +
                                           std::to_string(distances.cols()) + ", expected " + std::to_string(n) +
                                           " x " + std::to_string(n) + " for the tree's leaves");
  }
  if (hardness != nullptr) {
    if (hardness->size() != static_cast<std::size_t>(n)) {
      throw InvalidArgument("hardness", std::to_string(hardness->size()) + " values for " + std::to_string(n) +
                                            " PPPs, expected one per PPP");
    }
    for (std::size_t i = 0; i < hardness->size(); ++i) {
      if (!std::isfinite((*hardness)[i])) {
        throw InvalidArgument("hardness", "value " + std::to_string(i) + " is not a finite number");
      }
    }
  }
  std::vector<int> picks;
  for (const std::vector<int>& cluster : cutIntoClusters(tree, k)) {
    picks.push_back(hardness != nullptr ? hardest(cluster, *hardness) : medoid(cluster, distances));
  }
  return picks;
}

}  // namespace ppp::generator
