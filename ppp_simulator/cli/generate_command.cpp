#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli_options.hpp"
#include "commands.hpp"
#include "ppp_core/csv.hpp"
#include "ppp_agents/agent_config.hpp"
#include "ppp_generator/problem_set.hpp"
#include "ppp_generator/set_evolution.hpp"
#include "ppp_simulator/failure_fitness.hpp"
#include "progress.hpp"

namespace ppp {
namespace cli {

namespace {

struct GenerateFlags {
  std::string config = PPP_DEFAULT_CONFIG_DIR "/generator.yaml";
  std::string fitness;
  int population = 0;
  long matings = 0;
  std::string size;
  int max_obstacles = 0;
  std::uint64_t seed = 0;
  std::string start;
  std::string goal;
  std::string characters;
  int tournament_size = 0;
  double mutation_rate = 0;
  std::vector<std::string> weights;
  std::string replacement;
  int crowding_window = 0;
  std::vector<std::string> agents;
  std::string agents_file;
  int runs_per_eval = 0;
  std::string archive;
  std::vector<std::string> features;
  int bins = 0;
  int budget = 0;
  int threads = 0;
  std::string output;
  bool quiet = false;
};

generator::GeneratorOptions resolveOptions(const CLI::App& command, const GenerateFlags& f) {
  generator::GeneratorOptions o = generator::loadGeneratorOptions(f.config);
  auto given = [&](const char* name) { return command.count(name) > 0; };
  if (given("--fitness")) o.fitness = f.fitness;
  if (given("--population")) o.population = f.population;
  if (given("--matings")) o.matings = f.matings;
  if (given("--size")) {
    const Size size = parseSize(f.size, "--size");
    o.width = size.width;
    o.height = size.height;
    if (!given("--goal")) o.goal.reset();  // the default goal follows the size
  }
  if (given("--max-obstacles")) o.max_obstacles = f.max_obstacles;
  if (given("--seed")) o.seed = f.seed;
  if (given("--start")) o.start = parseCell(f.start, "--start");
  if (given("--goal")) o.goal = parseCell(f.goal, "--goal");
  if (given("--characters")) o.characters = f.characters;
  if (given("--tournament-size")) o.tournament_size = f.tournament_size;
  if (given("--mutation-rate")) o.mutation_rate = f.mutation_rate;
  if (given("--weight")) o.weights = parseWeights(f.weights, o.weights);
  if (given("--replacement")) o.replacement = f.replacement;
  if (given("--crowding-window")) o.crowding_window = f.crowding_window;
  if (given("--agents")) o.agents = f.agents;
  if (given("--agents-file")) o.agents_file = f.agents_file;
  if (given("--runs-per-eval")) o.runs_per_eval = f.runs_per_eval;
  if (given("--archive")) o.archive = f.archive;
  if (given("--features")) o.features = f.features;
  if (given("--bins")) o.bins = f.bins;
  o.validate();
  return o;
}

void runGenerate(const CLI::App& command, const GenerateFlags& flags) {
  const generator::GeneratorOptions options = resolveOptions(command, flags);
  simulator::EpisodeOptions episode;
  if (command.count("--budget") > 0) episode.budget = flags.budget;
  episode.validate();
  const std::vector<agents::AgentConfig> available =
      options.agents_file.empty() ? std::vector<agents::AgentConfig>{} : agents::loadAgentConfigs(options.agents_file);
  Progress progress("matings", flags.quiet);
  const generator::EvolvedSet evolved = generator::evolveSetDirectory(
      flags.output, options, simulator::fitnessFor(options, available, episode, flags.threads),
      [&](long done, long total, double best) {
        progress.update(done, total, "best " + options.fitness + " " + formatNumber(best));
      });
  std::cout << "wrote " << evolved.set.problems.size() << " PPPs, set.csv, generator.yaml and tree.{nwk,json,html}"
            << (options.archive == generator::kMapElitesArchive ? ", archive.{csv,svg}" : "") << " to "
            << flags.output << " (" << evolved.summary << ")\n";
}

}  // namespace

void addGenerateCommand(CLI::App& app) {
  auto flags = std::make_shared<GenerateFlags>();
  CLI::App* command = app.add_subcommand(
      "generate", "Evolve a set of PPPs with the genetic algorithm; write the .ppp files, set.csv and the taxonomy");
  command->add_option("--config", flags->config, "Generator YAML whose values the flags override")
      ->capture_default_str();
  command->add_option("--fitness", flags->fitness,
                      "Fitness: turns, advances, turns_plus_advances, difficulty, goal_visibility, "
                      "visibility_magnitude, random, failure (the failure rate of --agents)");
  command->add_option("--population", flags->population, "PPPs in the pool (>= 2)");
  command->add_option("--matings", flags->matings, "Steady-state mating events (>= 0)");
  command->add_option("--size", flags->size, "Grid size WIDTHxHEIGHT");
  command->add_option("--max-obstacles", flags->max_obstacles, "Obstacle budget per PPP (>= 0)");
  command->add_option("--seed", flags->seed, "Seed of every random choice");
  command->add_option("--start", flags->start, "Start cell X,Y");
  command->add_option("--goal", flags->goal, "Goal cell X,Y");
  command->add_option("--characters", flags->characters, "Taxonomy characters: wei or extended");
  command->add_option("--tournament-size", flags->tournament_size, "Individuals per mating event (>= 2)");
  command->add_option("--mutation-rate", flags->mutation_rate, "Probability of one mutation per child");
  command->add_option("--weight", flags->weights, "Difficulty weight NAME=VALUE (repeatable)");
  command->add_option("--replacement", flags->replacement,
                      "crowding (a child replaces the most similar of --crowding-window PPPs if as fit) or "
                      "tournament (the least fit of its tournament)");
  command->add_option("--crowding-window", flags->crowding_window, "PPPs a child is compared with (crowding)");
  command->add_option("--agents", flags->agents, "failure: the panel's agent names, comma-separated")
      ->delimiter(',');
  command->add_option("--agents-file", flags->agents_file,
                      "failure: agents file the names are looked up in (default: built-in type names)");
  command->add_option("--runs-per-eval", flags->runs_per_eval, "failure: episodes per agent per evaluated PPP");
  command->add_option("--budget", flags->budget, "failure: moves per episode (default 300)");
  command->add_option("--threads", flags->threads, "failure: worker threads (default 0: every core)");
  command->add_option("--archive", flags->archive, "none, or map_elites: the set is the elites of an archive");
  command->add_option("--features", flags->features, "map_elites: characters to bin, comma-separated")
      ->delimiter(',');
  command->add_option("--bins", flags->bins, "map_elites: bins per feature");
  command->add_option("-o,--output", flags->output, "Output directory")->required();
  command->add_flag("--quiet", flags->quiet, "No progress output");
  command->callback([command, flags] { runGenerate(*command, *flags); });
}

}  // namespace cli
}  // namespace ppp
