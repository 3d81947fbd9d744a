#include "planner_node_parameters.hpp"

#include <gtest/gtest.h>

namespace ppp {
namespace planners {
namespace {

TEST(PlannerNodeParametersTest, DefaultBaseFrameFollowsTheNamespace) {
  EXPECT_EQ(defaultBaseFrame("/ompl/robot"), "ompl/robot/base_link");
  EXPECT_EQ(defaultBaseFrame("//ompl"), "ompl/base_link");
  EXPECT_EQ(defaultBaseFrame("/"), "base_link");
  EXPECT_EQ(defaultBaseFrame(""), "base_link");
}

}  // namespace
}  // namespace planners
}  // namespace ppp
