#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "agent_flags.hpp"
#include "cli_options.hpp"
#include "ppp_core/text_format.hpp"
#include "commands.hpp"
#include "option_flags.hpp"
#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/continuous/continuous_runner.hpp"
#include "ppp_core/csv.hpp"
#include "ppp_core/diagnosis.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/picture.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/trajectory_picture.hpp"
#include "ppp_agents/episode_runner.hpp"
#include "ppp_agents/prepared_set.hpp"
#include "ppp_simulator/report/continuous_animation.hpp"
#include "ppp_simulator/report/episode_animation.hpp"

namespace ppp {
namespace cli {

namespace {

/// Options shared by `simulate` and `replay`: which agent, with which handicaps, on which PPP.
struct PlayFlags {
  AgentFlags agent;
  std::string problem;
};

struct SimulateFlags : PlayFlags {
  int runs = 1000;
  std::uint64_t seed = 1;
  bool json = false;
};

struct ReplayFlags : PlayFlags {
  std::uint64_t seed = 1;
  std::string output;
  simulator::AnimationOptions animation;
};

/// What `simulate` and `replay` take as the PPP.
constexpr const char* kProblemHelp =
    "A .ppp, map_server .yaml or MovingAI .map file, or empty:WxH for an empty grid";

/// The PPP `source` names. @throws InvalidArgument naming --robot-radius when a robot with a body cannot reach its
/// goal (the disc does not fit at the start or the goal, or through any passage): every run would fail.
Problem loadProblem(const std::string& source, const EpisodeOptions& episode) {
  const std::string prefix = "empty:";
  Problem problem;
  if (source.rfind(prefix, 0) == 0) {
    const Size size = parseSize(source.substr(prefix.size()), "--problem");
    problem = Problem::empty(size.width, size.height, 0);
  } else {
    problem = readProblemFile(source);
  }
  if (!isPointRobot(episode.robot_radius) &&
      !isReachable(configurationSpace(decodeGrid(problem), episode.robot_radius), problem.start, problem.goal)) {
    throw InvalidArgument(flagFor("robot_radius"), "a robot of radius " + formatShortest(episode.robot_radius) +
                                                " cannot reach the goal of " + source + " (the disc does not fit at " +
                                                "its start " + cellText(problem.start) + ", its goal " +
                                                cellText(problem.goal) + " or some passage between them): every run "
                                                "would fail; give start and goal cells further in");
  }
  return problem;
}

void runSimulate(const SimulateFlags& f) {
  if (f.runs <= 0) throw InvalidArgument("--runs", "expected a number of runs >= 1, got " + std::to_string(f.runs));
  const agents::AgentConfig config = f.agent.agent();
  const EpisodeOptions episode = f.agent.episode();
  const Problem problem = loadProblem(f.problem, episode);
  const Grid grid = decodeGrid(problem);
  long passes = 0;
  long steps = 0;
  if (agents::playsContinuously(config, episode)) {
    agents::ContinuousRunner runner(config, episode);
    const int grid_moves = fewestMoves(grid, problem.start, problem.goal, Connectivity::Four);
    for (int run = 0; run < f.runs; ++run) {
      const ContinuousOutcome outcome =
          runner.run(problem, grid, grid_moves, deriveSeed(f.seed, {static_cast<std::uint64_t>(run)}));
      passes += outcome.passed ? 1 : 0;
      steps += outcome.steps;
    }
  } else {
    agents::EpisodeRunner runner(config, episode);
    auto agent = agents::makeAgent(config);
    for (int run = 0; run < f.runs; ++run) {
      const auto outcome = runner.run(problem, grid, *agent, deriveSeed(f.seed, {static_cast<std::uint64_t>(run)}));
      passes += outcome.passed ? 1 : 0;
      steps += outcome.steps;
    }
  }
  const double rate = static_cast<double>(passes) / f.runs;
  const double mean_steps = static_cast<double>(steps) / f.runs;
  if (f.json) {
    nlohmann::json j = {{"runs", f.runs}, {"passes", passes}, {"pass_rate", rate}, {"mean_steps", mean_steps},
                        {"agent", config.name}, {"seed", f.seed}};
    std::cout << j.dump() << "\n";
  } else {
    std::cout << config.name << " on " << f.problem << ": " << passes << " of " << f.runs << " runs passed ("
              << formatNumber(100.0 * rate) << " %), mean " << formatNumber(mean_steps) << " steps\n";
  }
}

/// `ppp replay` of an agent in continuous motion: its trajectory drawn as a curve with the robot's last pose, or
/// the run animated with the laser's beams.
void replayContinuous(const ReplayFlags& f, const agents::AgentConfig& config, const EpisodeOptions& options) {
  const std::string extension = fileExtension(f.output);
  if (extension != ".png" && extension != ".gif") {
    throw InvalidArgument("--output", "expected a .png (the trajectory drawn) or .gif (the run animated) file name, "
                                      "got '" + f.output + "'");
  }
  const Problem problem = loadProblem(f.problem, options);
  const Grid grid = decodeGrid(problem);
  ContinuousOutcome outcome;
  std::string drawn;
  if (extension == ".gif") {
    simulator::ContinuousAnimation animation =
        simulator::animateContinuousRun(problem, grid, config, options, f.seed, f.animation);
    writeFileAtomically(f.output, animation.gif);
    outcome = std::move(animation.outcome);
    drawn = "animated in " + f.output + " (" + std::to_string(animation.frames) + " frames" +
            (animation.stride > 1 ? ", every " + std::to_string(animation.stride) + " control periods"
                                  : std::string()) + ")";
  } else {
    agents::ContinuousRunner runner(config, options);
    outcome = runner.run(problem, grid, fewestMoves(grid, problem.start, problem.goal, Connectivity::Four), f.seed,
                         true);
    writeTrajectoryPng(problem, outcome.poses, options.motion.resolution,
                       options.robot_radius * options.motion.resolution, f.output);
    drawn = "trajectory drawn in " + f.output;
  }
  std::cout << config.name << " with seed " << f.seed << ": " << (outcome.passed ? "passed" : "failed") << " ("
            << outcome.reason << ") after " << outcome.steps << " control periods (" << formatNumber(outcome.seconds)
            << " s), " << formatNumber(outcome.distance) << " m travelled; " << drawn << "\n";
  const Diagnosis diagnosis = diagnoseContinuousRun(outcome.passed, false, outcome.reason, outcome.cells);
  if (*diagnosis.kind != '\0') std::cout << "diagnosis: " << describeDiagnosis(diagnosis, outcome.reason) << "\n";
}

void runReplay(const ReplayFlags& f) {
  if (agents::playsContinuously(f.agent.agent(), f.agent.episode())) {
    replayContinuous(f, f.agent.agent(), f.agent.episode());
    return;
  }
  const std::string extension = fileExtension(f.output);
  const bool animated = extension == ".gif";
  if (!animated && extension != ".png") {
    throw InvalidArgument("--output", "expected a .png (the path drawn) or .gif (the episode animated) file name, got '" +
                                          f.output + "'");
  }
  try {
    f.animation.validate();
  } catch (const InvalidArgument& e) {  // name the flag, not the field
    throw InvalidArgument(flagFor(e.name()), e.problem());
  }
  const agents::AgentConfig config = f.agent.agent();
  const EpisodeOptions options = f.agent.episode();
  const Problem problem = loadProblem(f.problem, options);
  const Grid grid = decodeGrid(problem);
  EpisodeOutcome outcome;
  std::string drawn;
  if (animated) {
    const simulator::EpisodeAnimation animation = simulator::animateEpisode(problem, grid, config, options, f.seed, f.animation);
    writeFileAtomically(f.output, animation.gif);
    outcome = animation.outcome;
    drawn = "animated in " + f.output + " (" + std::to_string(animation.frames) + " frames" +
            (animation.stride > 1 ? ", every " + std::to_string(animation.stride) + " steps" : std::string()) + ")";
  } else {
    outcome = agents::recordEpisode(problem, grid, config, options, f.seed);
    drawn = "path drawn in " + f.output;
  }
  // The run as results.csv has it, diagnosis included.
  const agents::PreparedSet set = agents::prepareSingle("replay", "replayed", problem, options);
  const agents::EpisodeResult row = agents::episodeResult(set, 0, config.name, 0, f.seed, outcome);
  const Diagnosis diagnosis = agents::diagnosisOf(row);
  const std::vector<Cell> cycle = cycleCells(diagnosis, outcome.cells);
  if (!animated) writeProblemPng(problem, outcome.path, f.output, PictureOptions{}, cycle);
  std::cout << config.name << " with seed " << f.seed << ": " << (outcome.passed ? "passed" : "failed") << " ("
            << outcome.reason << ") after " << outcome.steps << " steps, " << outcome.bumps << " bumps, "
            << outcome.path_length << " cells moved; " << drawn << "\n";
  if (*diagnosis.kind != '\0') {
    std::cout << "diagnosis: " << describeDiagnosis(diagnosis, outcome.reason, static_cast<int>(cycle.size()))
              << (cycle.empty() || animated ? "" : " (the cycle's cells are pink)") << "\n";
    std::cout << "signature: " << row.signature << "\n";
  }
}

}  // namespace

void addSimulateCommand(CLI::App& app) {
  auto flags = std::make_shared<SimulateFlags>();
  CLI::App* command = app.add_subcommand("simulate", "Run one agent many times on one PPP and report its pass rate");
  flags->agent.add(command);
  command->add_option("--problem", flags->problem, kProblemHelp)->required();
  command->add_option("--runs", flags->runs, "Number of runs")->capture_default_str();
  command->add_option("--seed", flags->seed, "Seed; run i uses a seed derived from it")->capture_default_str();
  command->add_flag("--json", flags->json, "Print {runs, passes, pass_rate, mean_steps} as JSON");
  command->callback([flags] { runSimulate(*flags); });
}

void addReplayCommand(CLI::App& app) {
  auto flags = std::make_shared<ReplayFlags>();
  CLI::App* command = app.add_subcommand(
      "replay", "Run one episode with a given run seed (as in results.csv) and draw the agent's path");
  command->add_option("problem", flags->problem, kProblemHelp)->required();
  flags->agent.add(command);
  command->add_option("--seed", flags->seed, "The run's seed (results.csv column seed)")->required();
  command->add_option("-o,--output", flags->output,
                      "OUT.png: the map with the path; OUT.gif: the episode frame by frame (trail, scan window, "
                      "what the agent has not sensed shaded, bumps marked)")
      ->required();
  command
      ->add_option("--max-frames", flags->animation.max_frames,
                   "GIF: most frames; an episode of more than N - 1 steps shows every ceil(steps / (N - 1))-th step "
                   "and its last")
      ->capture_default_str();
  command->add_option("--frame-ms", flags->animation.frame_ms, "GIF: milliseconds per frame, a multiple of 10")
      ->capture_default_str();
  command->callback([flags] { runReplay(*flags); });
}

}  // namespace cli
}  // namespace ppp
