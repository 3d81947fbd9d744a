#include "ppp_agents/protocol/continuous_codec.hpp"

#include <cmath>
#include <string>

#include "ppp_agents/protocol/batch_types.hpp"
#include "ppp_core/error.hpp"

namespace ppp {
namespace protocol {

namespace {

constexpr int kMaxBeams = 100000;       // as the laser_beams option allows
constexpr long kMaxMapCells = 1L << 24;  // far above any PPP, below what a message could make us allocate

void requirePositive(double value, const char* field) {
  if (!std::isfinite(value) || value <= 0) {
    throw InvalidArgument(field, "expected a positive finite number, got " + std::to_string(value));
  }
}

void requireInMap(double x, double y, const MapFrame& frame, const char* field) {
  const bool inside = std::isfinite(x) && std::isfinite(y) && x >= 0 && y >= 0 &&
                      x <= frame.width * frame.resolution && y <= frame.height * frame.resolution;
  if (!inside) {
    throw InvalidArgument(field, "expected a point of the " + std::to_string(frame.width) + "x" +
                                     std::to_string(frame.height) + " map, got (" + std::to_string(x) + ", " +
                                     std::to_string(y) + ")");
  }
}

}  // namespace

ppp_msgs::ContinuousStart toStartMessage(std::uint32_t episode, const agents::ContinuousStart& start) {
  ppp_msgs::ContinuousStart m;
  m.episode = episode;
  m.width = static_cast<std::uint32_t>(start.frame.width);
  m.height = static_cast<std::uint32_t>(start.frame.height);
  m.resolution = start.frame.resolution;
  m.start.x = start.pose.x;
  m.start.y = start.pose.y;
  m.start.theta = start.pose.theta;
  m.goal.x = start.goal.x;
  m.goal.y = start.goal.y;
  m.robot_radius = start.radius;
  m.kinematics = start.limits.holonomic ? ppp_msgs::ContinuousStart::HOLONOMIC : ppp_msgs::ContinuousStart::DIFF_DRIVE;
  m.max_linear_speed = start.limits.max_linear_speed;
  m.max_angular_speed = start.limits.max_angular_speed;
  m.max_linear_acceleration = start.limits.max_linear_acceleration;
  m.max_angular_acceleration = start.limits.max_angular_acceleration;
  m.control_period = start.control_period;
  m.laser_beams = static_cast<std::uint32_t>(start.beams.count);
  m.laser_angle_min = start.beams.angle_min;
  m.laser_angle_increment = start.beams.angle_increment;
  m.laser_range_max = start.beams.range_max;
  m.agent_seed = start.seed;
  if (start.prior_map != nullptr) m.prior_map = priorMapCells(*start.prior_map);
  return m;
}

DecodedStart decodeContinuousStart(const ppp_msgs::ContinuousStart& m) {
  DecodedStart decoded;
  agents::ContinuousStart& s = decoded.start;
  if (m.width == 0 || m.height == 0 || static_cast<long>(m.width) * m.height > kMaxMapCells) {
    throw InvalidArgument("size", "expected a map of 1 to " + std::to_string(kMaxMapCells) + " cells, got " +
                                      std::to_string(m.width) + "x" + std::to_string(m.height));
  }
  requirePositive(m.resolution, "resolution");
  s.frame = MapFrame{static_cast<int>(m.width), static_cast<int>(m.height), m.resolution};
  requireInMap(m.start.x, m.start.y, s.frame, "start");
  if (!std::isfinite(m.start.theta)) throw InvalidArgument("start", "expected a finite heading");
  s.pose = Pose2D{m.start.x, m.start.y, m.start.theta};
  requireInMap(m.goal.x, m.goal.y, s.frame, "goal");
  s.goal = MapPoint{m.goal.x, m.goal.y};
  if (!std::isfinite(m.robot_radius) || m.robot_radius < 0) {
    throw InvalidArgument("robot_radius", "expected a finite radius of at least 0, got " +
                                              std::to_string(m.robot_radius));
  }
  s.radius = m.robot_radius;
  if (m.kinematics != ppp_msgs::ContinuousStart::DIFF_DRIVE && m.kinematics != ppp_msgs::ContinuousStart::HOLONOMIC) {
    throw InvalidArgument("kinematics", "expected diff_drive or holonomic, got '" + m.kinematics + "'");
  }
  s.limits.holonomic = m.kinematics == ppp_msgs::ContinuousStart::HOLONOMIC;
  requirePositive(m.max_linear_speed, "max_linear_speed");
  requirePositive(m.max_angular_speed, "max_angular_speed");
  requirePositive(m.max_linear_acceleration, "max_linear_acceleration");
  requirePositive(m.max_angular_acceleration, "max_angular_acceleration");
  s.limits.max_linear_speed = m.max_linear_speed;
  s.limits.max_angular_speed = m.max_angular_speed;
  s.limits.max_linear_acceleration = m.max_linear_acceleration;
  s.limits.max_angular_acceleration = m.max_angular_acceleration;
  requirePositive(m.control_period, "control_period");
  s.control_period = m.control_period;
  if (m.laser_beams < 1 || m.laser_beams > kMaxBeams) {
    throw InvalidArgument("laser_beams", "expected 1 to " + std::to_string(kMaxBeams) + " beams, got " +
                                             std::to_string(m.laser_beams));
  }
  if (!std::isfinite(m.laser_angle_min) || !std::isfinite(m.laser_angle_increment)) {
    throw InvalidArgument("laser_angle_min", "expected finite beam angles");
  }
  requirePositive(m.laser_range_max, "laser_range_max");
  s.beams = LaserBeams::fan(static_cast<int>(m.laser_beams), m.laser_angle_min, m.laser_angle_increment,
                            m.laser_range_max, 0);
  s.seed = m.agent_seed;
  EpisodeStart cells;
  cells.width = s.frame.width;
  cells.height = s.frame.height;
  cells.prior_map = m.prior_map;
  decoded.prior_map = priorGrid(cells);
  s.prior_map = decoded.prior_map.get();
  return decoded;
}

void encodeSensing(std::vector<agents::ContinuousRequest>& requests, ppp_msgs::SensingBatch* m) {
  const std::size_t n = requests.size();
  m->starts.clear();
  m->episodes.resize(n);
  m->steps.resize(n);
  m->x.resize(n);
  m->y.resize(n);
  m->theta.resize(n);
  m->forward.resize(n);
  m->left.resize(n);
  m->turn.resize(n);
  m->time.resize(n);
  const std::size_t beams = n > 0 ? requests[0].ranges.size() : 0;
  m->laser_beams = static_cast<std::uint32_t>(beams);
  m->ranges.resize(n * beams);
  for (std::size_t i = 0; i < n; ++i) {
    const agents::ContinuousRequest& r = requests[i];
    if (r.start) m->starts.push_back(toStartMessage(r.episode, *r.start));
    m->episodes[i] = r.episode;
    m->steps[i] = static_cast<std::uint32_t>(r.step);
    m->x[i] = r.pose.x;
    m->y[i] = r.pose.y;
    m->theta[i] = r.pose.theta;
    m->forward[i] = r.velocity.forward;
    m->left[i] = r.velocity.left;
    m->turn[i] = r.velocity.turn;
    m->time[i] = r.time;
    std::copy(r.ranges.begin(), r.ranges.end(), m->ranges.begin() + static_cast<std::ptrdiff_t>(i * beams));
  }
}

std::string checkSensingBatch(const ppp_msgs::SensingBatch& b, std::string* what) {
  const std::size_t n = b.episodes.size();
  for (const std::size_t size : {b.steps.size(), b.x.size(), b.y.size(), b.theta.size(), b.forward.size(),
                                 b.left.size(), b.turn.size(), b.time.size()}) {
    if (size != n) {
      *what = "a SensingBatch whose per-episode arrays differ in length (" + std::to_string(n) + " episodes, an array of " +
              std::to_string(size) + ")";
      return "batch";
    }
  }
  if (b.ranges.size() != n * b.laser_beams) {
    *what = "a SensingBatch with " + std::to_string(b.ranges.size()) + " ranges for " + std::to_string(n) +
            " episodes of " + std::to_string(b.laser_beams) + " beams";
    return "ranges";
  }
  return "";
}

ppp_msgs::CommandBatch encodeCommands(const std::string& agent, std::uint32_t batch,
                                      const std::vector<agents::ContinuousReply>& replies) {
  ppp_msgs::CommandBatch m;
  m.agent = agent;
  m.batch = batch;
  const std::size_t n = replies.size();
  m.episodes.resize(n);
  m.steps.resize(n);
  m.forward.resize(n);
  m.left.resize(n);
  m.turn.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const agents::ContinuousReply& r = replies[i];
    m.episodes[i] = r.episode;
    m.steps[i] = static_cast<std::uint32_t>(r.step);
    m.forward[i] = r.command.forward;
    m.left[i] = r.command.left;
    m.turn[i] = r.command.turn;
    if (r.failure == nullptr) continue;
    ppp_msgs::EpisodeFailure failure;
    failure.episode = r.episode;
    failure.reason = r.failure;
    m.failures.push_back(failure);
  }
  return m;
}

DecodedCommands decodeCommands(const ppp_msgs::CommandBatch& m) {
  DecodedCommands decoded;
  const std::size_t n = m.episodes.size();
  if (m.steps.size() != n || m.forward.size() != n || m.left.size() != n || m.turn.size() != n) {
    decoded.missing_reason = reason::kInvalidCommand;
    decoded.fault = "a CommandBatch whose episodes, steps, forward, left and turn differ in length";
    return decoded;
  }
  decoded.replies.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    agents::ContinuousReply& r = decoded.replies[i];
    r.episode = m.episodes[i];
    r.step = static_cast<int>(m.steps[i]);
    r.command = BodyVelocity{m.forward[i], m.left[i], m.turn[i]};
  }
  for (const ppp_msgs::EpisodeFailure& f : m.failures) {
    const char* why = reason::agentReportedReason(f.reason);
    if (why == nullptr) {
      decoded.fault = "an episode given up for an unknown reason '" + f.reason + "': recorded as invalid_command";
      why = reason::kInvalidCommand;
    }
    for (agents::ContinuousReply& r : decoded.replies) {
      if (r.episode == f.episode) r.failure = why;
    }
  }
  return decoded;
}

}  // namespace protocol
}  // namespace ppp
