#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_simulator/report/pass_rates.hpp"
#include "ppp_simulator/results_file.hpp"
#include "ppp_simulator/report/statistics.hpp"

namespace ppp {
namespace cli {

namespace {

struct CompareFlags {
  std::string dir_a;
  std::string dir_b;
  std::string set_a;
  std::string set_b;
  bool json = false;
};

/// Set and agent names in order of first appearance.
void namesInOrder(const std::vector<agents::EpisodeResult>& rows, std::vector<std::string>* sets,
                  std::vector<std::string>* agents) {
  for (const auto& r : rows) {
    if (std::find(sets->begin(), sets->end(), r.set) == sets->end()) sets->push_back(r.set);
    if (std::find(agents->begin(), agents->end(), r.agent) == agents->end()) agents->push_back(r.agent);
  }
}

void runCompare(const CompareFlags& f) {
  namespace fs = std::filesystem;
  const bool same = fs::weakly_canonical(f.dir_a) == fs::weakly_canonical(f.dir_b);
  std::vector<agents::EpisodeResult> rows = simulator::readResultsFile(f.dir_a + "/results.csv");
  std::vector<std::string> sets_a, sets_b, agents;
  namesInOrder(rows, &sets_a, &agents);
  if (sets_a.empty()) throw InvalidArgument(f.dir_a, "results.csv holds no runs");
  std::string set_a = f.set_a.empty() ? sets_a[0] : f.set_a;
  std::string set_b = f.set_b;
  if (same) {
    if (set_b.empty()) {
      if (sets_a.size() < 2) throw InvalidArgument("--set-b", f.dir_a + " holds one set; name the sets to compare");
      set_b = sets_a[1];
    }
  } else {
    auto rows_b = simulator::readResultsFile(f.dir_b + "/results.csv");
    namesInOrder(rows_b, &sets_b, &agents);
    if (sets_b.empty()) throw InvalidArgument(f.dir_b, "results.csv holds no runs");
    if (set_b.empty()) set_b = sets_b[0];
    // Sets of the second directory are named "B:<set>" so equal names in both directories stay apart.
    for (auto& r : rows_b) r.set = "B:" + r.set;
    set_b = "B:" + set_b;
    rows.insert(rows.end(), rows_b.begin(), rows_b.end());
  }
  std::vector<std::string> all_sets;
  std::vector<std::string> ignored;
  namesInOrder(rows, &all_sets, &ignored);
  const simulator::PassRateTable table = simulator::computePassRates(rows, all_sets, agents);
  const auto comparisons = simulator::compareSets(table, set_a, set_b);
  if (f.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& c : comparisons) {
      out.push_back({{"agent", c.agent}, {"mean_a", c.mean_a}, {"mean_b", c.mean_b}, {"u", c.test.u},
                     {"z", c.test.z}, {"p", c.test.p}, {"n_a", c.test.n_a}, {"n_b", c.test.n_b}});
    }
    std::cout << out.dump(1) << "\n";
    return;
  }
  std::cout << "Mann-Whitney U per agent: per-PPP pass rates of set A '" << set_a << "' vs set B '" << set_b
            << "'\n";
  std::printf("%-24s %8s %8s %10s %8s %10s\n", "agent", "A %", "B %", "U", "z", "p");
  for (const auto& c : comparisons) {
    std::printf("%-24s %8.1f %8.1f %10.1f %8.3f %10.4g%s\n", c.agent.c_str(), 100 * c.mean_a, 100 * c.mean_b,
                c.test.u, c.test.z, c.test.p, c.test.p < 0.05 ? "  *" : "");
  }
  std::cout << "(* significant at 0.05, two-sided, normal approximation with tie correction)\n";
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto flags = std::make_shared<CompareFlags>();
  CLI::App* command = app.add_subcommand(
      "compare", "Mann-Whitney U test per agent between two sets' per-PPP pass rates (two experiment directories, "
                 "or one directory and two of its sets)");
  command->add_option("dir_a", flags->dir_a, "Experiment directory holding set A")->required();
  command->add_option("dir_b", flags->dir_b, "Experiment directory holding set B (may be the same)")->required();
  command->add_option("--set-a", flags->set_a, "Set A (default: the first set of dir_a)");
  command->add_option("--set-b", flags->set_b, "Set B (default: the first set of dir_b, or the second of dir_a)");
  command->add_flag("--json", flags->json, "Print the table as JSON");
  command->callback([flags] { runCompare(*flags); });
}

}  // namespace cli
}  // namespace ppp
