#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ppp_core/kinematics.hpp"
#include "ppp_core/picture.hpp"
#include "ppp_core/problem.hpp"

namespace ppp {

/// The pixel of the map-frame point (x, y) metres in a picture of a `rows`-row problem at `resolution` metres per
/// cell drawn with `options`.
Pixel mapPixel(double x, double y, int rows, double resolution, const PictureOptions& options);

/// Draws a continuous run (ContinuousOutcome::poses) over its problem as row-major RGB bytes, sized and coloured as
/// renderProblemRgb(): the robot centre's trajectory as a blue curve, and the robot at its last pose as a disc
/// outline of `radius` metres (at least a few pixels) with a line from its centre along its heading.
/// @throws InvalidArgument as renderProblemRgb(), or naming "poses" when there is none.
std::vector<std::uint8_t> renderTrajectoryRgb(const Problem& problem, const std::vector<Pose2D>& poses,
                                              double resolution, double radius, const PictureOptions& options = {});

/// renderTrajectoryRgb() written as a PNG file, atomically. @throws as renderTrajectoryRgb(), IoError.
void writeTrajectoryPng(const Problem& problem, const std::vector<Pose2D>& poses, double resolution, double radius,
                        const std::string& png_path, const PictureOptions& options = {});

}  // namespace ppp
