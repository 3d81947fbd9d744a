#include "ppp_simulator/report/pass_rates.hpp"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <map>
#include <tuple>

#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/text_file.hpp"

namespace ppp {
namespace simulator {

namespace {

bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

/// -1, 0 or 1 as `a` sorts before, with or after `b` when digit runs are read as numbers.
int naturalCompare(const std::string& a, const std::string& b) {
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    if (isDigit(a[i]) && isDigit(b[j])) {
      std::size_t end_i = i;
      std::size_t end_j = j;
      while (end_i < a.size() && isDigit(a[end_i])) ++end_i;
      while (end_j < b.size() && isDigit(b[end_j])) ++end_j;
      std::size_t start_i = i;
      std::size_t start_j = j;
      while (start_i + 1 < end_i && a[start_i] == '0') ++start_i;
      while (start_j + 1 < end_j && b[start_j] == '0') ++start_j;
      const std::size_t length_i = end_i - start_i;
      const std::size_t length_j = end_j - start_j;
      if (length_i != length_j) return length_i < length_j ? -1 : 1;
      const int digits = a.compare(start_i, length_i, b, start_j, length_j);
      if (digits != 0) return digits < 0 ? -1 : 1;
      i = end_i;
      j = end_j;
    } else {
      if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]) ? -1 : 1;
      ++i;
      ++j;
    }
  }
  if (i < a.size()) return 1;
  if (j < b.size()) return -1;
  return 0;
}

/// Position of every name in an order. @throws InvalidArgument naming `what` for an empty or repeated name.
std::map<std::string, int> indexOrder(const std::vector<std::string>& order, const char* what) {
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (order[i].empty()) throw InvalidArgument(what, "entry " + std::to_string(i) + " is empty, expected a name");
    if (!index.emplace(order[i], static_cast<int>(i)).second) {
      throw InvalidArgument(what, "'" + order[i] + "' is listed twice, expected each name once");
    }
  }
  return index;
}

/// Sort key of a per-PPP row: set position, PPP id, agent position.
struct ProblemKey {
  int set = 0;
  std::string problem;
  int agent = 0;
};

struct ProblemKeyLess {
  bool operator()(const ProblemKey& a, const ProblemKey& b) const {
    if (a.set != b.set) return a.set < b.set;
    if (a.problem != b.problem) return naturalLess(a.problem, b.problem);
    return a.agent < b.agent;
  }
};

struct Tally {
  int runs = 0;
  int passes = 0;
  int soft_failures = 0;
  DiagnosisCounts diagnoses;
  double steps = 0;
};

/// summary.csv's diagnosis fields of `counts`.
std::vector<std::string> diagnosisFields(const DiagnosisCounts& counts) {
  std::vector<std::string> fields;
  for (const int n : counts.kinds) fields.push_back(std::to_string(n));
  fields.push_back(std::to_string(counts.endless));
  return fields;
}

/// A summary.csv line: `fields`, then the diagnosis counts.
std::string summaryLine(std::vector<std::string> fields, const DiagnosisCounts& counts) {
  for (std::string& f : diagnosisFields(counts)) fields.push_back(std::move(f));
  return csvLine(fields) + "\n";
}

}  // namespace

void DiagnosisCounts::add(const agents::EpisodeResult& result) {
  if (result.diagnosis.empty()) return;
  const int index = diagnosis::kindIndex(result.diagnosis);
  if (index >= 0) ++kinds[static_cast<std::size_t>(index)];
  if (result.endless_step >= 0) ++endless;
  if (result.reason == reason::kCollision) ++collisions;
}

void DiagnosisCounts::add(const DiagnosisCounts& other) {
  for (std::size_t i = 0; i < kinds.size(); ++i) kinds[i] += other.kinds[i];
  endless += other.endless;
  collisions += other.collisions;
}

double ProblemPassRate::rate() const { return runs > 0 ? static_cast<double>(passes) / runs : 0.0; }

const SetPassRate* PassRateTable::find(const std::string& set, const std::string& agent) const {
  for (const SetPassRate& row : per_set) {
    if (row.set == set && row.agent == agent) return &row;
  }
  return nullptr;
}

std::vector<double> PassRateTable::problemRates(const std::string& set, const std::string& agent) const {
  std::vector<double> rates;
  for (const ProblemPassRate& row : per_problem) {
    if (row.set == set && row.agent == agent) rates.push_back(row.rate());
  }
  return rates;
}

bool naturalLess(const std::string& a, const std::string& b) {
  const int natural = naturalCompare(a, b);
  return natural != 0 ? natural < 0 : a < b;  // "p01" and "p1" are distinct ids: fall back to bytes
}

