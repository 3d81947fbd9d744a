#pragma once

#include <string>

#include "ppp_core/problem.hpp"

namespace ppp {

/// Most voxels writeOctomap() will create (cells × layers), checked before building the tree.
constexpr long long kMaxOctomapVoxels = 1LL << 24;
/// Most voxel layers an extrusion may have (OctoMap keys reach 32768 voxels from the origin).
constexpr int kMaxOctomapLayers = 32768;

/// How a problem is extruded into a 3D OctoMap.
struct OctomapOptions {
  double resolution = 1.0;  ///< Metres per cell, which is also the octree's voxel size; finite and > 0.
  double height = 1.0;      ///< Height of the extrusion in metres, rounded up to whole voxels; finite and > 0.

  /// Checks the options. @throws InvalidArgument naming the option.
  void validate() const;
};

/// Writes a problem as an OctoMap binary tree (`.bt`) in the ROS `map` frame (via MapFrame: y up, origin at
/// the bottom-left corner of the grid, z up from the floor at 0). Every obstacle cell becomes a column of
/// occupied voxels from z = 0 to `height`, every free cell (start and goal included) a column of free voxels,
/// so free space is known rather than unknown; nothing exists above `height`.
/// @throws InvalidArgument for an invalid problem or options (or too many voxels), IoError naming `bt_path`
/// when it cannot be written.
void writeOctomap(const Problem& problem, const std::string& bt_path, const OctomapOptions& options = {});

}  // namespace ppp
