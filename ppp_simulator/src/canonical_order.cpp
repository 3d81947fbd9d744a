#include "ppp_simulator/canonical_order.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>

#include "ppp_core/error.hpp"

namespace ppp {
namespace simulator {

namespace {

constexpr std::size_t kRowsPerStopCheck = 1 << 14;  // rows handled between two questions to the StopCheck

/// Positions of names, asked row after row: the previous answer is kept, since consecutive rows mostly name the
/// same set, PPP and agent.
class NameIndex {
 public:
  /// The position of `name`, or -1 when it is not listed.
  int find(const std::string& name) { return lookUp(name, false); }
  /// The position of `name`, listing it after the others when it is not listed yet.
  int findOrAdd(const std::string& name) { return lookUp(name, true); }
  /// Lists `name` at `position` (a name listed twice keeps its first position).
  void add(const std::string& name, int position) { index_.emplace(name, position); }
  /// Every listed name with its position.
  const std::unordered_map<std::string, int>& positions() const { return index_; }

 private:
  int lookUp(const std::string& name, bool add) {
    if (last_ != nullptr && *last_ == name) return last_index_;
    auto it = index_.find(name);
    if (it == index_.end()) {
      if (!add) return -1;
      it = index_.emplace(name, static_cast<int>(index_.size())).first;
    }
    last_ = &it->first;
    last_index_ = it->second;
    return last_index_;
  }

  std::unordered_map<std::string, int> index_;
  const std::string* last_ = nullptr;
  int last_index_ = -1;
};

/// Each row's problem id as its rank in text order among every id of the sets and of the rows.
/// @throws Interrupted.
std::vector<int> problemRanks(const std::vector<agents::EpisodeResult>& rows, const std::vector<agents::PreparedSet>& sets,
                              const StopCheck& stop) {
  NameIndex distinct;
  for (const agents::PreparedSet& set : sets) {
    for (const std::string& id : set.set.ids) distinct.findOrAdd(id);
  }
  std::vector<int> problem_of_row(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i % kRowsPerStopCheck == 0) stopIfAsked(stop);
    problem_of_row[i] = distinct.findOrAdd(rows[i].problem);
  }
  std::vector<std::pair<const std::string*, int>> by_text;
  for (const auto& [id, index] : distinct.positions()) by_text.emplace_back(&id, index);
  std::sort(by_text.begin(), by_text.end(), [](const auto& a, const auto& b) { return *a.first < *b.first; });
  std::vector<int> rank(by_text.size());
  for (std::size_t r = 0; r < by_text.size(); ++r) {
    rank[static_cast<std::size_t>(by_text[r].second)] = static_cast<int>(r);
  }
  for (int& problem : problem_of_row) problem = rank[static_cast<std::size_t>(problem)];
  return problem_of_row;
}

}  // namespace

bool putInCanonicalOrder(std::vector<agents::EpisodeResult>* rows, const ExperimentConfig& config,
                         const std::vector<agents::PreparedSet>& sets, const std::string& path, const StopCheck& stop) {
  NameIndex set_order, agent_order;
  for (std::size_t i = 0; i < sets.size(); ++i) set_order.add(sets[i].name, static_cast<int>(i));
  for (std::size_t i = 0; i < config.agents.size(); ++i) agent_order.add(config.agents[i].name, static_cast<int>(i));
  const std::vector<int> problem_rank = problemRanks(*rows, sets, stop);
  // Each row's (set, problem, agent, run) positions, looked up once, then ordered as plain numbers.
  std::vector<std::pair<std::array<int, 4>, std::size_t>> keys(rows->size());
  for (std::size_t i = 0; i < rows->size(); ++i) {
    if (i % kRowsPerStopCheck == 0) stopIfAsked(stop);
    const agents::EpisodeResult& row = (*rows)[i];
    const int set = set_order.find(row.set);
    const int agent = agent_order.find(row.agent);
    if (set < 0 || agent < 0) {
      throw ParseError(path, 0, "row",
                       "run of set '" + row.set + "', agent '" + row.agent + "' is not part of this experiment");
    }
    keys[i] = {{set, problem_rank[i], agent, row.run}, i};
  }
  stopIfAsked(stop);
  // A run that was not interrupted wrote its rows in canonical order (OrderedAppender): nothing to move then.
  const auto not_rising = [](const auto& a, const auto& b) { return !(a.first < b.first); };
  if (std::adjacent_find(keys.begin(), keys.end(), not_rising) == keys.end()) return false;
  std::sort(keys.begin(), keys.end());
  // Row j of the result is row keys[j].second of the input: moved along each cycle of that permutation, in place
  // (a sorted copy of a million rows would be as large again).
  std::vector<bool> placed(rows->size());
  for (std::size_t start = 0; start < rows->size(); ++start) {
    if (placed[start]) continue;
    agents::EpisodeResult first = std::move((*rows)[start]);
    std::size_t j = start;
    for (std::size_t from = keys[j].second; from != start; j = from, from = keys[j].second) {
      (*rows)[j] = std::move((*rows)[from]);
      placed[j] = true;
    }
    (*rows)[j] = std::move(first);
    placed[j] = true;
  }
  return true;
}

}  // namespace simulator
}  // namespace ppp
