#include "ppp_agents/continuous/plan_follower.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "ppp_agents/path_follower.hpp"
#include "ppp_agents/planner_bridge_options.hpp"
#include "ppp_agents/protocol/batch_types.hpp"
#include "ppp_core/episode_reason.hpp"
#include "ppp_core/sensor.hpp"

namespace ppp {
namespace agents {

namespace {

/// Points per cell at which the path ahead is checked against the map.
constexpr int kChecksPerCell = 4;

}  // namespace

void PlanFollower::start(const ContinuousStart& start, const std::string& plan_requests) {
  start_ = start;
  start_.prior_map = nullptr;  // copied into prior_: the caller's grid need not outlive the run
  plan_requests_ = plan_requests;
  prior_ = start.prior_map != nullptr ? protocol::priorMapCells(*start.prior_map) : std::vector<std::int8_t>();
  memory_.start(start.frame, start.pose);
  asked_ = false;
  path_.clear();
  follower_ = PurePursuit();
}

bool PlanFollower::observe(const ContinuousSensing& sensing) {
  const bool learned = prior_.empty() && sensing.ranges != nullptr && memory_.add(sensing.pose, *sensing.ranges, start_.beams);
  if (!asked_ || plan_requests_ == kPlanRequestsEveryStep) return true;
  if (learned && plan_requests_ == kPlanRequestsOnChange) return true;
  return atPathEnd(sensing.pose) || pathBlocked();
}

PlanVerdict PlanFollower::take(const std::vector<MapPoint>& path, const Pose2D& pose) {
  asked_ = true;
  if (path.empty()) return {reason::kNoPath, "the planner found no path"};
  const MapFrame& frame = start_.frame;
  double nearest = 1e300;
  for (const MapPoint& p : path) {
    if (!(p.x >= 0 && p.y >= 0 && p.x <= frame.width * frame.resolution && p.y <= frame.height * frame.resolution)) {
      return {reason::kInvalidPath, "a path point (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                                        ") off the map"};
    }
    nearest = std::min(nearest, std::hypot(p.x - pose.x, p.y - pose.y));
  }
  if (nearest > frame.resolution) {
    return {reason::kInvalidPath, "the path passes no nearer than " + std::to_string(nearest) +
                                      " m to the robot (more than a cell)"};
  }
  if (!samePoints(path, path_)) {
    path_ = path;
    follower_.follow(path_, frame.resolution, start_.limits, start_.control_period);
  }
  return {};
}

BodyVelocity PlanFollower::command(const ContinuousSensing& sensing) {
  return path_.empty() ? BodyVelocity{} : follower_.command(sensing.pose, sensing.velocity);
}

bool PlanFollower::atPathEnd(const Pose2D& pose) const {
  if (path_.empty()) return true;
  const double tolerance = kTurnReachedCells * start_.frame.resolution;
  return follower_.segment() + 2 >= path_.size() &&
         std::hypot(path_.back().x - pose.x, path_.back().y - pose.y) <= tolerance;
}

bool PlanFollower::pathBlocked() const {
  const MapFrame& frame = start_.frame;
  const std::vector<std::int8_t>& cells = map();
  const auto blocked = [&](double x, double y) {
    const int column = static_cast<int>(std::floor(x / frame.resolution));
    const int row = static_cast<int>(std::floor(y / frame.resolution));
    if (column < 0 || row < 0 || column >= frame.width || row >= frame.height) return true;
    return cells[static_cast<std::size_t>((frame.height - 1 - row) * frame.width + column)] == kScanObstacle;
  };
  for (std::size_t i = follower_.segment(); i + 1 < path_.size(); ++i) {
    const MapPoint& a = path_[i];
    const MapPoint& b = path_[i + 1];
    const int checks = std::max(1, static_cast<int>(std::ceil(std::hypot(b.x - a.x, b.y - a.y) /
                                                              frame.resolution * kChecksPerCell)));
    for (int k = 1; k <= checks; ++k) {
      const double t = static_cast<double>(k) / checks;
      if (blocked(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y))) return true;
    }
  }
  return false;
}

}  // namespace agents
}  // namespace ppp
