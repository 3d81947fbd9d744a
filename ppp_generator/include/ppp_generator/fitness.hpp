#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ppp_core/dpa.hpp"
#include "ppp_core/evaluation.hpp"
#include "ppp_core/problem.hpp"

namespace ppp {
namespace generator {

/// What a fitness function may be configured with.
struct FitnessParameters {
  DifficultyWeights weights;  ///< For `difficulty`.
  std::uint64_t seed = 1;     ///< For `random`: its values come from a generator seeded with this.
};

/// A named fitness function: a value per valid PPP, and whether selection maximises or minimises it.
struct Fitness {
  std::string name;   ///< Registry name, e.g. "turns".
  bool maximise = true;  ///< True when larger values are fitter (harder).
  /// The raw value of a valid PPP, given its decoded grid and DPA result.
  std::function<double(const Problem&, const Grid&, const DpaResult&)> value;

  /// Fitness as "larger is fitter" whatever the direction.
  double score(double raw_value) const { return maximise ? raw_value : -raw_value; }
};

/// One registry entry, as listed by `ppp generate --help`.
struct FitnessInfo {
  std::string name;         ///< Registry name.
  bool maximise;            ///< Direction of selection.
  std::string description;  ///< One line for users.
};

/// Every registered fitness function, in registry order.
std::vector<FitnessInfo> fitnessCatalogue();

/// Comma-separated registry names, for error messages.
std::string fitnessNames();

/// Builds a fitness function by name. @throws InvalidArgument("fitness", ...) listing the valid names.
Fitness makeFitness(const std::string& name, const FitnessParameters& parameters = {});

}  // namespace generator
}  // namespace ppp
