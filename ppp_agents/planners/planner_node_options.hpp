#pragma once

#include <string>
#include <vector>

#include "dynamic_window.hpp"
#include "ompl_grid_planner.hpp"
#include "ppp_core/motion_options.hpp"
#include "ppp_core/option_spec.hpp"
#include "ppp_msgs/graph_names.h"

namespace ppp {
namespace planners {

/// The tf frames a planner node plans in (every example planner's `~map_frame` and `~base_frame`).
struct PlannerFrames {
  std::string map_frame = ppp_msgs::frames::kMap;  ///< Frame of the map, the goal and the plan.
  std::string base_frame;  ///< The robot's frame; its origin is the robot's position ("": defaultBaseFrame).
  /// @throws InvalidArgument naming the frame when it is empty or starts with a slash.
  void validate() const;
};

/// One declaration per frame parameter of a planner node.
const std::vector<OptionSpec<PlannerFrames>>& plannerFrameSpecs();

/// When a local example planner's control periods come (`~control_period`, which the experiment's graph sets in
/// continuous motion): it tells a period that continues the episode of the last one it answered (one period later)
/// from one that begins an episode.
struct PlannerPeriod {
  double control_period = MotionOptions{}.control_period;  ///< Seconds between two control periods.
  /// @throws InvalidArgument naming the parameter out of its declared range.
  void validate() const;
};

/// The declaration of `~control_period`.
const std::vector<OptionSpec<PlannerPeriod>>& plannerPeriodSpecs();

/// The robot's body as an example planner believes it (every example planner's `~inflation`).
struct PlannerBody {
  double inflation = 0;  ///< Known obstacles grown by a disc of this radius in map cells (footprint.hpp; 0: none).
  /// @throws InvalidArgument naming the parameter out of its declared range.
  void validate() const;
};

/// One declaration per body parameter of a planner node.
const std::vector<OptionSpec<PlannerBody>>& plannerBodySpecs();

/// What the OMPL planner node reads besides its frames.
struct OmplNodeParameters {
  OmplPlannerOptions planner;   ///< ~planner, ~planning_time and ~seed.
  bool unknown_is_free = true;  ///< ~unknown_is_free: plan through unknown map cells.
  /// @throws InvalidArgument naming the parameter out of its declared range.
  void validate() const;
};

/// One declaration per `~` parameter of the OMPL planner node besides its frames.
const std::vector<OptionSpec<OmplNodeParameters>>& omplNodeOptionSpecs();

/// What the MRPT planner node reads besides its frames and body.
struct MrptNodeParameters {
  bool unknown_is_free = true;  ///< ~unknown_is_free: plan through unknown map cells.
  /// @throws InvalidArgument naming the parameter out of its declared range.
  void validate() const;
};

/// One declaration per `~` parameter of the MRPT planner node besides its frames and body.
const std::vector<OptionSpec<MrptNodeParameters>>& mrptNodeOptionSpecs();

/// `~obstacles` of the reactive node: obstacle distances from the robot's scan, for its body (a disc's travel).
inline constexpr const char* kObstaclesFromScan = "scan";
/// `~obstacles` of the reactive node: the nearest ray per sector of the robot's scan, whatever its body.
inline constexpr const char* kObstaclesFromRays = "rays";
/// `~obstacles` of the reactive node: obstacle distances cast on the robot's map (its memory).
inline constexpr const char* kObstaclesFromMemory = "memory";

/// `~frame` of the reactive node: the method's sectors in the robot's frame (MRPT's navigator's).
inline constexpr const char* kReactiveFrameRobot = "robot";
/// `~frame` of the reactive node: the method's sectors turned so that the goal lies on the centre of the sector ahead.
inline constexpr const char* kReactiveFrameGoal = "goal";

/// What the MRPT reactive navigator node reads besides its frames.
struct ReactiveNodeParameters {
  std::string method = "ND";                  ///< ~method: the holonomic method (reactiveMethodNames()).
  std::string obstacles = kObstaclesFromScan;  ///< ~obstacles: where obstacle distances come from.
  std::string frame = kReactiveFrameRobot;     ///< ~frame: the frame the method's sectors are in.
  double range = 0;                           ///< ~range: metres the distances are fractions of (0: the scan's range_max).
  double max_speed = 1.0;                     ///< ~max_speed: metres per second at the method's full speed.
  double max_turn = 1.5;                      ///< ~max_turn: radians per second a diff-drive robot turns at most.
  double robot_radius = 0;                    ///< ~robot_radius: metres of the robot's disc (0: a point).
  std::string kinematics;                     ///< ~kinematics: "" on the grid, else the continuous robot's.
  /// @throws InvalidArgument naming the parameter out of its declared range.
  void validate() const;
};

/// One declaration per `~` parameter of the MRPT reactive navigator node besides its frames.
const std::vector<OptionSpec<ReactiveNodeParameters>>& reactiveNodeOptionSpecs();

/// What the DWA example node reads besides its frames: the robot (the experiment's graph sets it in continuous
/// motion, from the motion options; on the grid the window samples the grid's four moves) and the window's weights.
struct DwaNodeParameters {
  std::string kinematics;  ///< ~kinematics: "" on the grid, else the continuous robot's.
  double max_linear_speed = MotionOptions{}.max_linear_speed;                ///< ~max_linear_speed
  double max_angular_speed = MotionOptions{}.max_angular_speed;              ///< ~max_angular_speed
  double max_linear_acceleration = MotionOptions{}.max_linear_acceleration;  ///< ~max_linear_acceleration
  double max_angular_acceleration = MotionOptions{}.max_angular_acceleration;  ///< ~max_angular_acceleration
  double control_period = MotionOptions{}.control_period;  ///< ~control_period: seconds a command is held.
  double robot_radius = 0;                                 ///< ~robot_radius: metres.
  double costmap_resolution = 0.1;  ///< ~costmap_resolution: metres per cell of its memory (ScanCostmap).
  double inflation_radius = 0.5;    ///< ~inflation_radius: metres around obstacles routes avoid.
  int replan_every = 10;            ///< ~replan_every: continuous motion: periods between two plans of the route.
  DynamicWindowOptions window;  ///< ~sim_time, ~linear_samples, ~angular_samples, ~goal_bias, ~clearance_bias, ...
  /// The robot's limits (on the grid: holonomic, accelerations unbounded).
  KinematicLimits limits() const;
  /// The window's options (on the grid: the grid's four moves).
  DynamicWindowOptions windowOptions() const;
  /// @throws InvalidArgument naming the parameter out of its declared range.
  void validate() const;
};

/// One declaration per `~` parameter of the DWA example node besides its frames.
const std::vector<OptionSpec<DwaNodeParameters>>& dwaNodeOptionSpecs();

/// Metres of the smallest body MRPT's PTGs are given (a point has none): one cell of their collision grid.
constexpr double kTpSpaceSmallestBody = 0.05;

/// What the TP-space example node (MRPT's CReactiveNavigationSystem) reads besides its frames: its configuration
/// and the robot, which the experiment's graph sets in continuous motion from the motion options.
struct TpSpaceNodeParameters {
  std::string config;      ///< ~config: an MRPT reactive navigation INI file ("": the shipped one).
  std::string kinematics;  ///< ~kinematics: diff_drive (the navigator's PTGs are for a differential drive).
  double max_linear_speed = MotionOptions{}.max_linear_speed;    ///< ~max_linear_speed
  double max_angular_speed = MotionOptions{}.max_angular_speed;  ///< ~max_angular_speed
  double robot_radius = 0;                                       ///< ~robot_radius: metres.
  /// The body the navigator is given: the robot's disc, at least kTpSpaceSmallestBody metres.
  double bodyRadius() const;
  double target_allowed_distance = 0.1;  ///< ~target_allowed_distance: metres from the goal the navigator stops.
  /// @throws InvalidArgument naming the parameter out of its declared range or choices.
  void validate() const;
};

/// One declaration per `~` parameter of the TP-space example node besides its frames.
const std::vector<OptionSpec<TpSpaceNodeParameters>>& tpSpaceNodeOptionSpecs();

/// What the zoo planner node reads besides its frames: its planted fault (planted_faults.hpp).
struct ZooNodeParameters {
  std::string fault;  ///< ~fault: the planted fault's name (required).
  int limit = 0;      ///< ~limit: the fault's limit (0: its default).
  /// @throws InvalidArgument naming the parameter out of its declared range or choices.
  void validate() const;
};

/// One declaration per `~` parameter of the zoo planner node besides its frames.
const std::vector<OptionSpec<ZooNodeParameters>>& zooNodeOptionSpecs();

/// The default ~base_frame of a node in `node_namespace`: the namespace without its leading slash, then
/// "/base_link" ("/ompl/robot" -> "ompl/robot/base_link", "/" -> "base_link").
std::string defaultBaseFrame(const std::string& node_namespace);

}  // namespace planners
}  // namespace ppp
