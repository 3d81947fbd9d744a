#include "ppp_simulator/hunt_corpus.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>

#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/problem.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_simulator/corpus.hpp"
#include "ppp_simulator/corpus_check.hpp"
#include "ppp_simulator/failure_shrink.hpp"
#include "ppp_simulator/report/distinct_failures.hpp"
#include "ppp_simulator/results_file.hpp"

namespace ppp {
namespace simulator {

namespace {

namespace fs = std::filesystem;

/// How `agent`'s runs are judged: in process for a built-in agent, through `planner_rows` for a planner.
FailureJudging judgingOf(const agents::AgentConfig& agent, const EpisodeOptions& episode,
                         const PlannerRows& planner_rows) {
  FailureJudging judging;
  judging.agent = agent;
  judging.episode = episode;
  if (agents::isPlanner(agent)) {
    judging.play = playerOfRows(
        [&planner_rows, agent](const Problem& p, const std::vector<std::uint64_t>& seeds) {
          return planner_rows(agent, p, seeds);
        },
        episode);
  }
  return judging;
}

/// Shrinks the failure of `judging`'s agent on PPP `index` of `set` into `corpus`.
CorpusEntry shrinkInto(Corpus* corpus, const agents::PreparedSet& set, std::size_t index,
                       const FailureJudging& judging, const StopCheck& stop) {
  CorpusEntry entry;
  entry.set = set.name;
  entry.problem = set.set.ids[index];
  entry.agent = judging.agent.name;
  entry.seeds = seedList(judging.seeds);
  try {
    ShrunkFailure shrunk = shrinkFailure(set.set.problems[index], set.name + "/" + entry.problem + ".ppp", judging,
                                         ShrinkUnits::Descriptors, stop);
    setMetadata(&shrunk.problem.metadata, "id", entry.problem);
    const CorpusAddition addition = corpus->add(shrunk.problem);
    entry.kept = shrunk.kept.text();
    entry.descriptors_before = shrunk.descriptors_before;
    entry.descriptors_after = shrunk.descriptors_after;
    entry.trap = fs::path(addition.file).filename().string();
    entry.trap_file = addition.file;
    entry.added = addition.added;
    entry.cells_after = shrunk.cells_after;
    entry.failing_seed = firstFailingSeed(shrunk.problem, judging);
  } catch (const InvalidArgument& e) {
    if (e.name() != "problem") throw;
    entry.note = e.problem();
  } catch (const AgentUnreachable& e) {
    entry.note = std::string("its planner cannot be reached: ") + e.what();
  }
  return entry;
}

std::string entryLine(const CorpusEntry& e) {
  if (!e.note.empty()) return e.set + "/" + e.problem + " (" + e.agent + "): not shrunk, " + e.note;
  return e.set + "/" + e.problem + " (" + e.agent + "): " + std::to_string(e.descriptors_before) + " -> " +
         std::to_string(e.descriptors_after) + " descriptors, still " + e.kept + "; " +
         (e.added ? "added as " : "in the corpus already, as ") + e.trap;
}

/// The command that plays `e`'s trap again: ppp replay on its failing seed for a built-in agent, the check node (on
/// the trap's recorded seeds) for a planner.
std::string trapReplay(const CorpusEntry& e, const agents::AgentConfig& agent, const EpisodeOptions& episode) {
  if (!agents::isPlanner(agent)) return agents::replayCommand(e.trap_file, agent, episode, e.failing_seed);
  return checkLaunchCommand(e.trap_file, agent.name, "EXPERIMENT.yaml");
}

}  // namespace

std::vector<std::string> distinctTrapLines(const ExperimentConfig& config, const std::vector<CorpusEntry>& entries) {
  FailureGrouping grouping;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const CorpusEntry& e = entries[i];
    if (!e.trap.empty()) grouping.add(e.agent + " " + e.trap, e.set + "/" + e.problem, e.cells_after, i);
  }
  const std::vector<DistinctFailure> traps = grouping.groups();
  std::vector<std::string> lines{std::to_string(traps.size()) + " distinct trap" + (traps.size() == 1 ? "" : "s") +
                                 " in " + std::to_string(grouping.total()) + " shrunk failures (per agent):"};
  for (DistinctFailure trap : traps) {
    const CorpusEntry& e = entries[trap.smallest];
    trap.key = e.trap;
    lines.push_back(distinctFailureLine(trap, "PPP", e.agent + ", " + e.kept, e.set + "/" + e.problem,
                                        trapReplay(e, configAgent(config, e.agent), config.episode)));
  }
  return lines;
}

bool hasCorpus(const ExperimentConfig& config) {
  return std::any_of(config.sets.begin(), config.sets.end(), [](const SetSpec& s) { return !s.corpus.empty(); });
}

void checkCorpora(const ExperimentConfig& config) {
  for (const SetSpec& set : config.sets) {
    if (!set.corpus.empty()) Corpus check(set.corpus);
  }
}

std::vector<CorpusEntry> addHuntFailuresToCorpora(const ExperimentConfig& config,
                                                  const std::vector<agents::PreparedSet>& sets,
                                                  const std::vector<agents::EpisodeResult>& rows,
                                                  const PlannerRows& planner_rows, const StopCheck& stop,
                                                  const std::function<void(const std::string&)>& log) {
  std::map<std::string, std::unique_ptr<Corpus>> corpora;  // by directory: sets sharing one add to one
  std::vector<CorpusEntry> entries;
  for (const agents::PreparedSet& set : sets) {
    const SetSpec* spec = findSet(config, set.name);
    if (spec == nullptr || spec->corpus.empty()) continue;  // validate(): only hunted sets name a corpus
    std::unique_ptr<Corpus>& corpus = corpora[(fs::path(spec->corpus) / "").lexically_normal().string()];
    if (!corpus) corpus = std::make_unique<Corpus>(spec->corpus);
    for (const std::string& name : spec->generator->agents) {
      const agents::AgentConfig& agent = configAgent(config, name);
      if (agents::isPlanner(agent) && !planner_rows) {
        if (log) log("corpus " + spec->corpus + ": planner " + name + "'s failures are left out: it plays only through ROS");
        continue;
      }
      const FailedRunSeeds failed = failedRunSeeds(rows, name, kCorpusJudgedRuns);
      FailureJudging judging = judgingOf(agent, config.episode, planner_rows);
      for (std::size_t i = 0; i < set.set.problems.size(); ++i) {
        const auto found = failed.find({set.name, set.set.ids[i]});
        if (found == failed.end()) continue;
        judging.seeds = found->second;
        entries.push_back(shrinkInto(corpus.get(), set, i, judging, stop));
        if (log) log("corpus " + spec->corpus + ": " + entryLine(entries.back()));
      }
    }
  }
  return entries;
}

void writeCorpusLog(const std::string& path, const std::vector<CorpusEntry>& entries) {
  std::string text = csvLine({"set", "problem", "agent", "seeds", "kept", "descriptors_before", "descriptors_after",
                              "trap", "added", "note"}) +
                     "\n";
  for (const CorpusEntry& e : entries) {
    text += csvLine({e.set, e.problem, e.agent, e.seeds, e.kept, std::to_string(e.descriptors_before),
                     std::to_string(e.descriptors_after), e.trap, e.added ? "true" : "false", e.note}) +
            "\n";
  }
  writeFileAtomically(path, text);
}

}  // namespace simulator
}  // namespace ppp
