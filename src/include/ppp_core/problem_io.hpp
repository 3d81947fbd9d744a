#pragma once

#include <string>
#include <vector>

#include "ppp_core/map_yaml.hpp"
#include "ppp_core/octomap_export.hpp"
#include "ppp_core/picture.hpp"
#include "ppp_core/problem.hpp"

namespace ppp {

/// Everything the file writers can be told, whatever the format.
struct ProblemWriteOptions {
  MapYamlOptions map;          ///< For .yaml (+ .pgm).
  PictureOptions picture;      ///< For .png.
  std::vector<Cell> path;      ///< For .png: a route drawn over the map (may be empty).
  OctomapOptions octomap;      ///< For .bt.
};

/// Reads a problem from a `.ppp`, map_server `.yaml` or MovingAI `.map` file, chosen by extension.
/// @throws InvalidArgument for another extension; IoError, ParseError from the readers.
Problem readProblemFile(const std::string& path, const MapImportOptions& map_options = {});

/// Writes a problem as `.ppp`, `.yaml` (+ `.pgm`), `.png`, `.bt` (OctoMap) or `.map` (MovingAI), chosen by extension.
/// @throws InvalidArgument for another extension or bad options; IoError from the writers.
void writeProblemFile(const Problem& problem, const std::string& path, const ProblemWriteOptions& options = {});

/// The lower-case extension of a path including the dot (".ppp"), or "" when there is none.
std::string fileExtension(const std::string& path);

}  // namespace ppp
