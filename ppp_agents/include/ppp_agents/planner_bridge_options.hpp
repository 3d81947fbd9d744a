#pragma once

#include <string>
#include <vector>

#include "ppp_core/option_spec.hpp"
#include "ppp_msgs/graph_names.h"

namespace ppp {
namespace agents {

/// Most map cells per PPP cell side in the map the bridge publishes.
constexpr int kMaxCellsPerPppCell = 16;

/// `plan_requests`: in lockstep, ask every step.
inline constexpr const char* kPlanRequestsEveryStep = "every_step";
/// `plan_requests`: in lockstep, ask only when the robot's map changed or its path gives no move.
inline constexpr const char* kPlanRequestsOnChange = "on_change";
/// `plan_requests`: in lockstep, ask only when the robot's path gives it no move (or it did not move).
inline constexpr const char* kPlanRequestsOnBlocked = "on_blocked";

/// `interface`: the planner answers a request with a path (nav_msgs/Path on `plan`).
inline constexpr const char* kInterfacePath = "path";
/// `interface`: the planner answers a request with a velocity command (geometry_msgs/TwistStamped on `cmd_vel`).
inline constexpr const char* kInterfaceCmdVel = "cmd_vel";

/// `wakes_on`: messages for this repository's local planners, a timer for any other (plannerWakesOn in
/// agent_config.hpp); a bridge started by hand takes it as a timer.
inline constexpr const char* kWakesOnAuto = "auto";
/// `wakes_on`: a local planner in continuous motion answers on a timer on the robot's clock.
inline constexpr const char* kWakesOnTimer = "timer";
/// `wakes_on`: a local planner in continuous motion answers each control period's messages as they come.
inline constexpr const char* kWakesOnMessages = "messages";

/// `period_messages`: `changes` for this repository's local planners, `every` for any other (plannerPeriodMessages
/// in agent_config.hpp); a bridge started by hand takes it as `every`.
inline constexpr const char* kPeriodMessagesAuto = "auto";
/// `period_messages`: every control period carries the episode's map and goal, stamped with it.
inline constexpr const char* kPeriodMessagesEvery = "every";
/// `period_messages`: the map and goal go out when an episode begins (latched, stamped with its first period);
/// each period carries only what changed (tf, odometry, the laser, the clock).
inline constexpr const char* kPeriodMessagesChanges = "changes";

/// The planner bridge's own `~` parameters (besides its agent's name and memory): what it publishes to the
/// planner and how long it waits for it.
struct BridgeOptions {
  double resolution = 1.0;                         ///< Metres per PPP cell.
  int cells_per_ppp_cell = 1;                      ///< Map cells per PPP cell side in the published map.
  double robot_radius = 0;                         ///< The robot's radius in PPP cells (published for the planner).
  double plan_timeout = 5.0;                       ///< Seconds the planner has to answer a plan request.
  bool lockstep = true;                            ///< Move only on answers to requests (reproducible).
  std::string plan_requests = kPlanRequestsEveryStep;  ///< When a lockstep bridge asks (kPlanRequests...).
  std::string interface = kInterfacePath;          ///< What the planner answers with (kInterface...).
  bool endless_proof = true;  ///< Report the decision state that proves loops endless (a planner without memory).
  std::string wakes_on = kWakesOnAuto;  ///< Continuous motion, cmd_vel: what makes the planner answer (kWakesOn...).
  std::string period_messages = kPeriodMessagesAuto;  ///< Continuous motion, cmd_vel: kPeriodMessages...
  double connect_timeout = 20.0;                   ///< Seconds to wait at start-up for the planner's topics.
  std::string map_frame = ppp_msgs::frames::kMap;  ///< Frame of the map, poses and goal.
  std::string base_frame;  ///< The robot's frame (tf child, odom child, scan frame); "": defaultBridgeBaseFrame.
  /// @throws InvalidArgument naming the option out of its declared range, or an empty frame.
  void validate() const;
};

/// What is wrong with `options`' plan_requests beside its lockstep, or "" when nothing is.
std::string planRequestsProblem(const BridgeOptions& options);

/// What is wrong with `options`' interface beside its lockstep and plan requests, or "" when nothing is.
std::string interfaceProblem(const BridgeOptions& options);

/// True when the planner answers with velocity commands rather than paths.
inline bool commandsVelocity(const BridgeOptions& options) { return options.interface == kInterfaceCmdVel; }

/// True when a local planner in continuous motion answers on a timer (so a period asked again moves its clock on).
inline bool wakesOnTimer(const BridgeOptions& options) { return options.wakes_on != kWakesOnMessages; }

/// True when a local planner in continuous motion is sent the map and goal only when an episode begins.
inline bool sendsChangesOnly(const BridgeOptions& options) {
  return options.period_messages == kPeriodMessagesChanges;
}

/// What is wrong with `options`' period_messages beside its wakes_on (both resolved), or "" when nothing is.
std::string periodMessagesProblem(const BridgeOptions& options);

/// True when a lockstep bridge with `options` asks the planner at every step.
inline bool asksEveryStep(const BridgeOptions& options) { return options.plan_requests == kPlanRequestsEveryStep; }

/// True when a lockstep bridge with `options` asks the planner at a step whose scan changed the robot's map.
inline bool asksOnChange(const BridgeOptions& options) { return options.plan_requests != kPlanRequestsOnBlocked; }

/// One declaration per planner bridge parameter (the bridge reads them; the experiment's graph writes them).
const std::vector<OptionSpec<BridgeOptions>>& bridgeOptionSpecs();

/// The robot's footprint as costmaps read it (`footprint`): a 16-gon of `radius` metres round the robot's centre,
/// as [x, y] vertices.
std::vector<std::pair<double, double>> footprintPolygon(double radius);

/// The bridge's default base frame in namespace `ns`: "NS/robot/base_link" without the leading slash.
std::string defaultBridgeBaseFrame(const std::string& ns);

}  // namespace agents
}  // namespace ppp
