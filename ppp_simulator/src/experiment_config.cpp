#include "ppp_simulator/experiment_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "ppp_agents/continuous/continuous_agent.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/option_yaml.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_core/yaml_reader.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_generator/failure_fitness.hpp"
#include "ppp_simulator/report/episode_animation.hpp"

namespace ppp {
namespace simulator {

namespace fs = std::filesystem;

namespace {

std::string resolve(const fs::path& base, const std::string& path) {
  const fs::path p(path);
  return (p.is_absolute() ? p : base / p).lexically_normal().string();
}

std::vector<SetSpec> readSets(YamlMapReader& reader, const fs::path& base) {
  const YAML::Node list = reader.lookup("sets");
  if (!list) return {};
  if (!list.IsSequence()) reader.fail(list, "sets", "expected a list of sets");
  const std::string generator_defaults = (base / "generator.yaml").string();
  std::vector<SetSpec> sets;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string context = "sets[" + std::to_string(i) + "]";
    YamlMapReader item(list[i], reader.source(), context);
    SetSpec spec;
    if (!item.read("name", &spec.name)) item.fail(list[i], "name", "missing; every set needs a name");
    const YAML::Node generator = item.lookup("generator");
    std::string directory;
    const bool has_directory = item.read("directory", &directory);
    if (generator && has_directory) item.fail(list[i], "directory", "give either generator or directory, not both");
    if (has_directory) {
      spec.directory = resolve(base, directory);
    } else {
      generator::GeneratorOptions options;
      if (fs::exists(generator_defaults)) options = generator::loadGeneratorOptions(generator_defaults);
      if (generator) {
        YamlMapReader generator_reader(generator, reader.source(), context + ".generator");
        generator::applyGeneratorYaml(generator_reader, &options);
        generator_reader.rejectUnknownKeys();
      }
      spec.generator = options;
    }
    std::string corpus;
    if (item.read("corpus", &corpus)) {
      if (corpus.empty()) item.fail(list[i], "corpus", "expected a directory, got ''");
      spec.corpus = resolve(base, corpus);
    }
    item.rejectUnknownKeys();
    sets.push_back(spec);
  }
  return sets;
}

/// `reference: {SET: {AGENT: PERCENT, ...}, ...}`; the names are checked by validate().
std::vector<ReferenceRate> readReference(YamlMapReader& reader) {
  const YAML::Node node = reader.lookup("reference");
  if (!node) return {};
  if (!node.IsMap()) reader.fail(node, "reference", "expected {set: {agent: pass rate in percent, ...}, ...}");
  std::vector<ReferenceRate> reference;
  for (const auto& set : node) {
    const std::string set_name = set.first.Scalar();
    if (!set.second.IsMap()) {
      reader.fail(set.second, "reference." + set_name, "expected {agent: pass rate in percent, ...}");
    }
    for (const auto& agent : set.second) {
      const std::string key = "reference." + set_name + "." + agent.first.Scalar();
      double percent = 0;
      try {
        percent = agent.second.as<double>();
      } catch (const YAML::Exception&) {
        reader.fail(agent.second, key, "expected a pass rate in percent, got '" + YAML::Dump(agent.second) + "'");
      }
      if (!(percent >= 0 && percent <= 100)) {
        reader.fail(agent.second, key, "expected a pass rate in percent in [0, 100], got " + formatShortest(percent));
      }
      reference.push_back({set_name, agent.first.Scalar(), percent});
    }
  }
  return reference;
}

}  // namespace

void ExperimentConfig::validate() const {
  checkOptionRanges(experimentOptionSpecs(), *this);
  episode.validate();
  if (sets.empty()) throw InvalidArgument("sets", "an experiment needs at least one PPP set");
  if (agents.empty()) throw InvalidArgument("agents", "an experiment needs at least one agent");
  std::set<std::string> names;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const SetSpec& s = sets[i];
    if (s.name.empty() || s.name.find_first_of(",\"/\n") != std::string::npos) {
      throw InvalidArgument("sets", "set name '" + s.name + "' must be non-empty without , \" / or newlines");
    }
    if (!names.insert(s.name).second) throw InvalidArgument("sets", "duplicate set name '" + s.name + "'");
    if (!s.corpus.empty() && !(s.generator && generator::isPanelFitness(s.generator->fitness))) {
      throw InvalidArgument("sets[" + std::to_string(i) + "].corpus",
                            "only a hunted set (a generator with a panel fitness: failure or regret) adds its "
                            "failures to a corpus; '" + s.name + "' is not one");
    }
    if (!s.generator) continue;
    try {
      s.generator->validate();
      const SetSpec* start = findSet(*this, s.generator->initial_pool);
      if (start && !names.count(start->name)) {
        throw InvalidArgument("initial_pool", "names set '" + start->name + "', which is not listed before '" +
                                                  s.name + "': list the set it starts from first");
      }
      if (start == &s) throw InvalidArgument("initial_pool", "names set '" + s.name + "' itself");
      if (generator::isPanelFitness(s.generator->fitness)) {
        if (!s.generator->agents_file.empty()) {
          throw InvalidArgument("agents_file", "in an experiment the panel's names come from its agents");
        }
        generator::resolvePanel(s.generator->agents, agents, true);  // planners hunt through ROS; ppp experiment refuses them
        for (const agents::AgentConfig& a : agents) {
          const auto& panel = s.generator->agents;
          // A planner in continuous motion hunts through ROS on continuous lanes; a built-in agent only on the grid.
          const bool in_panel = std::find(panel.begin(), panel.end(), a.name) != panel.end();
          if (in_panel && !agents::isPlanner(a)) agents::refuseContinuous(a, episode);
        }
      }
    } catch (const InvalidArgument& e) {
      const std::string field = "sets[" + std::to_string(i) + "].generator." + e.name();
      throw InvalidArgument(field, e.problem());
    }
  }
  names.clear();
  for (const agents::AgentConfig& a : agents) {
    a.validate();
    agents::checkContinuousAgent(a, episode);
    if (!names.insert(a.name).second) throw InvalidArgument("agents", "duplicate agent name '" + a.name + "'");
  }
  std::set<std::pair<std::string, std::string>> referenced;
  for (const ReferenceRate& r : reference) {
    const std::string field = "reference." + r.set + "." + r.agent;
    if (!findSet(*this, r.set)) throw InvalidArgument(field, "this experiment has no set '" + r.set + "'");
    if (!names.count(r.agent)) throw InvalidArgument(field, "this experiment has no agent '" + r.agent + "'");
    if (!(r.percent >= 0 && r.percent <= 100)) {
      throw InvalidArgument(field, "expected a pass rate in percent in [0, 100], got " + formatShortest(r.percent));
    }
    if (!referenced.insert({r.set, r.agent}).second) throw InvalidArgument(field, "given twice");
  }
}

