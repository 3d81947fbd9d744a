#include "mrpt_tpspace_navigator.hpp"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/Clock.h>
#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/CPolygon.h>
#include <mrpt/nav/reactive/CReactiveNavigationSystem.h>
#include <mrpt/nav/reactive/CRobot2NavInterface.h>

#include <cmath>
#include <exception>
#include <stdexcept>
#include <filesystem>
#include <system_error>

#include <unistd.h>

#include "ppp_core/error.hpp"

namespace ppp {
namespace planners {

namespace {

constexpr const char* kFrame = "map";  // the navigator's world frame: poses and the target are in it
constexpr int kShapeSides = 16;         // the robot's polygon round its disc

/// MRPT's clock at `seconds` of simulated time: counted from a day after MRPT's epoch, which is its invalid time.
mrpt::Clock::time_point simulatedTime(double seconds) {
  return mrpt::Clock::time_point(std::chrono::duration_cast<mrpt::Clock::duration>(
      std::chrono::duration<double>(86400 + seconds)));
}

/// A regular polygon of kShapeSides vertices whose sides touch the disc of `radius`.
mrpt::math::CPolygon discShape(double radius) {
  mrpt::math::CPolygon shape;
  const double corner = radius / std::cos(M_PI / kShapeSides);
  for (int i = 0; i < kShapeSides; ++i) {
    const double angle = (i + 0.5) * 2 * M_PI / kShapeSides;
    shape.AddVertex(corner * std::cos(angle), corner * std::sin(angle));
  }
  return shape;
}

/// Checks that a robot's value is a positive number, naming it.
void requirePositive(const char* name, double value) {
  if (!(value > 0) || !std::isfinite(value)) {
    throw InvalidArgument(name, "the TP-space navigator needs a positive number, got " + std::to_string(value));
  }
}

/// The message of an MRPT exception without its call stack: the text after "Message:" to the end of its line, or
/// the whole text when it has none.
std::string mrptMessage(const std::exception& e) {
  const std::string text = e.what();
  const std::size_t start = text.find("Message:");
  if (start == std::string::npos) return text;
  const std::size_t from = text.find_first_not_of(' ', start + 8);
  return text.substr(from, text.find('\n', from) - from);
}

}  // namespace

std::vector<MapPoint> laserReturns(const std::vector<float>& ranges, double angle_min, double angle_increment) {
  std::vector<MapPoint> returns;
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    if (!std::isfinite(ranges[i])) continue;
    const double angle = angle_min + static_cast<double>(i) * angle_increment;
    returns.push_back(MapPoint{ranges[i] * std::cos(angle), ranges[i] * std::sin(angle)});
  }
  return returns;
}

/// The robot as the navigator asks about it: the period's sensing in, the command out.
class MrptTpSpaceNavigator::Robot : public mrpt::nav::CRobot2NavInterface {
 public:
  Robot() { setMinLoggingLevel(mrpt::system::LVL_ERROR); }

  void sense(const TpSpaceSensing& sensing) {
    sensing_ = sensing;
    command_ = BodyVelocity{};
  }
  const BodyVelocity& command() const { return command_; }

  bool getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose, mrpt::math::TTwist2D& velocity,
                               mrpt::system::TTimeStamp& timestamp, mrpt::math::TPose2D& odometry,
                               std::string& frame) override {
    pose = mrpt::math::TPose2D(sensing_.pose.x, sensing_.pose.y, sensing_.pose.theta);
    odometry = pose;
    const double c = std::cos(sensing_.pose.theta), s = std::sin(sensing_.pose.theta);
    const BodyVelocity& v = sensing_.velocity;
    velocity = mrpt::math::TTwist2D(c * v.forward - s * v.left, s * v.forward + c * v.left, v.turn);
    timestamp = simulatedTime(sensing_.time);
    frame = kFrame;
    return true;
  }
  bool changeSpeeds(const mrpt::kinematics::CVehicleVelCmd& command) override {
    const auto* drive = dynamic_cast<const mrpt::kinematics::CVehicleVelCmd_DiffDriven*>(&command);
    if (drive == nullptr) return false;  // a PTG for another kind of robot: MRPT stops and reports it
    command_ = BodyVelocity{drive->lin_vel, 0, drive->ang_vel};
    kept_ = command_;
    return true;
  }
  bool changeSpeedsNOP() override {  // keep the last command
    command_ = kept_;
    return true;
  }
  bool stop(bool /*emergency*/) override {
    command_ = kept_ = BodyVelocity{};
    return true;
  }
  mrpt::kinematics::CVehicleVelCmd::Ptr getEmergencyStopCmd() override { return getStopCmd(); }
  mrpt::kinematics::CVehicleVelCmd::Ptr getStopCmd() override {
    return std::make_shared<mrpt::kinematics::CVehicleVelCmd_DiffDriven>();
  }
  bool senseObstacles(mrpt::maps::CSimplePointsMap& obstacles, mrpt::system::TTimeStamp& timestamp) override {
    obstacles.clear();
    for (const MapPoint& p : sensing_.returns) obstacles.insertPoint(static_cast<float>(p.x), static_cast<float>(p.y));
    timestamp = simulatedTime(sensing_.time);
    return true;
  }
  double getNavigationTime() override { return sensing_.time - started_; }
  void resetNavigationTimer() override { started_ = sensing_.time; }

