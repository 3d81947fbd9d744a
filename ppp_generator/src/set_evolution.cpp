#include "ppp_generator/set_evolution.hpp"

#include "ppp_core/csv.hpp"
#include "ppp_generator/evaluation_log.hpp"
#include "ppp_generator/map_elites.hpp"

namespace ppp {
namespace generator {

namespace {

/// The set's ids by the hash of their grids.
std::map<std::uint64_t, std::string> idsByGrid(const ProblemSet& set) {
  std::map<std::uint64_t, std::string> ids;
  for (std::size_t i = 0; i < set.problems.size(); ++i) ids[decodeGrid(set.problems[i]).hash()] = set.ids[i];
  return ids;
}

}  // namespace

EvolvedSet evolveSet(const GeneratorOptions& options, Fitness fitness, const ProgressCallback& progress,
                     long progress_interval, const StopCheck& stop) {
  options.validate();
  EvolvedSet evolved;
  const EvaluationLog log;
  fitness = log.wrap(std::move(fitness));
  if (options.archive == kMapElitesArchive) {
    MapElites search(options, std::move(fitness));
    evolved.set = makeProblemSet(options, search.run(progress, progress_interval, stop));
    const std::map<std::uint64_t, std::string> ids = idsByGrid(evolved.set);
    std::vector<FeatureRange> ranges;
    for (const std::string& name : options.features) ranges.push_back(featureRange(name, options));
    evolved.extra_files["archive.csv"] = archiveCsv(search.archive(), options.features, ids);
    evolved.extra_files["archive.svg"] = archiveHeatMapSvg(
        search.archive(), options.features, ranges,
        "MAP-Elites archive: " + options.fitness + " over " + options.features[0] + " x " + options.features[1]);
    const ArchiveStats& s = search.stats();
    evolved.summary = std::to_string(s.matings) + " matings, " + std::to_string(search.archive().elites().size()) +
                      " archive cells filled, " + std::to_string(s.children_accepted) + " children became elites, " +
                      std::to_string(s.children_pruned) + " pruned as unsolvable";
  } else {
    GeneticAlgorithm ga(options, std::move(fitness));
    evolved.set = makeProblemSet(options, ga.run(progress, progress_interval, stop));
    const GenerationStats& s = ga.stats();
    evolved.summary = std::to_string(s.matings) + " matings, " + std::to_string(s.children_accepted) +
                      " children accepted, " + std::to_string(s.children_pruned) + " pruned as unsolvable, " +
                      std::to_string(s.children_duplicate) + " dropped as duplicates, " +
                      std::to_string(s.children_rejected) + " lost to a similar PPP";
    if (options.archive == kSignatureArchive) {
      const SignatureArchive& archive = ga.signatureArchive();
      evolved.extra_files[kSignatureArchiveFile] = archive.csv(idsByGrid(evolved.set));
      evolved.summary += "; " + std::to_string(archive.entries().size()) + " failure signatures, " +
                         std::to_string(s.children_novel) + " children failing in a new way";
      if (archive.dropped() > 0) evolved.summary += " (" + std::to_string(archive.dropped()) + " more not kept: archive full)";
    }
  }
  if (!log.empty()) evolved.extra_files[kEvaluationLogFile] = log.csv();
  evolved.summary += "; diversity " + formatNumber(evolved.set.diversity);
  return evolved;
}

EvolvedSet evolveSetDirectory(const std::string& dir, const GeneratorOptions& options, Fitness fitness,
                              const ProgressCallback& progress, const StopCheck& stop) {
  checkOutputDirectory(dir);
  EvolvedSet evolved = evolveSet(options, std::move(fitness), progress, 1000, stop);
  writeProblemSetDirectory(dir, evolved.set, options, evolved.extra_files);
  return evolved;
}

}  // namespace generator
}  // namespace ppp