const SetSpec* findSet(const ExperimentConfig& config, const std::string& name) {
  for (const SetSpec& set : config.sets) {
    if (set.name == name) return &set;
  }
  return nullptr;
}

std::string setDirectory(const SetSpec& set, const std::string& dir) {
  return set.generator ? (fs::path(dir) / "sets" / set.name).string() : set.directory;
}

generator::GeneratorOptions generatorOptionsIn(const ExperimentConfig& config, const SetSpec& set,
                                               const std::string& dir) {
  generator::GeneratorOptions options = *set.generator;
  if (const SetSpec* start = findSet(config, options.initial_pool)) options.initial_pool = setDirectory(*start, dir);
  return options;
}

const agents::AgentConfig& configAgent(const ExperimentConfig& config, const std::string& name) {
  std::vector<std::string> names;
  for (const agents::AgentConfig& agent : config.agents) {
    if (agent.name == name) return agent;
    names.push_back(agent.name);
  }
  throw InvalidArgument("agent", "the config has no agent '" + name + "'; it has: " + joinNames(names));
}

ExperimentConfig loadExperimentConfig(const std::string& path) {
  return parseExperimentConfig(readTextFile(path, kMaxYamlBytes), path);
}

ExperimentConfig parseExperimentConfig(const std::string& yaml, const std::string& path) {
  const YAML::Node root = parseYaml(yaml, path);
  const fs::path base = fs::absolute(fs::path(path)).parent_path();
  YamlMapReader reader(root, path);
  ExperimentConfig config;
  readOptionsYaml(reader, experimentOptionSpecs(), &config);
  config.sets = readSets(reader, base);
  // The experiment's robot is the one every evolved set is made solvable for.
  for (std::size_t i = 0; i < config.sets.size(); ++i) {
    std::optional<generator::GeneratorOptions>& g = config.sets[i].generator;
    if (!g) continue;
    if (g->robot_radius != 0 && g->robot_radius != config.episode.robot_radius) {
      throw InvalidArgument(path + ": sets[" + std::to_string(i) + "].generator.robot_radius",
                            "the experiment's robot_radius (" + formatShortest(config.episode.robot_radius) +
                                ") decides it; give it there");
    }
    g->robot_radius = config.episode.robot_radius;
  }
  // initial_pool: the name of a set of this experiment, or a directory relative to the YAML's.
  for (SetSpec& set : config.sets) {
    if (set.generator && !set.generator->initial_pool.empty() && !findSet(config, set.generator->initial_pool)) {
      set.generator->initial_pool = resolve(base, set.generator->initial_pool);
    }
  }
  const YAML::Node agents = reader.lookup("agents");
  if (agents && agents.IsScalar()) {
    config.agents = agents::loadAgentConfigs(resolve(base, agents.Scalar()));
  } else if (agents) {
    config.agents = agents::readAgentConfigs(reader, "agents");
  }
  config.reference = readReference(reader);
  reader.rejectUnknownKeys();
  try {
    config.validate();
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(path + ": " + e.name(), e.problem());
  }
  return config;
}

