// Which agents the report sets side by side in both motion models, and how it words their failed runs.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ppp_core/diagnosis.hpp"
#include "ppp_core/motion_options.hpp"
#include "ppp_simulator/report/motion_models.hpp"

namespace ppp {
namespace simulator {
namespace {

agents::AgentConfig planner(const std::string& name, const std::string& node, const std::string& args,
                            const std::string& motion) {
  agents::AgentConfig agent;
  agent.name = name;
  agent.type = "planner";
  agent.planner_node = node;
  agent.planner_args = args;
  agent.motion = motion;
  return agent;
}

TEST(MotionModelsTest, EachContinuousAgentIsPairedWithItsGridTwinPreferringTheSameArguments) {
  const std::vector<agents::AgentConfig> agents = {
      planner("vff", "ppp_agents/mrpt_reactive_node", "_method:=VFF", kMotionGrid),
      planner("nd", "ppp_agents/mrpt_reactive_node", "_method:=ND", kMotionGrid),
      planner("dwa", "ppp_agents/dwa_planner_node", "_costmap_resolution:=0.25", kMotionGrid),
      planner("nd_driven", "ppp_agents/mrpt_reactive_node", "_method:=ND", kMotionContinuous),
      planner("dwa_driven", "ppp_agents/dwa_planner_node", "", kMotionContinuous),
      planner("mine_driven", "", "", kMotionContinuous),  // no grid twin
  };
  const std::vector<MotionPair> pairs = motionPairs(agents, EpisodeOptions{});
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].grid_agent, "nd");  // not vff: the same node, other arguments
  EXPECT_EQ(pairs[0].continuous_agent, "nd_driven");
  EXPECT_EQ(pairs[1].grid_agent, "dwa");  // tuned apart, the same node
  EXPECT_EQ(pairs[1].continuous_agent, "dwa_driven");
  // An experiment in continuous motion: the agents left at its motion ("experiment") play continuously and have
  // no grid twin.
  EpisodeOptions continuous;
  continuous.motion.motion = kMotionContinuous;
  EXPECT_TRUE(motionPairs({planner("a", "x", "", agents::kMotionOfExperiment),
                           planner("b", "x", "", agents::kMotionOfExperiment)},
                          continuous)
                  .empty());
}

TEST(MotionModelsTest, FailedRunsAreCountedByKindMostFirstWithCollisionsApartFromOtherReportedReasons) {
  SetPassRate row;
  const auto count = [&](const char* kind, int n) {
    row.diagnoses.kinds[static_cast<std::size_t>(diagnosis::kindIndex(kind))] = n;
  };
  EXPECT_EQ(failureKinds(row), "none");
  count(diagnosis::kLoop, 3);
  count(diagnosis::kStuck, 12);
  count(diagnosis::kReported, 7);  // 5 collisions and 2 timeouts
  count(diagnosis::kDetour, 4);    // passed runs: not failures
  row.diagnoses.collisions = 5;
  EXPECT_EQ(failureKinds(row), "12 stuck, 5 collision, 3 loop, 2 reported");
}

}  // namespace
}  // namespace simulator
}  // namespace ppp
