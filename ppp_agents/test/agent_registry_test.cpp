// The agent registry: every type named once, with the traits the simulator, the report and the nodes use.

#include "ppp_agents/agent_registry.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "ppp_agents/agent_config.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace agents {
namespace {

TEST(AgentRegistryTest, EveryBuiltInTypeBuildsAndThePlannerDoesNot) {
  std::set<std::string> names;
  for (const AgentType& type : agentRegistry()) {
    EXPECT_TRUE(names.insert(type.name).second) << type.name << " registered twice";
    EXPECT_NE(std::string(type.description), "") << type.name;
    AgentConfig config;
    config.name = config.type = type.name;
    if (type.make == nullptr) {
      EXPECT_EQ(std::string(type.name), kPlannerType);
      EXPECT_THROW(makeAgent(config), InvalidArgument);
    } else {
      EXPECT_NE(makeAgent(config), nullptr) << type.name;
    }
  }
  EXPECT_EQ(agentTypeNames().size(), agentRegistry().size() - 1);  // every type but the planner
}

TEST(AgentRegistryTest, TraitsOfTheControlTheBaselineAndThePlanner) {
  EXPECT_TRUE(agentType("astar").has(AgentTrait::Control));
  EXPECT_TRUE(agentType("astar").has(AgentTrait::NeedsPriorMap));
  EXPECT_TRUE(agentType("random").has(AgentTrait::Baseline));
  EXPECT_FALSE(agentType("random").has(AgentTrait::ReadsScanWindow));
  EXPECT_TRUE(agentType("explorer").has(AgentTrait::ReadsScanWindow));
  EXPECT_FALSE(agentType("explorer").has(AgentTrait::Control) || agentType("explorer").has(AgentTrait::Baseline));
  AgentConfig planner{"mine", kPlannerType, 0, 0.0};
  EXPECT_FALSE(givenPriorMap(planner));
  planner.prior_map = true;
  EXPECT_TRUE(givenPriorMap(planner));
  EXPECT_TRUE(givenPriorMap(AgentConfig{"a", "astar", 0, 0.0}));
  EXPECT_FALSE(givenPriorMap(AgentConfig{"b", "bumper", 0, 0.0}));
}

TEST(AgentRegistryTest, AnUnknownTypeListsTheValidOnes) {
  EXPECT_EQ(findAgentType("explorr"), nullptr);
  try {
    agentType("explorr");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()),
              "type: unknown agent type 'explorr'; valid: astar, random, wall_follower_left, wall_follower_right, "
              "explorer, long_term_explorer, bumper, decision_bumper, planner");
  }
}

}  // namespace
}  // namespace agents
}  // namespace ppp