const std::vector<OptionSpec<ExperimentConfig>>& experimentOptionSpecs() {
  using X = ExperimentConfig;
  static const std::vector<OptionSpec<X>> specs = [] {
    std::vector<OptionSpec<X>> list = {
        declareOption("seed", "every run's seed derives from this one", +[](X& x) -> std::uint64_t& { return x.seed; }),
        declareOption("runs", "runs per agent per PPP (an agent's own runs key overrides it)",
                      +[](X& x) -> int& { return x.runs; }, Bounds{1, agents::kMaxRuns}),
    };
    for (const OptionSpec<X>& spec : nestedOptions(episodeOptionSpecs(), +[](X& x) -> EpisodeOptions& {
           return x.episode;
         })) {
      list.push_back(spec);
    }
    list.push_back(declareOption("threads", "worker threads (0: every core)", +[](X& x) -> int& { return x.threads; },
                                 Bounds{0, generator::kMaxThreads})
                       .notAffectingResults());
    list.push_back(declareOption("hardest", "pictures of the hardest PPPs in the report",
                                 +[](X& x) -> int& { return x.hardest; }, Bounds{0, kMaxHardest})
                       .notAffectingResults());
    list.push_back(declareOption("animation_frames",
                                 "most frames of a failing run's animation in the report (longer runs: every k-th step)",
                                 +[](X& x) -> int& { return x.animation_frames; }, Bounds{2, kMaxAnimationFrames})
                       .notAffectingResults());
    list.push_back(declareOption("shrink_worst",
                                 "the report shows each agent's pictured worst PPP shrunk to the smallest PPP on "
                                 "which the pictured run still fails the same way (ppp shrink; a planner's only "
                                 "through ROS, played on its bridges)",
                                 +[](X& x) -> bool& { return x.shrink_worst; })
                       .notAffectingResults());
    return list;
  }();
  return specs;
}

ExperimentWork estimateWork(const ExperimentConfig& config) {
  ExperimentWork work;
  double runs_per_ppp = 0;  // over every agent
  for (const agents::AgentConfig& agent : config.agents) runs_per_ppp += config.runsFor(agent);
  for (const SetSpec& set : config.sets) {
    double problems = 0;
    if (set.generator) {
      const generator::GeneratorOptions& g = *set.generator;
      problems = g.population;
      work.matings += static_cast<double>(g.matings);
      if (generator::isPanelFitness(g.fitness)) {
        work.hunt_episodes += (2.0 * static_cast<double>(g.matings) + g.population) * g.agents.size() * g.runs_per_eval;
      }
    } else {
      try {
        problems = static_cast<double>(generator::problemSetFiles(set.directory).size());
      } catch (const Error&) {
        problems = 0;  // the experiment itself reports an unreadable set
      }
    }
    work.episodes += problems * runs_per_ppp;
  }
  work.result_bytes = 90.0 * work.episodes;
  return work;
}

std::string workSummary(const ExperimentWork& work) {
  std::ostringstream out;
  out << formatShortest(work.episodes) << " episodes";
  if (work.hunt_episodes > 0) out << ", " << formatShortest(work.hunt_episodes) << " more while hunting";
  out << ", " << formatShortest(work.matings) << " matings, results.csv about "
      << formatShortest(std::ceil(work.result_bytes / 1e6)) << " MB";
  return out.str();
}

void checkWork(const ExperimentWork& work, bool allow_large) {
  std::string over;
  const auto add = [&over](bool above, const char* what) {
    if (above) over += (over.empty() ? "" : ", ") + std::string(what);
  };
  add(work.episodes + work.hunt_episodes > kLargeEpisodes, "more than 1e8 episodes");
  add(work.matings > kLargeMatings, "more than 1e8 matings");
  add(work.result_bytes > kLargeResultBytes, "results.csv above 10 GB");
  if (over.empty() || allow_large) return;
  throw InvalidArgument("work", "a large experiment (" + over + "): " + workSummary(work) +
                                    "; pass --large (ROS: args:=--large) to run it anyway");
}

std::string experimentFingerprint(const ExperimentConfig& c) {
  std::ostringstream out;
  out << "# PPP Lab experiment: every option that may change its results. A rerun on this directory resumes only\n"
      << "# if this text is unchanged.\n"
      << optionsYaml(resultOptions(experimentOptionSpecs()), c, false) << "sets:\n";
  for (const SetSpec& s : c.sets) {
    out << "  - name: " << option_detail::quoted(s.name) << "\n";
    if (s.generator) {
      out << "    generator:\n";
      std::istringstream lines(optionsYaml(resultOptions(generator::generatorOptionSpecs()), *s.generator, false));
      for (std::string line; std::getline(lines, line);) out << "      " << line << "\n";
    } else {
      out << "    directory: " << option_detail::quoted(s.directory) << "\n";
    }
  }
  out << "agents:\n";
  for (const agents::AgentConfig& a : c.agents) {
    std::string fields;
    for (const OptionSpec<agents::AgentConfig>& spec : resultOptions(agents::agentOptionSpecs())) {
      const std::string value = spec.text(a);
      fields += (fields.empty() ? "" : ", ") + spec.name + ": " + (value.empty() ? "''" : value);
    }
    out << "  - {" << fields << "}\n";
  }
  return out.str();
}

}  // namespace simulator
}  // namespace ppp
