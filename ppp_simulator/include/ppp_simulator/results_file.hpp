#pragma once

#include <fstream>
#include <mutex>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "ppp_simulator/episode_result.hpp"

namespace ppp {
namespace simulator {

/// Identity of one run: (set, problem, agent, run).
using RunKey = std::tuple<std::string, std::string, std::string, int>;

/// results.csv of an experiment, appended to as runs finish (each batch flushed at once), so that nothing
/// written is lost when the process dies; reopening it resumes: the rows already there are kept and a
/// half-written last line (the process died mid-write) is cut off.
class ResultsFile {
 public:
  /// Opens or creates `path`. @throws IoError, ParseError (a header or row that is not ours).
  explicit ResultsFile(const std::string& path);
  /// The rows present when the file was opened.
  const std::vector<EpisodeResult>& existing() const { return existing_; }
  /// Keys of the rows present when the file was opened.
  const std::set<RunKey>& done() const { return done_; }
  /// Appends rows and flushes; safe to call from several threads. @throws IoError.
  void append(const std::vector<EpisodeResult>& rows);
  /// Rewrites the file atomically with `rows` in the given order. @throws IoError.
  void rewrite(const std::vector<EpisodeResult>& rows);

 private:
  std::string path_;
  std::vector<EpisodeResult> existing_;
  std::set<RunKey> done_;
  std::mutex mutex_;
  std::ofstream out_;
};

/// Reads every row of a results.csv. @throws IoError, ParseError.
std::vector<EpisodeResult> readResultsFile(const std::string& path);

}  // namespace simulator
}  // namespace ppp
