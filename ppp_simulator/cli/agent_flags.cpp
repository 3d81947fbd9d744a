#include "agent_flags.hpp"

#include "option_flags.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace cli {

void AgentFlags::add(CLI::App* command) {
  command_ = command;
  static const agents::AgentConfig agent_defaults;
  static const EpisodeOptions episode_defaults;
  addOptionFlags(command, agents::agentPlayOptionSpecs(), &agent_defaults, &given_);
  command->get_option(flagName(agents::agentPlayOptionSpecs()[0]))->required();
  addOptionFlags(command, episodeOptionSpecs(), &episode_defaults, &given_);
}

agents::AgentConfig AgentFlags::agent() const {
  agents::AgentConfig config;
  applyOptionFlags(*command_, agents::agentPlayOptionSpecs(), given_, &config);
  config.name = config.type;
  try {
    config.validate();
  } catch (const InvalidArgument& e) {
    throw namingTheFlag(*command_, agents::agentPlayOptionSpecs(), e);
  }
  if (agents::isPlanner(config)) {
    throw InvalidArgument(flagName(agents::agentPlayOptionSpecs()[0]), "planner agents play through ROS (planner_bridge_node), "
                                                         "never in process; valid here: " +
                                                             joinNames(agents::agentTypeNames()));
  }
  return config;
}

EpisodeOptions AgentFlags::episode() const {
  EpisodeOptions options;
  applyAndValidateFlags(*command_, episodeOptionSpecs(), given_, &options);
  return options;
}

}  // namespace cli
}  // namespace ppp
