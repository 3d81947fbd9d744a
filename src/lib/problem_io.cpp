#include "ppp_core/problem_io.hpp"

#include <algorithm>
#include <cctype>

#include "ppp_core/error.hpp"
#include "ppp_core/movingai_map.hpp"
#include "ppp_core/ppp_file.hpp"

namespace ppp {

std::string fileExtension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string extension = path.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

Problem readProblemFile(const std::string& path, const MapImportOptions& map_options) {
  const std::string extension = fileExtension(path);
  if (extension == ".ppp") return readPppFile(path);
  if (extension == ".yaml" || extension == ".yml") return readMapYaml(path, map_options);
  if (extension == ".map") return readMovingAiMap(path, map_options);
  throw InvalidArgument(path,
                        "cannot read '" + extension + "' files; expected .ppp, .yaml (map_server) or .map (MovingAI)");
}

void writeProblemFile(const Problem& problem, const std::string& path, const ProblemWriteOptions& options) {
  const std::string extension = fileExtension(path);
  if (extension == ".ppp") {
    writePppFile(problem, path);
  } else if (extension == ".yaml" || extension == ".yml") {
    writeMapYaml(problem, path, options.map);
  } else if (extension == ".png") {
    writeProblemPng(problem, options.path, path, options.picture);
  } else if (extension == ".bt") {
    writeOctomap(problem, path, options.octomap);
  } else if (extension == ".map") {
    writeMovingAiMap(problem, path);
  } else {
    throw InvalidArgument(path, "cannot write '" + extension + "' files; expected .ppp, .yaml, .png, .bt or .map");
  }
}

}  // namespace ppp
