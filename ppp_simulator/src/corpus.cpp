#include "ppp_simulator/corpus.hpp"

#include <filesystem>

#include "ppp_core/error.hpp"
#include "ppp_core/obstacle_shape.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/problem_io.hpp"
#include "ppp_core/rng.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_generator/problem_set.hpp"

namespace ppp {
namespace simulator {

namespace fs = std::filesystem;

namespace {

std::string trapNameOfShape(const std::string& shape) { return "trap_" + formatHex64(nameHash(shape)); }

}  // namespace

std::string trapName(const Problem& problem) { return trapNameOfShape(obstacleShape(decodeGrid(problem))); }

Corpus::Corpus(std::string dir) : dir_(std::move(dir)) {
  std::error_code error;
  if (!fs::exists(dir_, error)) return;
  if (!fs::is_directory(dir_, error)) throw IoError(dir_, "is not a directory; expected a corpus of PPP files");
  if (generator::hasProblemSet(dir_)) {
    throw IoError(dir_, "is a set (it has a set.csv, which would not list a PPP added to it); give a corpus: a "
                        "directory of PPP files without one");
  }
  for (const std::string& file : generator::problemFilesIn(dir_)) {
    files_.emplace(obstacleShape(decodeGrid(readProblemFile(file))), file);
    names_.insert(fs::path(file).stem().string());
  }
}

CorpusAddition Corpus::add(const Problem& problem) {
  const std::string shape = obstacleShape(decodeGrid(problem));
  const auto found = files_.find(shape);
  if (found != files_.end()) return CorpusAddition{found->second, false};
  const std::string trap = trapNameOfShape(shape);
  std::string name = trap;
  for (int k = 2; names_.count(name) > 0; ++k) name = trap + "_" + std::to_string(k);
  std::error_code error;
  if (!fs::create_directories(dir_, error) && error) throw IoError(dir_, "cannot create it: " + error.message());
  const std::string file = (fs::path(dir_) / (name + ".ppp")).string();
  writePppFile(problem, file);
  files_.emplace(shape, file);
  names_.insert(name);
  return CorpusAddition{file, true};
}

}  // namespace simulator
}  // namespace ppp