 private:
  TpSpaceSensing sensing_;
  BodyVelocity command_;
  BodyVelocity kept_;
  double started_ = 0;
};

/// A directory of this process's own in the system's temporary directory, removed with everything in it.
struct MrptTpSpaceNavigator::CacheDirectory {
  CacheDirectory() : path(std::filesystem::temp_directory_path() / ("ppp-tpspace-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ~CacheDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  std::filesystem::path path;
};

MrptTpSpaceNavigator::MrptTpSpaceNavigator(const std::string& config_text, const std::string& source,
                                           const TpSpaceRobot& robot)
    : robot_(std::make_unique<Robot>()), radius_(robot.radius) {
  requirePositive("robot_radius", robot.radius);
  requirePositive("max_linear_speed", robot.max_linear_speed);
  requirePositive("max_angular_speed", robot.max_angular_speed);
  mrpt::Clock::setSimulatedTime(simulatedTime(0));
  mrpt::Clock::setActiveClock(mrpt::Clock::Source::Simulated);
  cache_ = std::make_unique<CacheDirectory>();
  try {
    config_ = std::make_unique<mrpt::config::CConfigFileMemory>(config_text);
    const std::string ptg_section = "CReactiveNavigationSystem";
    const int ptgs = config_->read_int(ptg_section, "PTG_COUNT", 0, true);
    for (int i = 0; i < ptgs; ++i) {
      const std::string prefix = "PTG" + std::to_string(i) + "_";
      config_->write(ptg_section, prefix + "v_max_mps", robot.max_linear_speed);
      config_->write(ptg_section, prefix + "w_max_dps", robot.max_angular_speed * 180 / M_PI);
    }
    config_->write("CAbstractPTGBasedReactive", "robotMax_V_mps", robot.max_linear_speed);
    config_->write("CAbstractPTGBasedReactive", "robotMax_W_degps", robot.max_angular_speed * 180 / M_PI);
    navigator_ = build();
  } catch (const std::exception& e) {
    throw InvalidArgument(source, "MRPT refuses the reactive navigation configuration: " + mrptMessage(e));
  }
}

std::unique_ptr<mrpt::nav::CReactiveNavigationSystem> MrptTpSpaceNavigator::build() const {
  auto navigator = std::make_unique<mrpt::nav::CReactiveNavigationSystem>(*robot_, false, false);
  navigator->setMinLoggingLevel(mrpt::system::LVL_ERROR);
  // Its delay statistics would be printed at every episode's end; MRPT lends them out only as const.
  const_cast<mrpt::system::CTimeLogger&>(navigator->getDelaysTimeLogger()).disable();
  navigator->loadConfigFile(*config_);
  navigator->params_abstract_ptg_navigator.ptg_cache_files_directory = cache_->path.string();
  navigator->changeRobotShape(discShape(radius_));
  navigator->changeRobotCircularShapeRadius(radius_);
  navigator->initialize();
  for (std::size_t i = 0; i < navigator->getPTG_count(); ++i) {
    const auto* ptg = navigator->getPTG(i);
    if (!std::dynamic_pointer_cast<mrpt::kinematics::CVehicleVelCmd_DiffDriven>(
            ptg->getSupportedKinematicVelocityCommand())) {
      throw std::invalid_argument("PTG" + std::to_string(i) + " (" + ptg->GetRuntimeClass()->className +
                                  ") is not for a differential-drive robot");
    }
  }
  return navigator;
}

MrptTpSpaceNavigator::~MrptTpSpaceNavigator() = default;

void MrptTpSpaceNavigator::start(MapPoint goal, double tolerance) {
  mrpt::nav::CAbstractNavigator::TNavigationParams request;
  request.target.target_coords = mrpt::math::TPose2D(goal.x, goal.y, 0);
  request.target.target_frame_id = kFrame;
  request.target.targetAllowedDistance = static_cast<float>(tolerance);
  try {
    // A navigator that has never navigated: nothing of the last episode, so a run plays alike whichever runs its
    // process played before.
    if (navigated_) navigator_ = next_.get();
    navigated_ = true;
    next_ = std::async(std::launch::async, [this] { return build(); });
  } catch (const std::exception& e) {
    throw Error("MRPT CReactiveNavigationSystem: " + mrptMessage(e));
  }
  navigator_->navigate(&request);
}

BodyVelocity MrptTpSpaceNavigator::step(const TpSpaceSensing& sensing) {
  mrpt::Clock::setSimulatedTime(simulatedTime(sensing.time));
  robot_->sense(sensing);
  try {
    navigator_->navigationStep();
  } catch (const std::exception& e) {
    throw Error("MRPT CReactiveNavigationSystem: " + mrptMessage(e));
  }
  return robot_->command();
}

std::string MrptTpSpaceNavigator::error() const {
  if (navigator_->getCurrentState() != mrpt::nav::CAbstractNavigator::NAV_ERROR) return "";
  const std::string& message = navigator_->getErrorReason().error_msg;
  return message.empty() ? "navigation error" : message;
}

}  // namespace planners
}  // namespace ppp
