#include "ppp_simulator/simulator_options.hpp"

#include <string>

#include "ppp_core/option_yaml.hpp"

namespace ppp {
namespace simulator {

namespace {

/// Shortest timeout: a millisecond.
constexpr double kMinSeconds = 0.001;
/// Longest timeout: a day.
constexpr double kMaxSeconds = 86400;
/// Most episodes per message (a batch of 20x20 scans stays under ~100 MB).
constexpr int kMaxBatchSize = 100000;

}  // namespace

void SimulatorOptions::validate() const { checkOptionRanges(simulatorOptionSpecs(), *this); }

const std::vector<OptionSpec<SimulatorOptions>>& simulatorOptionSpecs() {
  using S = SimulatorOptions;
  // Pace, patience and recording: results are the same whatever they are (a silent agent's runs fail either way).
  static const std::vector<OptionSpec<S>> specs = [] {
    const Bounds seconds{kMinSeconds, kMaxSeconds};
    std::vector<OptionSpec<S>> list = {
      declareOption("batch_size",
                    "episodes per agent per message (ppp launch-file's graph in one nodelet manager: " +
                        std::to_string(kManagerBatchSize) + " unless given)",
                    +[](S& s) -> int& { return s.batch_size; }, Bounds{1, kMaxBatchSize}),
      declareOption("step_timeout", "seconds an agent node has to answer a batch",
                    +[](S& s) -> double& { return s.step_timeout; }, seconds),
      declareOption("planner_step_timeout", "seconds a planner agent's bridge has to answer a step",
                    +[](S& s) -> double& { return s.planner_step_timeout; }, seconds),
      declareOption("timeouts_before_giving_up", "unanswered batches in a row after which an agent's runs all fail",
                    +[](S& s) -> int& { return s.timeouts_before_giving_up; }, Bounds{1, 1000}),
      declareOption("connect_timeout", "seconds to wait for each agent node to connect (a planner agent's bridge connects once its "
                    "planner has: the experiment's graph raises this to the bridges' wait plus 10 s)",
                    +[](S& s) -> double& { return s.connect_timeout; }, seconds),
      declareOption("set_timeout", "seconds a set's topic may go without a publisher before giving up",
                    +[](S& s) -> double& { return s.set_timeout; }, seconds),
      declareOption("record", "write OUTPUT/experiment.bag", +[](S& s) -> bool& { return s.record; }),
      declareOption("record_runs", "runs recorded in detail per recorded PPP",
                    +[](S& s) -> int& { return s.record_runs; }, Bounds{0, 1000}),
      declareOption("record_problems", "PPPs of each set recorded in detail",
                    +[](S& s) -> int& { return s.record_problems; }, Bounds{0, 100000}),
      declareOption("resolution", "metres per cell in the map frame", +[](S& s) -> double& { return s.resolution; },
                    Bounds{1e-6, 1e6}),
    };
    for (OptionSpec<S>& spec : list) spec = spec.notAffectingResults();
    return list;
  }();
  return specs;
}

const std::vector<OptionSpec<SimulatorTask>>& simulatorTaskSpecs() {
  using T = SimulatorTask;
  static const std::vector<OptionSpec<T>> specs = [] {
    std::vector<OptionSpec<T>> list = {
        declareOption("mode", "what the node does", +[](T& t) -> std::string& { return t.mode; })
            .withChoices("mode", {{kExperimentMode, "run the experiment of ~config into ~output_dir"},
                                  {kHuntMode, "serve ~evaluate for hunts with ~config's agents until shut down"}}),
        declareOption("config", "the experiment YAML (required)", +[](T& t) -> std::string& { return t.config; }),
        declareOption("output_dir", "where results, report and bag go (required for an experiment)",
                      +[](T& t) -> std::string& { return t.output_dir; }),
        declareOption("generator_nodes", "play the sets the generator nodes publish instead of evolving them here",
                      +[](T& t) -> bool& { return t.generator_nodes; }),
        declareOption("planners",
                      "planner agents' nodes given at launch (NAME=PACKAGE/EXECUTABLE, or NAME= for one started by "
                      "hand) over the config's planner_node: they decide how many instances of each play",
                      +[](T& t) -> std::vector<std::string>& { return t.planners; }),
    };
    for (OptionSpec<T>& spec : list) spec = spec.notAffectingResults();  // where and how, never what
    return list;
  }();
  return specs;
}

}  // namespace simulator
}  // namespace ppp
