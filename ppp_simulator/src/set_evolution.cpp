#include "ppp_simulator/set_evolution.hpp"

#include "ppp_core/csv.hpp"
#include "ppp_generator/map_elites.hpp"
#include "ppp_simulator/failure_fitness.hpp"

namespace ppp {
namespace simulator {

namespace {

generator::Fitness fitnessFor(const generator::GeneratorOptions& options,
                              const std::vector<agents::AgentConfig>& available, const EpisodeOptions& episode,
                              int threads) {
  if (options.fitness != generator::kFailureFitness) {
    return generator::makeFitness(options.fitness, generator::FitnessParameters{options.weights, options.seed});
  }
  FailurePanel panel;
  panel.agents = resolvePanel(options.agents, available);
  panel.episode = episode;
  panel.runs_per_eval = options.runs_per_eval;
  panel.seed = options.seed;
  panel.threads = threads;
  return makeFailureFitness(panel);
}

}  // namespace

EvolvedSet evolveSet(const generator::GeneratorOptions& options, const std::vector<agents::AgentConfig>& available,
                     const EpisodeOptions& episode, int threads, const generator::ProgressCallback& progress) {
  options.validate();
  generator::Fitness fitness = fitnessFor(options, available, episode, threads);
  EvolvedSet evolved;
  if (options.archive == generator::kMapElitesArchive) {
    generator::MapElites search(options, std::move(fitness));
    evolved.set = generator::makeProblemSet(options, search.run(progress));
    std::map<std::uint64_t, std::string> ids;
    for (std::size_t i = 0; i < evolved.set.problems.size(); ++i) {
      ids[decodeGrid(evolved.set.problems[i]).hash()] = evolved.set.ids[i];
    }
    std::vector<generator::FeatureRange> ranges;
    for (const std::string& name : options.features) ranges.push_back(generator::featureRange(name, options));
    evolved.extra_files["archive.csv"] = generator::archiveCsv(search.archive(), options.features, ids);
    evolved.extra_files["archive.svg"] = generator::archiveHeatMapSvg(
        search.archive(), options.features, ranges,
        "MAP-Elites archive: " + options.fitness + " over " + options.features[0] + " x " + options.features[1]);
    const auto& s = search.stats();
    evolved.summary = std::to_string(s.matings) + " matings, " + std::to_string(search.archive().elites().size()) +
                      " archive cells filled, " + std::to_string(s.children_accepted) + " children became elites, " +
                      std::to_string(s.children_pruned) + " pruned as unsolvable";
  } else {
    generator::GeneticAlgorithm ga(options, std::move(fitness));
    evolved.set = generator::makeProblemSet(options, ga.run(progress));
    const auto& s = ga.stats();
    evolved.summary = std::to_string(s.matings) + " matings, " + std::to_string(s.children_accepted) +
                      " children accepted, " + std::to_string(s.children_pruned) + " pruned as unsolvable, " +
                      std::to_string(s.children_duplicate) + " dropped as duplicates, " +
                      std::to_string(s.children_rejected) + " lost to a similar PPP";
  }
  evolved.summary += "; diversity " + formatNumber(evolved.set.diversity);
  return evolved;
}

EvolvedSet evolveSetDirectory(const std::string& dir, const generator::GeneratorOptions& options,
                              const std::vector<agents::AgentConfig>& available, const EpisodeOptions& episode,
                              int threads, const generator::ProgressCallback& progress) {
  generator::checkOutputDirectory(dir);
  EvolvedSet evolved = evolveSet(options, available, episode, threads, progress);
  generator::writeProblemSetDirectory(dir, evolved.set, options, evolved.extra_files);
  return evolved;
}

}  // namespace simulator
}  // namespace ppp
