#include "ppp_generator/generator_node_options.hpp"

#include "ppp_core/option_yaml.hpp"
#include "ppp_generator/generator_options.hpp"

namespace ppp {
namespace generator {

void GeneratorNodeOptions::validate() const { checkOptionRanges(generatorNodeOptionSpecs(), *this); }

const std::vector<OptionSpec<GeneratorNodeOptions>>& generatorNodeOptionSpecs() {
  using N = GeneratorNodeOptions;
  static const std::vector<OptionSpec<N>> specs = [] {
    std::vector<OptionSpec<N>> list = {
        declareOption("options", "generator options as YAML text (config/generator.yaml's keys)",
                      +[](N& n) -> std::string& { return n.options_yaml; }),
        declareOption("set_name", "name of the published set ('': the fitness name)",
                      +[](N& n) -> std::string& { return n.set_name; }),
        declareOption("output_dir", "where the set's files are written ('': nowhere)",
                      +[](N& n) -> std::string& { return n.output_dir; }),
        declareOption("resume", "publish the set already in output_dir when it was evolved with these options",
                      +[](N& n) -> bool& { return n.resume; }),
        declareOption("publish_index", "which PPP of the set is published on map (below the population)",
                      +[](N& n) -> int& { return n.publish_index; }, Bounds{0, kMaxPopulation - 1}),
        declareOption("resolution", "metres per cell of the published maps",
                      +[](N& n) -> double& { return n.resolution; }, Bounds{1e-6, 1e6}),
        declareOption("generate_on_start", "evolve a set at start-up (else only on the generate service)",
                      +[](N& n) -> bool& { return n.generate_on_start; }),
        declareOption("exit_when_done", "exit once the start-up set is published",
                      +[](N& n) -> bool& { return n.exit_when_done; }),
        declareOption("evaluator",
                      "failure, regret: the simulator's EvaluateProblems service ('': play the panel in process)",
                      +[](N& n) -> std::string& { return n.evaluator; }),
        declareOption("evaluator_timeout", "seconds to wait for the evaluator to appear",
                      +[](N& n) -> double& { return n.evaluator_timeout; }, Bounds{0.001, 86400}),
        declareOption("wait_for_set",
                      "a ppp_msgs/ProblemSet topic to hear from before evolving: the generator of the set that "
                      "initial_pool reads ('': none)",
                      +[](N& n) -> std::string& { return n.wait_for_set; }),
    };
    for (std::size_t i = 1; i < list.size(); ++i) list[i] = list[i].notAffectingResults();  // where and how
    return list;
  }();
  return specs;
}

}  // namespace generator
}  // namespace ppp
