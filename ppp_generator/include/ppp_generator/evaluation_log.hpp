#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "ppp_generator/fitness.hpp"

namespace ppp {
namespace generator {

/// Every PPP a hunt scored, in the order it scored them: what a hunt's power is measured from (how many evaluations
/// and how long to its first failing PPP, failing PPPs per evaluation). A set directory's evaluations.csv.
class EvaluationLog {
 public:
  /// Starts the clock of the log's `seconds` column.
  EvaluationLog();

  /// `fitness` with its batch scorer wrapped so that each PPP it scores adds a row; a fitness without one (scored
  /// by value, never failing anything) is returned unchanged and adds none.
  Fitness wrap(Fitness fitness) const;

  /// True when no PPP was scored through a wrapped fitness.
  bool empty() const;

  /// The rows as CSV: `evaluation` (1, 2, ... in scoring order), `seconds` (wall time since the log was made,
  /// the one column that differs between two runs of a seed), `value` (the raw fitness), `failure_rate` (the share
  /// of the panel's runs that failed), `grid` (the PPP's grid hash, 16 hex digits: one PPP scored twice has one).
  std::string csv() const;

 private:
  struct Rows {
    std::chrono::steady_clock::time_point start;
    std::string text;
    long count = 0;
  };
  std::shared_ptr<Rows> rows_;
};

/// The name of the log in a set directory.
constexpr const char* kEvaluationLogFile = "evaluations.csv";

/// An evaluations.csv without its `seconds` column: what two runs of one seed write alike (in process or through ROS).
std::string withoutSeconds(const std::string& evaluations_csv);

}  // namespace generator
}  // namespace ppp
