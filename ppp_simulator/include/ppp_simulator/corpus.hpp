#pragma once

#include <string>

#include "ppp_core/problem.hpp"

namespace ppp {
namespace simulator {

/// Where a PPP went when added to a corpus.
struct CorpusAddition {
  std::string file;    ///< The file holding it: the one written, or the corpus's PPP of the same shape.
  bool added = false;  ///< False when the corpus had a PPP of the same obstacle shape already.
};

/// Adds `problem` (a shrunk failure, typically) to the corpus directory `dir`, created when missing, as
/// `trap_HASH.ppp` (HASH: 16 hex digits of its obstacleShape()), unless one of the corpus's PPPs has the same
/// obstacle shape: moved, mirrored or rotated, it is the same trap, and the corpus keeps the first.
/// @throws IoError when `dir` is a set (it has a set.csv, which would not list the new file) or cannot be
/// written; ParseError for a corpus file that cannot be read.
CorpusAddition addToCorpus(const std::string& dir, const Problem& problem);

}  // namespace simulator
}  // namespace ppp
