// Why MRPT's TP-space navigator, as MRPT's example configures it (config/mrpt_tpspace.ini), turns away from a far
// goal in free space: two pieces of MRPT 2.5.8 called directly, with no code of ours.
// - CHolonomicFullEval, the navigator's method in TP-space, with the example's phases (factor 6, then 4, then 0 and
//   2): a target more than twice the reference distance away leaves 49 of its 121 directions tied, and it picks
//   one 71 degrees off the target.
// - CPTG_DiffDrive_CollisionGridBased::inverseMap_WS2TP, which maps a target into TP-space for the example's
//   CPTG_DiffDrive_alpha family: any target beyond the reference distance is reported as outside the family's
//   domain (its last line compares target_dist with itself); fixed in MRPT 2.11.11.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/nav/holonomic/CHolonomicFullEval.h>
#include <mrpt/nav/holonomic/ClearanceDiagram.h>
#include <mrpt/nav/tpspace/CPTG_DiffDrive_CollisionGridBased.h>
#include <mrpt/version.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

namespace ppp {
namespace planners {
namespace {

constexpr int kDirections = 121;  // the example's PTGs' num_paths

/// What FullEval, configured as the shipped file's [CHolonomicFullEval], chose for a target `distance` (a
/// fraction of the reference distance) straight ahead with nothing within range.
struct FullEvalChoice {
  double direction = 0;  // radians
  int tied = 0;          // directions whose final score equals the best one
};

FullEvalChoice fullEvalAhead(double distance) {
  const mrpt::config::CConfigFile config(PPP_TPSPACE_CONFIG);
  mrpt::nav::CHolonomicFullEval method;
  method.initialize(config);
  mrpt::nav::ClearanceDiagram clearance;
  mrpt::nav::CAbstractHolonomicReactiveMethod::NavInput input;
  input.obstacles.assign(kDirections, 1.0);
  input.targets = {mrpt::math::TPoint2D(distance, 0.0)};
  input.maxRobotSpeed = 1.0;
  input.maxObstacleDist = 1.0;
  input.clearance = &clearance;
  mrpt::nav::CAbstractHolonomicReactiveMethod::NavOutput output;
  method.navigate(input, output);
  const auto log = std::dynamic_pointer_cast<mrpt::nav::CLogFileRecord_FullEval>(output.logRecord);
  if (!log || log->dirs_eval.empty()) {
    ADD_FAILURE() << "FullEval left no log record";
    return {};
  }
  const std::vector<double>& scores = log->dirs_eval.back();
  const double best = *std::max_element(scores.begin(), scores.end());
  FullEvalChoice choice;
  choice.direction = output.desiredDirection;
  choice.tied = static_cast<int>(
      std::count_if(scores.begin(), scores.end(), [&](double s) { return std::abs(s - best) < 1e-9; }));
  return choice;
}

// Factor 2 scores a direction by how near its collision-free end comes to the target, clipped at 1
// (CHolonomicFullEval.cpp, 2.5.8: `std::min(1.0, endpt_dist_to_target)`); every end lies within 1 of the robot, so
// a target beyond 2 is at least 1 from each and all score alike. Factor 1 (the closest approach along the
// direction), which would still rank them, is in none of the example's phases. Up to 1.2 FullEval heads straight
// for the target; from 2.25 on, 49 directions tie and it takes one at 1.246 rad.
TEST(MrptTpSpaceSourceTest, FullEvalAsTheExampleConfiguresItCannotRankDirectionsToAFarTarget) {
  for (const double near : {0.5, 0.9, 1.2}) {
    const FullEvalChoice choice = fullEvalAhead(near);
    EXPECT_NEAR(choice.direction, 0.0, 1e-9) << "target " << near;
    EXPECT_EQ(choice.tied, 1) << "target " << near;
  }
  for (const double far : {2.25, 5.0}) {
    const FullEvalChoice choice = fullEvalAhead(far);
    EXPECT_EQ(choice.tied, 49) << "target " << far;
    EXPECT_NEAR(choice.direction, 1.246, 0.001) << "target " << far;
  }
}

// The example's second family (PTG1, CPTG_DiffDrive_alpha) maps a target into TP-space with the collision grid's
// inverse. For a target beyond its reference distance (10 m) the inverse extrapolates and then returns
// `target_dist > target_dist`, always false, so the navigator discards the family ("PTG discarded since target(s)
// is(are) out of domain"). MRPT's changelog for 2.11.11 (2024-02-29) fixes it ("wrongly discarding of WS points out
// of the refDistance radius as invalid"); Debian 12 ships 2.5.8. The first family (CPTG_DiffDrive_C) has an
// inverse of its own and keeps far targets.
TEST(MrptTpSpaceSourceTest, TheAlphaFamilyDiscardsEveryTargetBeyondItsReferenceDistanceBefore2_11_11) {
  const mrpt::config::CConfigFile config(PPP_TPSPACE_CONFIG);
  const std::string section = "CReactiveNavigationSystem";
  const std::filesystem::path cache =
      std::filesystem::temp_directory_path() / ("ppp-tpspace-source-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(cache);
  for (const int family : {0, 1}) {
    const std::string prefix = "PTG" + std::to_string(family) + "_";
    auto ptg = mrpt::nav::CParameterizedTrajectoryGenerator::CreatePTG(
        config.read_string(section, prefix + "Type", ""), config, section, prefix);
    auto* shaped = dynamic_cast<mrpt::nav::CPTG_RobotShape_Polygonal*>(ptg.get());
    ASSERT_NE(shaped, nullptr) << prefix;
    mrpt::math::CPolygon disc;  // a 16-gon round a disc of 0.2 m, as mrpt_tpspace_node gives the robot
    for (int i = 0; i < 16; ++i) disc.AddVertex(0.2 * std::cos(i * M_PI / 8), 0.2 * std::sin(i * M_PI / 8));
    shaped->setRobotShape(disc);
    ptg->initialize((cache / (prefix + "grid.dat.gz")).string(), false);
    ASSERT_DOUBLE_EQ(ptg->getRefDistance(), 10.0);
    int k = 0;
    double d = 0;
    EXPECT_TRUE(ptg->inverseMap_WS2TP(5.0, 0.0, k, d)) << prefix << " 5 m ahead";
    const bool far_kept = ptg->inverseMap_WS2TP(15.0, 0.0, k, d);
    const bool fixed = family == 0 || MRPT_VERSION >= 0x020B0B;  // 2.11.11 in the six-digit code of 2.10 and later
    EXPECT_EQ(far_kept, fixed) << prefix << " 15 m ahead, MRPT version code " << std::hex << MRPT_VERSION;
  }
  std::filesystem::remove_all(cache);
}

}  // namespace
}  // namespace planners
}  // namespace ppp
