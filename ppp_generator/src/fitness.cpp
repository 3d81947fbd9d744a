#include "ppp_generator/fitness.hpp"

#include <memory>

#include "ppp_core/error.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/visibility.hpp"

namespace ppp {
namespace generator {

namespace {

using ValueFunction = std::function<double(const Problem&, const Grid&, const DpaResult&)>;

/// One registry row: to add a fitness function, add a row here.
struct Entry {
  const char* name;
  bool maximise;
  const char* description;
  ValueFunction (*make)(const FitnessParameters&);
};

ValueFunction evaluationField(const FitnessParameters& p, double Evaluation::*field) {
  auto evaluator = std::make_shared<Evaluator>(p.weights);
  return [evaluator, field](const Problem& problem, const Grid& grid, const DpaResult& dpa) {
    return evaluator->evaluate(problem, grid, dpa).*field;
  };
}

const Entry kEntries[] = {
    {"turns", true, "Wei's: fewest turns of the optimal route (maximised)",
     [](const FitnessParameters&) -> ValueFunction {
       return [](const Problem&, const Grid&, const DpaResult& dpa) { return static_cast<double>(dpa.turns); };
     }},
    {"advances", true, "Ashlock's: fewest advances to the goal (maximised)",
     [](const FitnessParameters&) -> ValueFunction {
       return [](const Problem&, const Grid&, const DpaResult& dpa) { return static_cast<double>(dpa.advances); };
     }},
    {"turns_plus_advances", true, "Ashlock's: fewest turns + advances (maximised)",
     [](const FitnessParameters&) -> ValueFunction {
       return [](const Problem&, const Grid&, const DpaResult& dpa) {
         return static_cast<double>(dpa.turns_plus_advances);
       };
     }},
    {"difficulty", false, "visibility, openness and obstacle use; every weight a parameter (minimised)",
     [](const FitnessParameters& p) { return evaluationField(p, &Evaluation::difficulty); }},
    {"goal_visibility", false, "fraction of the grid visible from the goal (minimised)",
     [](const FitnessParameters&) -> ValueFunction {
       auto solver = std::make_shared<VisibilitySolver>();
       return [solver](const Problem& problem, const Grid& grid, const DpaResult&) {
         return static_cast<double>(solver->solve(grid, problem.goal)) / grid.size();
       };
     }},
    {"visibility_magnitude", false, "norm of the five viewpoint visibilities (minimised)",
     [](const FitnessParameters& p) { return evaluationField(p, &Evaluation::visibility_magnitude); }},
    {"random", true, "baseline: a random value per PPP, no selection pressure",
     [](const FitnessParameters& p) -> ValueFunction {
       auto rng = std::make_shared<Rng>(deriveSeed(p.seed, {0x66697431}));
       return [rng](const Problem&, const Grid&, const DpaResult&) { return rng->uniform01(); };
     }},
};

}  // namespace

std::vector<FitnessInfo> fitnessCatalogue() {
  std::vector<FitnessInfo> catalogue;
  for (const Entry& e : kEntries) catalogue.push_back({e.name, e.maximise, e.description});
  catalogue.push_back({kFailureFitness, true,
                       "share of failed episodes of the named agents (agents, runs_per_eval; maximised)"});
  catalogue.push_back({kRegretFitness, true,
                       "mean regret of the named agents: (moves used - fewest moves) / fewest moves, a failed run "
                       "using its whole budget (agents, runs_per_eval; maximised)"});
  return catalogue;
}

std::string fitnessNames() {
  std::string names;
  for (const FitnessInfo& info : fitnessCatalogue()) names += (names.empty() ? "" : ", ") + info.name;
  return names;
}

std::vector<OptionChoice> fitnessChoices() {
  std::vector<OptionChoice> choices;
  for (const FitnessInfo& info : fitnessCatalogue()) choices.push_back({info.name, info.description});
  return choices;
}

Fitness makeFitness(const std::string& name, const FitnessParameters& parameters) {
  for (const Entry& e : kEntries) {
    if (name == e.name) return Fitness{e.name, e.maximise, e.make(parameters), {}, 1};
  }
  if (isPanelFitness(name)) {
    throw InvalidArgument("fitness", "'" + name + "' plays episodes of an agent panel; it is built by the episode "
                                     "engine (ppp generate, ppp experiment, the simulator node), not on its own");
  }
  throw InvalidArgument("fitness", "unknown fitness '" + name + "'; valid: " + fitnessNames());
}

FitnessScore failureScore(double failure_rate, double budget_used) {
  return {failure_rate, failure_rate + 0.001 * budget_used};
}

FitnessScore regretScore(double regret, double budget_used) { return {regret, regret + 0.001 * budget_used}; }

bool isPanelFitness(const std::string& name) { return name == kFailureFitness || name == kRegretFitness; }

bool fitnessMaximises(const std::string& name) {
  for (const FitnessInfo& info : fitnessCatalogue()) {
    if (name == info.name) return info.maximise;
  }
  throw InvalidArgument("fitness", "unknown fitness '" + name + "'; valid: " + fitnessNames());
}

}  // namespace generator
}  // namespace ppp
