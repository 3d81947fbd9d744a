// The agent and episode flags of `ppp simulate` and `ppp replay`: declared from the agent and episode option
// tables, they accept and refuse what the agents YAML, the agent node's parameters and the experiment YAML do
// (the shared cases), and their errors name the flag.
#include "agent_flags.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "agent_option_cases.hpp"
#include "option_flags.hpp"
#include "ppp_core/option_cases.hpp"

namespace ppp {
namespace cli {
namespace {

/// What `ppp simulate --agent explorer ARGS` makes of its agent and episode flags: "" when accepted, else the
/// error.
std::string flagsError(std::vector<std::string> args) {
  CLI::App app;
  AgentFlags flags;
  flags.add(&app);
  if (std::find(args.begin(), args.end(), "--agent") == args.end()) {
    args.insert(args.begin(), {"--agent", "explorer"});
  }
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments in reverse
  try {
    app.parse(args);
    flags.agent();
    flags.episode();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

/// The flag of a declared option.
template <typename Options>
std::string flagOf(const std::vector<OptionSpec<Options>>& specs, const std::string& option) {
  return flagName(selectOptions(specs, {option})[0]);
}

/// Expects each case's flag (of `specs`) to be accepted or refused, naming the flag, as the case says.
template <typename Options>
void expectFlagsHoldTo(const std::vector<OptionSpec<Options>>& specs, const std::vector<OptionCase>& cases) {
  for (const OptionCase& c : cases) {
    const std::string flag = flagOf(specs, c.option);
    const std::string error = flagsError({flag, c.value});
    if (c.accepted) {
      EXPECT_EQ(error, "") << flag << " " << c.value;
    } else {
      EXPECT_EQ(error.rfind(flag + ": ", 0), 0u) << flag << " " << c.value << " gave: " << error;
    }
  }
}

TEST(AgentFlagsTest, AgentFlagsAcceptAndRefuseWhatEverySourceDoes) {
  expectFlagsHoldTo(agents::agentPlayOptionSpecs(), agents::test::agentOptionCases(agents::agentPlayOptionSpecs()));
}

TEST(AgentFlagsTest, EpisodeFlagsAcceptAndRefuseWhatTheExperimentYamlDoes) {
  // The same cases as experiment_config_test's EpisodeKeysAcceptAndRefuseWhatEverySourceDoes.
  expectFlagsHoldTo(episodeOptionSpecs(),
                    declaredOptionCases(episodeOptionSpecs(), EpisodeOptions{}));
}

TEST(AgentFlagsTest, FlagsAreTheDeclaredOnesWithTheirDocs) {
  CLI::App app;
  AgentFlags flags;
  flags.add(&app);
  const std::string help = app.help();
  for (const char* expected : {"--agent", "--memory full|5x5|3x3|...", "a memory window KxK (odd K) or 'full'; default full",
                               "--sensor-noise FLOAT in [0, 1]", "flipped (default 0)", "--budget INT in [1, 1000000]",
                               "fails (default 300)", "--sensor-range INT in [1, 7]", "window) (default 2)"}) {
    EXPECT_NE(help.find(expected), std::string::npos) << expected << " missing from:\n" << help;
  }
  EXPECT_EQ(flagsError({"--budget", "50"}), "");
  EXPECT_EQ(flagsError({"--memory", "5x5"}), "");
  EXPECT_EQ(flagsError({"--memory", "5x5", "--agent", "planner"}).rfind("--agent: planner agents play through ROS", 0),
            0u);
}

TEST(AgentFlagsTest, TheAgentIsNamedAfterItsTypeWithTheGivenHandicaps) {
  CLI::App app;
  AgentFlags flags;
  flags.add(&app);
  app.parse(std::vector<std::string>{"0.25", "--sensor-noise", "3x3", "--memory", "explorer", "--agent", "40",
                                     "--budget"});
  const agents::AgentConfig agent = flags.agent();
  EXPECT_EQ(agent.name, "explorer");
  EXPECT_EQ(agent.type, "explorer");
  EXPECT_EQ(agent.memory_window, 3);
  EXPECT_EQ(agent.sensor_noise, 0.25);
  EXPECT_EQ(flags.episode().budget, 40);
  EXPECT_EQ(flags.episode().sensor_range, 2);
}

// The replay command a report prints is generated from the same tables: its flags give back the run's agent and
// episode options, and the flags of defaults are left out.
TEST(AgentFlagsTest, FlagsWrittenFromTheTablesReadBackAsTheSameOptions) {
  agents::AgentConfig agent{"explorer_memory_5x5", "explorer", 5, 0.1};
  EpisodeOptions episode;
  episode.budget = 120;
  episode.connectivity = Connectivity::Eight;
  const std::string agent_flags = optionFlags(agents::agentPlayOptionSpecs(), agent, agents::AgentConfig{});
  const std::string episode_flags = optionFlags(episodeOptionSpecs(), episode, EpisodeOptions{});
  EXPECT_EQ(agent_flags, "--agent explorer --memory 5x5 --sensor-noise 0.1");
  EXPECT_EQ(episode_flags, "--budget 120 --connectivity 8");
  std::vector<std::string> args;
  std::istringstream words(agent_flags + " " + episode_flags);
  for (std::string word; words >> word;) args.insert(args.begin(), word);  // CLI11 takes them in reverse
  CLI::App app;
  AgentFlags flags;
  flags.add(&app);
  app.parse(args);
  EXPECT_EQ(flags.agent().memory_window, 5);
  EXPECT_EQ(flags.agent().sensor_noise, 0.1);
  EXPECT_EQ(flags.episode().budget, 120);
  EXPECT_EQ(flags.episode().connectivity, Connectivity::Eight);
  EXPECT_EQ(flags.episode().sensor_range, EpisodeOptions{}.sensor_range);
  EXPECT_EQ(optionFlags(episodeOptionSpecs(), EpisodeOptions{}, EpisodeOptions{}), "");
}

}  // namespace
}  // namespace cli
}  // namespace ppp
