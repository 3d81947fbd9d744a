#include "ppp_agents/planner_bridge_options.hpp"

#include <cmath>

#include "ppp_core/error.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/option_yaml.hpp"

namespace ppp {
namespace agents {

void BridgeOptions::validate() const {
  checkOptionRanges(bridgeOptionSpecs(), *this);
  if (!planRequestsProblem(*this).empty()) throw InvalidArgument("plan_requests", planRequestsProblem(*this));
  if (!interfaceProblem(*this).empty()) throw InvalidArgument("interface", interfaceProblem(*this));
  if (!periodMessagesProblem(*this).empty()) throw InvalidArgument("period_messages", periodMessagesProblem(*this));
  if (map_frame.empty()) throw InvalidArgument("map_frame", "expected a non-empty frame name");
  if (base_frame.empty()) throw InvalidArgument("base_frame", "expected a non-empty frame name");
}

std::string planRequestsProblem(const BridgeOptions& options) {
  if (options.lockstep || asksEveryStep(options)) return "";
  return "a free-running bridge (lockstep: false) asks only when the robot's path is blocked; " +
         options.plan_requests + " needs lockstep: true";
}

std::string periodMessagesProblem(const BridgeOptions& options) {
  if (!sendsChangesOnly(options) || !wakesOnTimer(options)) return "";
  return "changes needs a planner that answers each period's messages (wakes_on: messages): a period a timer "
         "overslept is asked again a control period later, and its planner could not tell it from the first of an "
         "episode whose map and goal it has not yet received";
}

std::string interfaceProblem(const BridgeOptions& options) {
  if (!commandsVelocity(options)) return "";
  if (!options.lockstep) return "a cmd_vel planner is played in lockstep only (lockstep: true)";
  if (!asksEveryStep(options)) {
    return "a cmd_vel planner is asked at every step (it gives no path to move along), not " +
           options.plan_requests;
  }
  return "";
}

const std::vector<OptionSpec<BridgeOptions>>& bridgeOptionSpecs() {
  using B = BridgeOptions;
  static const std::vector<OptionSpec<B>> specs = {
      declareOption("resolution", "metres per PPP cell",
                    +[](B& b) -> double& { return b.resolution; }, Bounds{1e-6, 1e6}),
      declareOption("cells_per_ppp_cell",
                    "map cells per PPP cell side in the map published to the planner (so a robot's disc is "
                    "several map cells wide)",
                    +[](B& b) -> int& { return b.cells_per_ppp_cell; }, Bounds{1, kMaxCellsPerPppCell}),
      declareOption("robot_radius",
                    "the robot's radius in PPP cells (the experiment's), set for the planner as robot/robot_radius "
                    "and robot/footprint in metres",
                    +[](B& b) -> double& { return b.robot_radius; }, Bounds{0, kMaxRobotRadius}),
      declareOption("plan_timeout", "seconds the planner has to answer a plan request",
                    +[](B& b) -> double& { return b.plan_timeout; }, Bounds{1e-3, 86400}),
      declareOption("lockstep",
                    "move only on the planner's answer to a plan request, so a run does not depend on timing "
                    "(false: free-running, the robot follows the newest path; not reproducible)",
                    +[](B& b) -> bool& { return b.lockstep; }),
      declareOption("plan_requests", "in lockstep, the steps at which the bridge asks the planner for a plan",
                    +[](B& b) -> std::string& { return b.plan_requests; })
          .withChoices("plan request rule",
                       {{kPlanRequestsEveryStep, "every step"},
                        {kPlanRequestsOnChange,
                         "when the robot's map changed, the robot did not move or its path gives it no move; "
                         "otherwise it moves on along the plan"},
                        {kPlanRequestsOnBlocked,
                         "only when the robot did not move or its path gives it no move (blocked by a known "
                         "obstacle, or the robot off it), as a navigation stack re-plans when its path is blocked"}}),
      declareOption("interface", "what the planner answers a request with",
                    +[](B& b) -> std::string& { return b.interface; })
          .withChoices("planner interface",
                       {{kInterfacePath, "a path (nav_msgs/Path on plan), followed cell by cell"},
                        {kInterfaceCmdVel,
                         "a velocity command (geometry_msgs/TwistStamped on cmd_vel, stamped with the request's "
                         "stamp): the robot takes the move nearest its direction"}}),
      declareOption("endless_proof",
                    "in lockstep, prove loops endless from the bridge's state and the planner's answer, which holds "
                    "when the planner's answer is a function of its input (false for a planner with a memory of "
                    "its own, such as MRPT's ND)",
                    +[](B& b) -> bool& { return b.endless_proof; }),
      declareOption("wakes_on",
                    "interface cmd_vel in continuous motion: what makes the planner answer a control period, which "
                    "says how a period left unanswered for a wall second is asked again",
                    +[](B& b) -> std::string& { return b.wakes_on; })
          .withChoices("planner wake-up",
                       {{kWakesOnAuto,
                         "messages for this repository's local planners (planner_node ppp_agents/dwa_planner_node, "
                         "mrpt_reactive_node, mrpt_tpspace_node, echo_planner_node), a timer for any other planner"},
                        {kWakesOnTimer,
                         "a timer on the robot's clock, as move_base's controller runs: the period is asked again "
                         "a control period later (a timer that overslept wakes), the rest of the episode moved with "
                         "it"},
                        {kWakesOnMessages,
                         "the period's messages, answered as they come, as this repository's local planners do: the "
                         "period's messages are sent again as they were (a planner that restarted gets them, one "
                         "that is only slow answers once) and the clock stays"}}),
      declareOption("period_messages",
                    "interface cmd_vel in continuous motion: which messages each control period sends the planner "
                    "(the rows are the same either way for a planner that follows the rule of the one it is given)",
                    +[](B& b) -> std::string& { return b.period_messages; })
          .withChoices("period messages",
                       {{kPeriodMessagesAuto,
                         "changes for this repository's local planners (unless their wakes_on is timer), every for "
                         "any other planner"},
                        {kPeriodMessagesEvery,
                         "the episode's map and goal with every period, stamped with it, beside tf, odometry, the "
                         "laser and the clock: a planner answers a period when its messages of that stamp are in"},
                        {kPeriodMessagesChanges,
                         "the map and goal only when an episode begins (latched, stamped with its first period), "
                         "then tf, odometry, the laser and the clock: a period more than one and a half control "
                         "periods after the last one answered begins an episode, and is answered when the map and "
                         "goal stamped with it are in (needs wakes_on: messages)"}})
          .notAffectingResults(),
      declareOption("connect_timeout",
                    "seconds to wait at start-up for the planner's topics (an experiment's graph sets 300 for a "
                    "planner the user starts, 20 for one it starts)",
                    +[](B& b) -> double& { return b.connect_timeout; }, Bounds{1e-3, 86400})
          .notAffectingResults(),
      declareOption("map_frame", "frame of the map, poses and goal", +[](B& b) -> std::string& { return b.map_frame; })
          .notAffectingResults(),
      declareOption("base_frame", "the robot's frame ('': NAMESPACE/robot/base_link)",
                    +[](B& b) -> std::string& { return b.base_frame; })
          .notAffectingResults(),
  };
  return specs;
}

std::vector<std::pair<double, double>> footprintPolygon(double radius) {
  constexpr int kVertices = 16;
  std::vector<std::pair<double, double>> vertices;
  for (int i = 0; i < kVertices; ++i) {
    const double angle = 2 * M_PI * i / kVertices;
    vertices.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
  }
  return vertices;
}

std::string defaultBridgeBaseFrame(const std::string& ns) {
  return ppp_msgs::frames::under(ns + "/" + ppp_msgs::topics::kRobotNamespace, ppp_msgs::frames::kBaseLink);
}

}  // namespace agents
}  // namespace ppp
