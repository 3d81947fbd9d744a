#include "ppp_agents/planner_episode.hpp"

#include "ppp_core/diagnosis.hpp"
#include "ppp_core/footprint.hpp"
#include "ppp_core/reachability.hpp"

namespace ppp {
namespace agents {

void PlannerEpisode::start(const EpisodeInfo& info, const Grid* prior, int memory_window, double resolution) {
  frame_ = MapFrame{info.width, info.height, resolution};
  goal_ = info.goal;
  connectivity_ = info.connectivity;
  has_prior_ = prior != nullptr;
  known_.width = info.width;
  known_.height = info.height;
  known_.cells.assign(static_cast<std::size_t>(info.width) * info.height, kScanUnknown);
  if (has_prior_) {
    for (int i = 0; i < prior->size(); ++i) {
      known_.cells[i] = prior->isObstacle(prior->cellAt(i)) ? kScanObstacle : kScanFree;
    }
  } else {
    memory_.reset(info.width, info.height, memory_window);
  }
  follower_.clear();
  follower_.setConnectivity(info.connectivity);
  position_ = previous_ = Cell{-1, -1};
  changed_ = false;
}

bool PlannerEpisode::observe(const Scan& scan) {
  previous_ = position_;
  position_ = scan.position();
  changed_ = false;
  if (has_prior_) return false;
  memory_.update(scan);
  for (int y = 0; y < frame_.height; ++y) {
    for (int x = 0; x < frame_.width; ++x) {
      std::int8_t& known = known_.cells[y * frame_.width + x];
      const std::int8_t now = memory_.at(Cell{x, y});
      changed_ = changed_ || known != now;
      known = now;
    }
  }
  return changed_;
}

std::optional<Action> PlannerEpisode::moveWithoutRequest(const BridgeOptions& options) {
  if (!options.lockstep || asksEveryStep(options) || position_ == previous_) return std::nullopt;
  if (changed_ && asksOnChange(options)) return std::nullopt;
  return next(position_);
}

void PlannerEpisode::offer(const std::vector<MapPoint>& points, Cell robot) {
  if (!points.empty()) follower_.follow(points, frame_, robot, goal_, known_);
}

std::optional<Action> PlannerEpisode::next(Cell robot) { return follower_.next(robot, known_); }

bool PlannerEpisode::fits(const std::vector<MapPoint>& points, Cell robot) const {
  if (points.empty()) return true;
  PathFollower probe;
  return probe.follow(points, frame_, robot, goal_, known_).empty();
}

Answer PlannerEpisode::answer(const std::vector<MapPoint>& points, Cell robot) {
  if (points.empty()) return Answer{AnswerVerdict::NoPath, Action::Stay, "the planner published an empty path"};
  const std::string problem = follower_.follow(points, frame_, robot, goal_, known_);
  if (!problem.empty()) return Answer{AnswerVerdict::InvalidPath, Action::Stay, problem};
  const std::optional<Action> action = follower_.next(robot, known_);
  if (!action) {
    return Answer{AnswerVerdict::InvalidPath, Action::Stay, "the path gives the robot no move from its cell"};
  }
  return Answer{AnswerVerdict::Move, *action, ""};
}

std::uint64_t PlannerEpisode::stateDigest(const std::vector<MapPoint>& following) const {
  StateDigest digest;
  for (const Cell c : {position_, previous_, goal_}) {
    digest.add(c.x);
    digest.add(c.y);
  }
  digest.add(changed_ ? 1 : 0);
  digest.addBytes(known_.cells.data(), known_.cells.size());
  follower_.addTo(&digest);
  digest.add(static_cast<std::int64_t>(following.size()));
  for (const MapPoint& p : following) {
    digest.addBytes(&p.x, sizeof p.x);
    digest.addBytes(&p.y, sizeof p.y);
  }
  return digest.value();
}

const char* PlannerEpisode::noPathKind(Cell robot, double robot_radius) const {
  Grid map(frame_.width, frame_.height);
  for (int i = 0; i < map.size(); ++i) map.setObstacle(map.cellAt(i), known_.cells[i] == kScanObstacle);
  Grid space;
  const Grid& motion = motionGrid(map, robot_radius, &space);
  const bool route = motion.contains(robot) && motion.isFree(robot) && motion.isFree(goal_) &&
                     isReachable(motion, robot, goal_);
  return route ? diagnosis::kMissedRoute : diagnosis::kNoRoute;
}

}  // namespace agents
}  // namespace ppp
