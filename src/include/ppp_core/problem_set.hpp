#pragma once

#include <string>
#include <vector>

#include "ppp_core/evaluation.hpp"
#include "ppp_core/problem.hpp"

namespace ppp {

/// A set of PPPs with everything the taxonomy and the reports need.
struct ProblemSet {
  std::string fitness;                   ///< Fitness function that produced the set.
  bool maximise = true;                  ///< Its direction.
  std::vector<std::string> ids;          ///< "ppp_000", ... (file stem of each PPP).
  std::vector<Problem> problems;         ///< The PPPs, metadata included.
  std::vector<Evaluation> evaluations;   ///< Every measure of each PPP.
  std::vector<double> fitness_values;    ///< Raw fitness value of each PPP.
  std::vector<double> nearest;           ///< Share of cells in which each PPP differs from its nearest other.
  double diversity = 0;                  ///< setDiversity of the PPPs' grids (see diversity.hpp).

  /// Fitness oriented so that larger is fitter ("harder"), per PPP.
  std::vector<double> hardness() const;
};

}  // namespace ppp
