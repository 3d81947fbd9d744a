#pragma once

#include <Eigen/Core>

#include <vector>

#include "ppp_generator/taxonomy.hpp"

namespace ppp::generator {

/// "Give me k PPPs": cuts the tree into k clusters (cutIntoClusters) and picks one leaf per cluster, in
/// cluster order. Without `hardness` the pick is the cluster's medoid (smallest mean distance to the other
/// members); with it, the member with the largest hardness value (so pass e.g. fitness, or the negated
/// difficulty score). Ties go to the lowest index.
/// @throws InvalidArgument naming "k" unless 1 <= k <= leaves, "distances" unless it is leaves x leaves,
/// "hardness" unless it has one finite value per leaf, "tree" for a malformed tree.
std::vector<int> selectDiverse(const Tree& tree, const Eigen::MatrixXd& distances, int k,
                               const std::vector<double>* hardness = nullptr);

}  // namespace ppp::generator
