#pragma once

#include <string>
#include <vector>

#include "ppp_simulator/report/pass_rates.hpp"

namespace ppp {
namespace simulator {

/// A published pass rate to show beside the measured one (`reference:` in an experiment YAML, e.g. the
/// dissertation's Table 5.1).
struct ReferenceRate {
  std::string set;     ///< A set of the experiment.
  std::string agent;   ///< An agent of the experiment.
  double percent = 0;  ///< The published mean pass rate over the set's PPPs, in percent [0, 100].
};

/// A measured mean pass rate beside its reference.
struct ReferenceComparison {
  std::string set;        ///< PPP set name.
  std::string agent;      ///< Agent configuration name.
  double reference = 0;   ///< The published rate, in [0, 1].
  bool measured = false;  ///< False when the agent has no results on the set (the fields below are then 0).
  double mean = 0;        ///< The measured mean over the set's PPPs of their pass rates, in [0, 1].
  int problems = 0;       ///< PPPs the mean is over.
  double margin = 0;      ///< Half-width of the mean's 95 % interval: 1.96 x the per-PPP rates' sample standard
                          ///< deviation / sqrt(problems); 0 for a single PPP.
  /// The reference lies within mean +- margin: another set of as many PPPs like this one could have given it.
  bool within() const;
};

/// Each reference beside the measured rate of its set and agent, in the references' order.
std::vector<ReferenceComparison> compareWithReference(const PassRateTable& rates,
                                                      const std::vector<ReferenceRate>& reference);

}  // namespace simulator
}  // namespace ppp
