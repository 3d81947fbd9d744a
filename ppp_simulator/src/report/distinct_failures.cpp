#include "ppp_simulator/report/distinct_failures.hpp"

#include <algorithm>

namespace ppp {
namespace simulator {

void FailureGrouping::add(const std::string& key, const std::string& place, int obstacle_cells, std::size_t item) {
  const auto [it, added] = groups_.try_emplace(key);
  Group& group = it->second;
  if (added) {
    group.failure.key = key;
    group.failure.smallest = item;
    group.failure.smallest_cells = obstacle_cells;
    group.order = static_cast<int>(groups_.size());
  } else if (obstacle_cells < group.failure.smallest_cells) {
    group.failure.smallest = item;
    group.failure.smallest_cells = obstacle_cells;
  }
  ++group.failure.count;
  group.places.insert(place);
  ++total_;
}

std::vector<DistinctFailure> FailureGrouping::groups() const {
  std::vector<const Group*> order;
  for (const auto& entry : groups_) order.push_back(&entry.second);
  std::sort(order.begin(), order.end(), [](const Group* a, const Group* b) {
    return a->failure.count != b->failure.count ? a->failure.count > b->failure.count : a->order < b->order;
  });
  std::vector<DistinctFailure> kinds;
  for (const Group* group : order) {
    kinds.push_back(group->failure);
    kinds.back().places = static_cast<int>(group->places.size());
  }
  return kinds;
}

namespace {

std::string counting(int n, const std::string& what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

}  // namespace

std::string distinctFailureLine(const DistinctFailure& failure, const std::string& counted, const std::string& what,
                                const std::string& smallest_name, const std::string& replay) {
  std::string line = "  " + counting(failure.count, counted);
  if (counted != "PPP") line += " on " + counting(failure.places, "PPP");
  line += ": " + failure.key + (what.empty() ? "" : " (" + what + ")") + "; smallest " + smallest_name + ", " +
          counting(failure.smallest_cells, "obstacle cell");
  if (!replay.empty()) line += "; replay: " + replay;
  return line;
}

}  // namespace simulator
}  // namespace ppp
