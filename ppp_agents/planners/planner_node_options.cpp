#include "planner_node_options.hpp"

#include <algorithm>
#include <limits>

#include "planted_faults.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/motion_options.hpp"
#include "ppp_core/option_yaml.hpp"

namespace ppp {
namespace planners {

void PlannerFrames::validate() const {
  for (const auto& [name, frame] : {std::pair<const char*, const std::string*>{"map_frame", &map_frame},
                                    {"base_frame", &base_frame}}) {
    if (frame->empty() || frame->front() == '/') {
      throw InvalidArgument(name, "expected a tf frame name without a leading slash, got '" + *frame + "'");
    }
  }
}

const std::vector<OptionSpec<PlannerFrames>>& plannerFrameSpecs() {
  using F = PlannerFrames;
  static const std::vector<OptionSpec<F>> specs = {
      declareOption("map_frame", "frame of the map, the goal and the plan (no leading slash)",
                    +[](F& f) -> std::string& { return f.map_frame; })
          .notAffectingResults(),
      declareOption("base_frame", "the robot's frame ('': the node's namespace + /base_link)",
                    +[](F& f) -> std::string& { return f.base_frame; })
          .notAffectingResults(),
  };
  return specs;
}

void PlannerPeriod::validate() const { checkOptionRanges(plannerPeriodSpecs(), *this); }

const std::vector<OptionSpec<PlannerPeriod>>& plannerPeriodSpecs() {
  using P = PlannerPeriod;
  static const std::vector<OptionSpec<P>> specs = {
      declareOption("control_period", "continuous motion: seconds between two control periods (set by the graph)",
                    +[](P& p) -> double& { return p.control_period; }, Bounds{1e-6, 1e3}),
  };
  return specs;
}

void PlannerBody::validate() const { checkOptionRanges(plannerBodySpecs(), *this); }

const std::vector<OptionSpec<PlannerBody>>& plannerBodySpecs() {
  using B = PlannerBody;
  static const std::vector<OptionSpec<B>> specs = {
      declareOption("inflation",
                    "plan as a disc of this radius in map cells: cells nearer a known obstacle or the map's edge are "
                    "not entered (0: a point; right for the robot when it equals its robot_radius)",
                    +[](B& b) -> double& { return b.inflation; }, Bounds{0, kMaxRobotRadius}),
  };
  return specs;
}

void OmplNodeParameters::validate() const {
  checkOptionRanges(omplNodeOptionSpecs(), *this);
  planner.validate();
}

const std::vector<OptionSpec<OmplNodeParameters>>& omplNodeOptionSpecs() {
  using O = OmplNodeParameters;
  static const std::vector<OptionSpec<O>> specs = [] {
    std::vector<OptionChoice> planners;
    for (const std::string& name : omplPlannerNames()) planners.push_back({name, ""});
    return std::vector<OptionSpec<O>>{
        declareOption("planner", "the OMPL geometric planner", +[](O& o) -> std::string& { return o.planner.planner; })
            .withChoices("OMPL planner", planners),
        declareOption("planning_time",
                      "wall-clock seconds OMPL may plan per request (0: no such limit; a plan it cuts short depends "
                      "on the machine's load, so results with it are not reproducible)",
                      +[](O& o) -> double& { return o.planner.planning_time; }, Bounds{0, 3600}),
        declareOption("planning_iterations",
                      "planner iterations OMPL may run per request (0: 100,000 for RRTConnect and PRM, 10,000 for "
                      "RRTstar; an RRTConnect iteration grows one tree a step towards a random sample and the other "
                      "towards it): a time limit that gives the same plans on any machine (RRTConnect, RRTstar; PRM "
                      "grows its roadmap on a timer)",
                      +[](O& o) -> int& { return o.planner.planning_iterations; }, Bounds{0, 1000000000}),
        declareOption("seed", "seed each plan's random numbers derive from, with what the plan is asked",
                      +[](O& o) -> int& { return o.planner.seed; }, Bounds{1, 2147483647}),
        declareOption("unknown_is_free", "plan through unknown map cells",
                      +[](O& o) -> bool& { return o.unknown_is_free; }),
    };
  }();
  return specs;
}

void MrptNodeParameters::validate() const { checkOptionRanges(mrptNodeOptionSpecs(), *this); }

const std::vector<OptionSpec<MrptNodeParameters>>& mrptNodeOptionSpecs() {
  using M = MrptNodeParameters;
  static const std::vector<OptionSpec<M>> specs = {
      declareOption("unknown_is_free", "plan through unknown map cells (MRPT itself takes them for obstacles)",
                    +[](M& m) -> bool& { return m.unknown_is_free; }),
  };
  return specs;
}

void ReactiveNodeParameters::validate() const { checkOptionRanges(reactiveNodeOptionSpecs(), *this); }

const std::vector<OptionSpec<ReactiveNodeParameters>>& reactiveNodeOptionSpecs() {
  using R = ReactiveNodeParameters;
  static const std::vector<OptionSpec<R>> specs = {
      declareOption("method", "MRPT's holonomic reactive method", +[](R& r) -> std::string& { return r.method; })
          .withChoices("holonomic method",
                       {{"ND", "Nearness Diagram (mrpt::nav::CHolonomicND): it prefers the direction it chose last"},
                        {"VFF", "virtual force field (CHolonomicVFF)"},
                        {"FullEval", "full evaluation of every direction (CHolonomicFullEval)"}}),
      declareOption("obstacles", "where the distances to obstacles per direction come from",
                    +[](R& r) -> std::string& { return r.obstacles; })
          .withChoices("obstacle source",
                       {{kObstaclesFromScan, "the robot's scan: how far its body (~robot_radius) travels in each "
                                             "direction before it touches a return, as MRPT's navigator gives them "
                                             "(a point: the nearest ray in each direction)"},
                        {kObstaclesFromRays, "the nearest ray of the robot's scan in each direction, whatever its "
                                             "body (what a point would have)"},
                        {kObstaclesFromMemory, "how far its body travels in each direction on the robot's map: what "
                                               "it remembers, unknown cells free"}}),
      declareOption("frame", "the frame the method's 72 directions are counted in, from its seam straight behind",
                    +[](R& r) -> std::string& { return r.frame; })
          .withChoices("frame",
                       {{kReactiveFrameRobot, "the robot's, as MRPT's navigator gives them (on the grid the map's: the "
                                              "seam points west)"},
                        {kReactiveFrameGoal, "turned so that the goal lies on the centre of the sector ahead, the "
                                             "seam behind, 177.5 degrees from it (ND mishandles goals within two "
                                             "sectors of its seam)"}}),
      declareOption("range",
                    "metres the obstacle distances and the goal are given to the method as fractions of (0: the "
                    "scan's range_max)",
                    +[](R& r) -> double& { return r.range; }, Bounds{0, 1e6}),
      declareOption("max_speed", "metres per second the method's full speed commands",
                    +[](R& r) -> double& { return r.max_speed; }, Bounds{1e-6, 1e6}),
      declareOption("max_turn", "continuous motion, diff drive: radians per second the robot turns at most",
                    +[](R& r) -> double& { return r.max_turn; }, Bounds{1e-6, 1e6}),
      declareOption("robot_radius",
                    "metres of the robot's disc, which obstacle distances are for (0: a point; the experiment's "
                    "graph sets it in continuous motion)",
                    +[](R& r) -> double& { return r.robot_radius; }, Bounds{0, kMaxMotionMagnitude}),
      declareOption("kinematics", "the robot the commands are for (the experiment's graph sets it in continuous motion)",
                    +[](R& r) -> std::string& { return r.kinematics; })
          .withChoices("kinematics",
                       {{"", "the grid: linear x east and y north, the robot never turning"},
                        {kKinematicsDiffDrive, "continuous motion, diff drive: turn towards the method's direction "
                                               "(relative to the heading), drive along the heading as it comes ahead"},
                        {kKinematicsHolonomic, "continuous motion, holonomic: the direction as linear x and y in "
                                               "the robot's frame"}}),
  };
  return specs;
}

KinematicLimits DwaNodeParameters::limits() const {
  KinematicLimits limits;
  limits.holonomic = kinematics != kKinematicsDiffDrive;
  limits.max_linear_speed = max_linear_speed;
  limits.max_angular_speed = max_angular_speed;
  const bool grid = kinematics.empty();
  limits.max_linear_acceleration = grid ? std::numeric_limits<double>::infinity() : max_linear_acceleration;
  limits.max_angular_acceleration = grid ? std::numeric_limits<double>::infinity() : max_angular_acceleration;
  return limits;
}

DynamicWindowOptions DwaNodeParameters::windowOptions() const {
  DynamicWindowOptions options = window;
  options.grid_moves = kinematics.empty();
  return options;
}

void DwaNodeParameters::validate() const { checkOptionRanges(dwaNodeOptionSpecs(), *this); }

const std::vector<OptionSpec<DwaNodeParameters>>& dwaNodeOptionSpecs() {
  using D = DwaNodeParameters;
  static const std::vector<OptionSpec<D>> specs = {
      declareOption("kinematics", "the robot the commands are for (the experiment's graph sets it in continuous motion)",
                    +[](D& d) -> std::string& { return d.kinematics; })
          .withChoices("kinematics",
                       {{"", "the grid: the candidates are standing and the four moves at top speed (the grid "
                             "rounds any other direction)"},
                        {kKinematicsDiffDrive, "continuous motion, diff drive: forward speeds and turning rates"},
                        {kKinematicsHolonomic, "continuous motion, holonomic: velocities in the robot's plane"}}),
      declareOption("max_linear_speed", "the robot's top speed, metres per second (set by the graph)",
                    +[](D& d) -> double& { return d.max_linear_speed; }, Bounds{1e-6, kMaxMotionMagnitude}),
      declareOption("max_angular_speed", "the robot's top turning rate, radians per second (set by the graph)",
                    +[](D& d) -> double& { return d.max_angular_speed; }, Bounds{1e-6, kMaxMotionMagnitude}),
      declareOption("max_linear_acceleration", "continuous motion: metres per second squared (set by the graph)",
                    +[](D& d) -> double& { return d.max_linear_acceleration; }, Bounds{1e-6, kMaxMotionMagnitude}),
      declareOption("max_angular_acceleration", "continuous motion: radians per second squared (set by the graph)",
                    +[](D& d) -> double& { return d.max_angular_acceleration; }, Bounds{1e-6, kMaxMotionMagnitude}),
      declareOption("control_period", "seconds a command is held (set by the graph in continuous motion)",
                    +[](D& d) -> double& { return d.control_period; }, Bounds{1e-6, 1e3}),
      declareOption("robot_radius", "the robot's disc in metres (set by the graph in continuous motion)",
                    +[](D& d) -> double& { return d.robot_radius; }, Bounds{0, kMaxMotionMagnitude}),
      declareOption("costmap_resolution", "metres per cell of the memory of scan returns its routes are planned on",
                    +[](D& d) -> double& { return d.costmap_resolution; }, Bounds{1e-3, 1e3}),
      declareOption("inflation_radius", "metres around remembered returns within which routes cost more",
                    +[](D& d) -> double& { return d.inflation_radius; }, Bounds{0, 1e3}),
      declareOption("replan_every", "continuous motion: control periods between two plans of the route (the grid: "
                                    "every step)",
                    +[](D& d) -> int& { return d.replan_every; }, Bounds{1, 1000000}),
      declareOption("sim_time", "seconds each sampled velocity is rolled out for",
                    +[](D& d) -> double& { return d.window.sim_time; }, Bounds{1e-3, 60}),
      declareOption("linear_samples", "forward speeds sampled (holonomic: rings of velocities)",
                    +[](D& d) -> int& { return d.window.linear_samples; }, Bounds{1, 100}),
      declareOption("angular_samples", "turning rates sampled (holonomic: directions per ring)",
                    +[](D& d) -> int& { return d.window.angular_samples; }, Bounds{1, 100}),
      declareOption("goal_bias", "cost per metre from a rollout's end to the goal",
                    +[](D& d) -> double& { return d.window.goal_bias; }, Bounds{0, 1e6}),
      declareOption("clearance_bias", "cost of a rollout touching the robot's disc to an obstacle (falling to 0 at "
                                      "clearance_scale)",
                    +[](D& d) -> double& { return d.window.clearance_bias; }, Bounds{0, 1e6}),
      declareOption("clearance_scale", "metres of clearance beyond which an obstacle costs nothing",
                    +[](D& d) -> double& { return d.window.clearance_scale; }, Bounds{1e-6, 1e6}),
      declareOption("safety_margin", "metres a rollout keeps between the robot's disc and every scan return",
                    +[](D& d) -> double& { return d.window.safety_margin; }, Bounds{0, 1e6}),
  };
  return specs;
}

double TpSpaceNodeParameters::bodyRadius() const { return std::max(robot_radius, kTpSpaceSmallestBody); }

void TpSpaceNodeParameters::validate() const { checkOptionRanges(tpSpaceNodeOptionSpecs(), *this); }

const std::vector<OptionSpec<TpSpaceNodeParameters>>& tpSpaceNodeOptionSpecs() {
  using T = TpSpaceNodeParameters;
  static const std::vector<OptionSpec<T>> specs = {
      declareOption("config", "an MRPT reactive navigation configuration (INI: PTGs, holonomic method, motion "
                              "decider; empty: the shipped config/mrpt_tpspace.ini, MRPT's example)",
                    +[](T& t) -> std::string& { return t.config; }),
      declareOption("kinematics", "the robot the commands are for (the experiment's graph sets it in continuous motion)",
                    +[](T& t) -> std::string& { return t.kinematics; })
          .withChoices("kinematics", {{kKinematicsDiffDrive, "continuous motion, diff drive: linear x and angular z, "
                                                             "as the PTGs drive"}}),
      declareOption("max_linear_speed", "the robot's top speed, metres per second (set by the graph)",
                    +[](T& t) -> double& { return t.max_linear_speed; }, Bounds{1e-6, kMaxMotionMagnitude}),
      declareOption("max_angular_speed", "the robot's top turning rate, radians per second (set by the graph)",
                    +[](T& t) -> double& { return t.max_angular_speed; }, Bounds{1e-6, kMaxMotionMagnitude}),
      declareOption("robot_radius", "the robot's disc in metres (set by the graph); MRPT's PTGs need a body, so "
                                    "a smaller one, a point included, is given a disc of 0.05 m, their grid's cell",
                    +[](T& t) -> double& { return t.robot_radius; }, Bounds{0, kMaxMotionMagnitude}),
      declareOption("target_allowed_distance", "metres from the goal at which the navigator ends its navigation "
                                               "(below the goal tolerance, or the robot stops short of the goal)",
                    +[](T& t) -> double& { return t.target_allowed_distance; }, Bounds{1e-3, 1e3}),
  };
  return specs;
}

void ZooNodeParameters::validate() const {
  if (fault.empty()) throw InvalidArgument("fault", "the zoo planner needs a fault; expected one of its choices");
  checkOptionRanges(zooNodeOptionSpecs(), *this);
  FaultyPlanner(fault, limit);  // refuses an unknown, repeated or unplantable fault, or a limit of several faults
}

namespace {

/// `spec` with `choices` named in its documentation but not restricted to one of them: the zoo's fault takes a
/// list of them, checked by ZooNodeParameters::validate().
OptionSpec<ZooNodeParameters> withChoicesListed(OptionSpec<ZooNodeParameters> spec, std::vector<OptionChoice> choices) {
  spec.choices = std::move(choices);
  return spec;
}

}  // namespace

const std::vector<OptionSpec<ZooNodeParameters>>& zooNodeOptionSpecs() {
  using Z = ZooNodeParameters;
  static const std::vector<OptionSpec<Z>> specs = [] {
    std::vector<OptionChoice> faults;
    for (const PlantedFault& f : plantedFaults()) {
      const std::string limit = f.default_limit > 0 ? " (~limit " + std::to_string(f.default_limit) + ")" : "";
      faults.push_back({f.name, f.kind + ": " + f.description + limit});
    }
    return std::vector<OptionSpec<Z>>{
        withChoicesListed(declareOption("fault", "the planted fault, or several separated by commas (required; "
                                                 "dead_end_filter cannot go with goal_clearance, which refuses its goals first)",
                                        +[](Z& z) -> std::string& { return z.fault; }),
                          faults),
        declareOption("limit", "the fault's limit: cells of route, cells expanded, open-list entries or routes "
                               "planned (0: the fault's own default; faults without one ignore it; with several "
                               "faults that take one, only 0)",
                      +[](Z& z) -> int& { return z.limit; }, Bounds{0, 1000000}),
    };
  }();
  return specs;
}

std::string defaultBaseFrame(const std::string& node_namespace) {
  return ppp_msgs::frames::under(node_namespace, ppp_msgs::frames::kBaseLink);
}

}  // namespace planners
}  // namespace ppp