std::vector<ResultGroup> groupResults(const std::vector<agents::EpisodeResult>& results) {
  std::vector<ResultGroup> groups;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const agents::EpisodeResult& r = results[i];
    if (groups.empty() || groups.back().row->agent != r.agent || groups.back().row->problem != r.problem ||
        groups.back().row->set != r.set) {
      ResultGroup group;
      group.row = &r;
      group.index = i;
      groups.push_back(group);
    }
    ResultGroup& group = groups.back();
    ++group.runs;
    if (r.passed) ++group.passes;
    if (r.soft_failure) ++group.soft_failures;
    group.diagnoses.add(r);
    group.steps += r.steps;
    if (!r.passed && (group.first_fail == nullptr || r.run < group.first_fail->run)) group.first_fail = &r;
  }
  return groups;
}

PassRateTable computePassRates(const std::vector<agents::EpisodeResult>& results, const std::vector<std::string>& set_order,
                               const std::vector<std::string>& agent_order) {
  return computeGroupedPassRates(groupResults(results), set_order, agent_order);
}

PassRateTable computeGroupedPassRates(const std::vector<ResultGroup>& groups, const std::vector<std::string>& set_order,
                               const std::vector<std::string>& agent_order) {
  const std::map<std::string, int> set_index = indexOrder(set_order, "set_order");
  const std::map<std::string, int> agent_index = indexOrder(agent_order, "agent_order");

  std::map<ProblemKey, Tally, ProblemKeyLess> tallies;
  for (const ResultGroup& group : groups) {
    const agents::EpisodeResult& result = *group.row;
    const std::string where = "result " + std::to_string(group.index);
    const auto set = set_index.find(result.set);
    if (set == set_index.end()) {
      throw InvalidArgument("results", where + " is for set '" + result.set + "', which is not in set_order");
    }
    const auto agent = agent_index.find(result.agent);
    if (agent == agent_index.end()) {
      throw InvalidArgument("results", where + " is for agent '" + result.agent + "', which is not in agent_order");
    }
    if (result.problem.empty()) throw InvalidArgument("results", where + " has an empty problem id");
    Tally& tally = tallies[ProblemKey{set->second, result.problem, agent->second}];
    tally.runs += group.runs;
    tally.passes += group.passes;
    tally.soft_failures += group.soft_failures;
    tally.diagnoses.add(group.diagnoses);
    tally.steps += group.steps;
  }

  PassRateTable table;
  table.sets = set_order;
  table.agents = agent_order;
  table.per_problem.reserve(tallies.size());
  // Per (set, agent): sums of the per-PPP rates and the counts, in set-major, agent-minor order.
  std::vector<SetPassRate> sums(set_order.size() * agent_order.size());
  for (const auto& [key, tally] : tallies) {
    ProblemPassRate row;
    row.set = set_order[static_cast<std::size_t>(key.set)];
    row.problem = key.problem;
    row.agent = agent_order[static_cast<std::size_t>(key.agent)];
    row.runs = tally.runs;
    row.passes = tally.passes;
    row.soft_failures = tally.soft_failures;
    row.diagnoses = tally.diagnoses;
    row.mean_steps = tally.steps / tally.runs;
    const std::size_t slot = static_cast<std::size_t>(key.set) * agent_order.size() + static_cast<std::size_t>(key.agent);
    SetPassRate& sum = sums[slot];
    ++sum.problems;
    sum.runs += row.runs;
    sum.passes += row.passes;
    sum.soft_failures += row.soft_failures;
    sum.diagnoses.add(row.diagnoses);
    sum.mean_rate += row.rate();
    table.per_problem.push_back(std::move(row));
  }
  for (std::size_t s = 0; s < set_order.size(); ++s) {
    for (std::size_t a = 0; a < agent_order.size(); ++a) {
      SetPassRate row = sums[s * agent_order.size() + a];
      if (row.problems == 0) continue;
      row.set = set_order[s];
      row.agent = agent_order[a];
      row.mean_rate /= row.problems;
      table.per_set.push_back(std::move(row));
    }
  }
  return table;
}

const std::vector<std::string>& summaryCsvHeader() {
  static const std::vector<std::string> header = [] {
    std::vector<std::string> h = {"level", "set", "problem", "agent", "problems", "runs", "passes", "pass_rate",
                                  "soft_failures"};
    for (const char* kind : diagnosis::kKinds) h.push_back(kind);
    h.push_back("endless_loops");
    return h;
  }();
  return header;
}

void writeSummaryCsv(const std::string& path, const PassRateTable& table) {
  std::string text = csvLine(summaryCsvHeader()) + "\n";
  for (const ProblemPassRate& row : table.per_problem) {
    text += summaryLine({"problem", row.set, row.problem, row.agent, "1", std::to_string(row.runs),
                         std::to_string(row.passes), formatNumber(row.rate()), std::to_string(row.soft_failures)},
                        row.diagnoses);
  }
  for (const SetPassRate& row : table.per_set) {
    text += summaryLine({"set", row.set, "", row.agent, std::to_string(row.problems), std::to_string(row.runs),
                         std::to_string(row.passes), formatNumber(row.mean_rate), std::to_string(row.soft_failures)},
                        row.diagnoses);
  }
  writeFileAtomically(path, text);
}

}  // namespace simulator
}  // namespace ppp
