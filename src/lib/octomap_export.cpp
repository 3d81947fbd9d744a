#include "ppp_core/octomap_export.hpp"

#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "ppp_core/error.hpp"
#include "ppp_core/map_frame.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {

namespace {

/// Whole voxel layers covering [0, height]; a hair of tolerance keeps 1.0 / 0.1 from becoming 11 layers.
long long layerCount(const OctomapOptions& options) {
  return static_cast<long long>(std::ceil(options.height / options.resolution - 1e-9));
}

}  // namespace

void OctomapOptions::validate() const {
  if (!std::isfinite(resolution) || resolution <= 0.0) {
    throw InvalidArgument("resolution", "expected metres per cell > 0, got " + formatShortest(resolution));
  }
  if (!std::isfinite(height) || height <= 0.0) {
    throw InvalidArgument("height", "expected an extrusion height in metres > 0, got " + formatShortest(height));
  }
  // OctoMap keys are 16 bits centred on the origin: coordinates must stay below 32768 voxels.
  if (height / resolution > kMaxOctomapLayers) {
    throw InvalidArgument("height", "height " + formatShortest(height) + " m is more than " +
                                        std::to_string(kMaxOctomapLayers) + " voxels of " + formatShortest(resolution) +
                                        " m, beyond the reach of OctoMap keys");
  }
}

void writeOctomap(const Problem& problem, const std::string& bt_path, const OctomapOptions& options) {
  options.validate();
  validateProblem(problem);
  const long long layers = std::max(1LL, layerCount(options));
  const long long voxels = static_cast<long long>(problem.width) * problem.height * layers;
  if (voxels > kMaxOctomapVoxels) {
    throw InvalidArgument("height", "a " + std::to_string(problem.width) + "x" + std::to_string(problem.height) +
                                        " grid " + std::to_string(layers) + " voxels high makes " +
                                        std::to_string(voxels) + " voxels; the limit is " +
                                        std::to_string(kMaxOctomapVoxels));
  }
  const Grid grid = decodeGrid(problem);
  const MapFrame frame{problem.width, problem.height, options.resolution};
  octomap::OcTree tree(options.resolution);
  const float occupied = tree.getClampingThresMaxLog();
  const float free = tree.getClampingThresMinLog();
  for (int y = 0; y < problem.height; ++y) {
    for (int x = 0; x < problem.width; ++x) {
      const Cell c{x, y};
      const float value = grid.isObstacle(c) ? occupied : free;
      for (long long k = 0; k < layers; ++k) {
        const double z = (static_cast<double>(k) + 0.5) * options.resolution;
        tree.setNodeValue(frame.centreX(c), frame.centreY(c), z, value, true);
      }
    }
  }
  tree.updateInnerOccupancy();
  tree.prune();
  std::ostringstream out;
  if (!tree.writeBinary(out)) throw IoError(bt_path, "OctoMap could not serialise the tree");
  writeFileAtomically(bt_path, out.str());
}

}  // namespace ppp
