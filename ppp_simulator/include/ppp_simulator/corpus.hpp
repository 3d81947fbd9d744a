#pragma once

#include <map>
#include <set>
#include <string>

#include "ppp_core/problem.hpp"

namespace ppp {
namespace simulator {

/// The name of `problem`'s trap: "trap_" and 16 hex digits of its obstacle shape (obstacleShape()), the same for
/// every PPP whose obstacles are its own moved, mirrored or rotated.
std::string trapName(const Problem& problem);

/// Where a PPP went when added to a corpus.
struct CorpusAddition {
  std::string file;    ///< The file holding it: the one written, or the corpus's PPP of the same shape.
  bool added = false;  ///< False when the corpus had a PPP of the same obstacle shape already.
};

/// A corpus directory that PPPs (shrunk failures, typically) are added to, one per obstacle shape: a PPP whose
/// obstacles are those of one of the corpus's PPPs moved, mirrored or rotated (obstacleShape()) is the same trap,
/// and the corpus keeps the first.
class Corpus {
 public:
  /// Reads the shapes of the PPPs in `dir` (none when it does not exist yet: the first addition makes it).
  /// @throws IoError when `dir` is not a directory or is a set (its set.csv would not list a PPP added to it);
  /// ParseError for a PPP file of it that cannot be read.
  explicit Corpus(std::string dir);
  /// Adds `problem` as `trapName().ppp` (`_2`, `_3`, ... after the name when a file of that name is there
  /// already), unless the corpus holds its shape. @throws IoError when it cannot be
  /// written.
  CorpusAddition add(const Problem& problem);

 private:
  std::string dir_;
  std::map<std::string, std::string> files_;  // obstacle shape -> the corpus's file of it
  std::set<std::string> names_;               // the file names (without extension) taken
};

}  // namespace simulator
}  // namespace ppp
