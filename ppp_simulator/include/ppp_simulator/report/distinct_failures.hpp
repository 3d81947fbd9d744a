#pragma once

#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace ppp {
namespace simulator {

/// The failures of one kind (one failure signature, or one trap once shrunk): how many, on how many maps, and the
/// smallest of them.
struct DistinctFailure {
  std::string key;          ///< What the failures share: a signature (docs/reference/signatures.md) or a trap's file.
  int count = 0;            ///< Failures of this kind (runs, or PPPs shrunk to one trap).
  int places = 0;           ///< Different maps they happened on.
  std::size_t smallest = 0;  ///< The caller's item of the failure on the map with the fewest obstacle cells.
  int smallest_cells = 0;   ///< That map's obstacle cells.
};

/// Groups failures by kind so that a reader sees at once how many different things are wrong: each failure is
/// added with its key, the map it happened on and its obstacle cells, and an item (an index into the caller's
/// list) that stands for it.
class FailureGrouping {
 public:
  /// Counts failure `item` of kind `key` on map `place` of `obstacle_cells`; the group's smallest map is the one of
  /// fewest obstacle cells, the first added among equals.
  void add(const std::string& key, const std::string& place, int obstacle_cells, std::size_t item);
  /// The kinds, the most common first (the first added among equals).
  std::vector<DistinctFailure> groups() const;
  /// How many failures were added.
  int total() const { return total_; }

 private:
  struct Group {
    DistinctFailure failure;
    std::set<std::string> places;
    int order = 0;
  };
  std::map<std::string, Group> groups_;
  int total_ = 0;
};

/// One line per kind, for a terminal: "  3 runs on 2 PPPs: KEY (WHAT); smallest NAME, 5 obstacle cells; replay: CMD"
/// (`counted`: what a failure is, "run" or "PPP"; `what` and `replay` may be empty).
std::string distinctFailureLine(const DistinctFailure& failure, const std::string& counted, const std::string& what,
                                const std::string& smallest_name, const std::string& replay);

}  // namespace simulator
}  // namespace ppp
