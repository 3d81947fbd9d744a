#include "ppp_generator/hunt_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "ppp_core/continuous_episode.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace generator {

namespace {

/// Candidate ids within the request ("c0", "c1", ...): results name their PPP by id.
std::string candidateId(std::size_t index) { return "c" + std::to_string(index); }

}  // namespace

HuntEvaluation::HuntEvaluation(const std::vector<Problem>& problems, const std::vector<agents::AgentConfig>& panel,
                               const EpisodeOptions& episode, int runs, std::uint64_t generator_seed, int batch_size,
                               const std::vector<std::uint64_t>& run_seeds)
    : runs_(runs), keeps_rows_(!run_seeds.empty()), motion_(episode.motion) {
  if (runs < 1 || runs > generator::kMaxRunsPerEval) {
    throw InvalidArgument("runs", "expected runs in [1, " + std::to_string(generator::kMaxRunsPerEval) + "], got " +
                                      std::to_string(runs));
  }
  if (!run_seeds.empty() && run_seeds.size() != static_cast<std::size_t>(runs)) {
    throw InvalidArgument("run_seeds", "expected one seed per run (" + std::to_string(runs) + "), got " +
                                           std::to_string(run_seeds.size()));
  }
  ProblemSet set;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    set.ids.push_back(candidateId(i));
    set.problems.push_back(problems[i]);
  }
  try {
    sets_.push_back(agents::prepareSet("candidates", std::move(set), episode));
  } catch (const InvalidArgument& e) {
    throw InvalidArgument("problems", e.what());
  }
  std::vector<std::uint64_t> hashes;
  for (const Grid& grid : sets_[0].grids) hashes.push_back(grid.hash());
  for (std::size_t a = 0; a < panel.size(); ++a) {
    agent_index_[panel[a].name] = static_cast<int>(a);
    const int instances = agents::instanceCount(panel[a], episode);
    const agents::AgentLane::SeedFunction seed_of = [hashes, generator_seed, run_seeds, name = panel[a].name](
                                                        int, int problem, int run) {
      if (!run_seeds.empty()) return run_seeds[static_cast<std::size_t>(run)];
      return failureRunSeed(generator_seed, hashes[static_cast<std::size_t>(problem)], name, run);
    };
    continuous_.push_back(agents::playsContinuously(panel[a], episode));
    for (int instance = 0; instance < instances; ++instance) {
      const agents::LaneShare share{instance, instances};
      if (continuous_.back()) {
        continuous_lanes_.push_back(std::make_unique<agents::ContinuousLane>(
            panel[a], episode, sets_, seed_of, runs, batch_size, agents::AgentLane::SkipFunction{}, share));
      } else {
        lanes_.push_back(std::make_unique<agents::AgentLane>(panel[a], episode, sets_, seed_of, runs, batch_size,
                                                             agents::AgentLane::SkipFunction{}, share));
      }
    }
  }
  tallies_.assign(problems.size(), PanelTally(panel.size()));
  evaluations_.assign(problems.size(), PanelEvaluation{});
}

void HuntEvaluation::record(const std::vector<agents::EpisodeResult>& ended) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const agents::EpisodeResult& r : ended) {
    const std::size_t p = static_cast<std::size_t>(std::stoi(r.problem.substr(1)));
    const auto a = static_cast<std::size_t>(agent_index_.at(r.agent));
    PanelEvaluation& e = evaluations_.at(p);
    ++e.episodes;
    const bool passed = r.passed && !r.soft_failure;
    const int budget = sets_[0].budgets[p];
    if (continuous_[a]) {
      // Its control periods as a fraction of its own budget, on the grid's budget; its optimum the same fraction
      // (the optimal route's time at top speed): regret is that of simulated time.
      const int optimal = static_cast<int>(r.optimal_length);
      const double periods = static_cast<double>(continuousStepBudget(motion_, optimal));
      const double fastest = optimal * motion_.resolution / motion_.max_linear_speed / motion_.control_period;
      tallies_[p].add(a, passed, static_cast<int>(std::lround(std::min<double>(r.steps, periods) / periods * budget)),
                      budget, std::max(1, static_cast<int>(std::lround(fastest / periods * budget))));
    } else {
      tallies_[p].add(a, passed, r.steps, budget, sets_[0].moves[p]);
    }
    tallies_[p].played[a] += r.steps;
    if (!r.diagnosis.empty()) ++e.diagnoses[r.diagnosis];
    if (!r.signature.empty()) ++e.estimate.signatures[r.signature];
    if (r.endless_step >= 0) ++e.endless;
    if (!passed) {
      ++e.failed;
      ++e.reasons[r.soft_failure ? kSoftFailureReason : r.reason];
    }
  }
  if (keeps_rows_) rows_.insert(rows_.end(), ended.begin(), ended.end());
}

bool HuntEvaluation::finished() const {
  const auto done = [](const auto& lane) { return lane->finished(); };
  return std::all_of(lanes_.begin(), lanes_.end(), done) &&
         std::all_of(continuous_lanes_.begin(), continuous_lanes_.end(), done);
}

std::vector<agents::EpisodeResult> HuntEvaluation::rows() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return rows_;
}

std::vector<PanelEvaluation> HuntEvaluation::evaluations() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<PanelEvaluation> result = evaluations_;
  for (std::size_t p = 0; p < result.size(); ++p) {
    FailureEstimate estimate = estimateOf(tallies_[p], runs_, sets_[0].budgets[p]);
    estimate.signatures = std::move(result[p].estimate.signatures);  // counted run by run in record()
    result[p].estimate = std::move(estimate);
  }
  return result;
}

}  // namespace generator
}  // namespace ppp
