#include "ppp_simulator/report/continuous_animation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "ppp_agents/continuous/continuous_runner.hpp"
#include "ppp_core/canvas.hpp"
#include "ppp_core/gif_animation.hpp"
#include "ppp_core/laser.hpp"
#include "ppp_core/reachability.hpp"
#include "ppp_core/square_world.hpp"
#include "ppp_core/trajectory_picture.hpp"

namespace ppp {
namespace simulator {

namespace {

/// Palette indices of a frame.
enum Ink : std::uint8_t { kGridLineInk, kFreeInk, kObstacleInk, kStartInk, kGoalInk, kTrailInk, kRobotInk, kBeamInk,
                          kBeamHitInk };

const std::vector<Rgb> kPalette = {kGridLineColour, kFreeColour, kObstacleColour, kStartColour,    kGoalColour,
                                   kPathColour,     kAgentColour, kBeamColour,    kBeamHitColour};

/// Every how many beams one is drawn as a line.
constexpr int kBeamLineEvery = 6;

}  // namespace

ContinuousAnimation animateContinuousRun(const Problem& problem, const Grid& grid, const agents::AgentConfig& config,
                                         const EpisodeOptions& options, std::uint64_t run_seed,
                                         const AnimationOptions& animation, const StopCheck& stop) {
  animation.validate();
  agents::ContinuousRunner runner(config, options);
  return drawContinuousRun(problem, grid, options,
                           runner.run(problem, grid, fewestMoves(grid, problem.start, problem.goal, Connectivity::Four),
                                      run_seed, true),
                           animation, stop);
}

ContinuousAnimation animateRecordedContinuousRun(const Problem& problem, const Grid& grid,
                                                 const agents::AgentConfig& config, const EpisodeOptions& options,
                                                 std::uint64_t run_seed, const std::vector<BodyVelocity>& commands,
                                                 const std::string& end_reason, const AnimationOptions& animation,
                                                 const StopCheck& stop) {
  animation.validate();
  return drawContinuousRun(
      problem, grid, options,
      agents::recordedContinuousRun(problem, grid, options,
                                    fewestMoves(grid, problem.start, problem.goal, Connectivity::Four), run_seed,
                                    commands, end_reason, config.name),
      animation, stop);
}

ContinuousAnimation drawContinuousRun(const Problem& problem, const Grid& grid, const EpisodeOptions& options,
                                      ContinuousOutcome outcome, const AnimationOptions& animation,
                                      const StopCheck& stop) {
  animation.validate();
  const PictureOptions picture{animationCellPixels(problem, animation), true};
  ContinuousAnimation result;
  result.outcome = std::move(outcome);
  const std::vector<Pose2D>& poses = result.outcome.poses;
  const int steps = result.outcome.steps;
  result.stride = std::max(1, (steps + animation.max_frames - 2) / (animation.max_frames - 1));

  const double resolution = options.motion.resolution;
  const double radius = options.robot_radius * resolution;
  const SquareWorld world(grid, resolution);
  LaserBeams beams = LaserBeams::of(options.motion);
  beams.noise = 0;
  const auto pixel = [&](double x, double y) { return mapPixel(x, y, problem.height, resolution, picture); };
  const int width = pictureWidth(problem.width, picture), height = pictureHeight(problem.height, picture);
  Canvas<std::uint8_t> base(width, height, kGridLineInk);
  for (int y = 0; y < problem.height; ++y) {
    for (int x = 0; x < problem.width; ++x) base.fillCell(Cell{x, y}, grid.isObstacle(Cell{x, y}) ? kObstacleInk : kFreeInk, picture);
  }
  base.fillCell(problem.start, kStartInk, picture);
  base.fillCell(problem.goal, kGoalInk, picture);

  GifAnimation gif(width, height, kPalette);
  const int thickness = std::max(1, picture.cell_pixels / 8);
  const double drawn_radius = std::max(radius, 2.5 * resolution / picture.cell_pixels);
  std::vector<float> ranges;
  for (int t = 0;; t = std::min(t + result.stride, steps)) {
    stopIfAsked(stop);
    Canvas<std::uint8_t> frame = base;
    const Pose2D& pose = poses[t];
    scanLaser(world, pose, beams, nullptr, &ranges);
    for (int i = 0; i < beams.count; ++i) {
      const double angle = pose.theta + beams.angle_min + i * beams.angle_increment;
      const double reach = std::isfinite(ranges[i]) ? ranges[i] : beams.range_max;
      const Pixel end = pixel(pose.x + reach * std::cos(angle), pose.y + reach * std::sin(angle));
      if (i % kBeamLineEvery == 0) frame.line(pixel(pose.x, pose.y), end, 1, kBeamInk);
      if (std::isfinite(ranges[i])) frame.disc(end, 0, kBeamHitInk);
    }
    for (int k = 0; k < t; ++k) {  // the trajectory so far, over the beams
      frame.line(pixel(poses[k].x, poses[k].y), pixel(poses[k + 1].x, poses[k + 1].y), thickness, kTrailInk);
    }
    constexpr int kOutlineSteps = 48;
    constexpr double kTurn = 2 * 3.14159265358979323846;
    for (int k = 0; k < kOutlineSteps; ++k) {
      const double a = kTurn * k / kOutlineSteps, b = kTurn * (k + 1) / kOutlineSteps;
      frame.line(pixel(pose.x + drawn_radius * std::cos(a), pose.y + drawn_radius * std::sin(a)),
                 pixel(pose.x + drawn_radius * std::cos(b), pose.y + drawn_radius * std::sin(b)), 1, kRobotInk);
    }
    frame.line(pixel(pose.x, pose.y),
               pixel(pose.x + drawn_radius * std::cos(pose.theta), pose.y + drawn_radius * std::sin(pose.theta)),
               thickness, kRobotInk);
    const bool last = t == steps;
    gif.addFrame(frame.pixels(), (last ? animation.last_frame_ms : animation.frame_ms) / 10);
    if (last) break;
  }
  result.frames = gif.frames();
  result.gif = gif.encode();
  return result;
}

}  // namespace simulator
}  // namespace ppp
