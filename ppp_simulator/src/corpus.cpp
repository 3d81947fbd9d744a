#include "ppp_simulator/corpus.hpp"

#include <cstdio>
#include <filesystem>

#include "ppp_core/error.hpp"
#include "ppp_core/obstacle_shape.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_generator/problem_set.hpp"

namespace ppp {
namespace simulator {

namespace fs = std::filesystem;

CorpusAddition addToCorpus(const std::string& dir, const Problem& problem) {
  std::error_code error;
  if (generator::hasProblemSet(dir)) {
    throw IoError(dir, "is a set (it has a set.csv, which would not list a PPP added to it); give a corpus: a "
                       "directory of PPP files without one");
  }
  if (!fs::create_directories(dir, error) && error) throw IoError(dir, "cannot create it: " + error.message());
  const std::string shape = obstacleShape(decodeGrid(problem));
  if (!fs::is_empty(dir, error)) {
    std::vector<std::string> files;
    try {
      files = generator::problemSetFiles(dir);
    } catch (const IoError&) {
      files.clear();  // a directory of other files only: no PPP yet
    }
    for (const std::string& file : files) {
      if (obstacleShape(decodeGrid(readProblemFile(file))) == shape) return CorpusAddition{file, false};
    }
  }
  char name[32];
  std::snprintf(name, sizeof name, "trap_%016llx.ppp", static_cast<unsigned long long>(nameHash(shape)));
  const std::string file = (fs::path(dir) / name).string();
  writePppFile(problem, file);
  return CorpusAddition{file, true};
}

}  // namespace simulator
}  // namespace ppp
