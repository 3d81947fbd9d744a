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

/// The identity of a row's run.
RunKey runKey(const EpisodeResult& row);

/// Whether a row records a run lost to the simulator <-> agent link rather than played out: the agent process did
/// not answer in time (timeout) or went away (agent_lost), as when a node crashes or a network link is cut. Such a
/// row says nothing about the agent, so a resume plays the run again and its new row supersedes this one.
bool isLostRun(const EpisodeResult& row);

/// The rows of `rows` that stand, in their order: of several rows of one run (a lost run played again), the last.
std::vector<EpisodeResult> standingRows(std::vector<EpisodeResult> rows);

/// results.csv of an experiment, appended to as runs finish (each batch flushed at once), so that nothing
/// written is lost when the process dies; reopening it resumes: the rows already there are kept, a
/// half-written last line (the process died mid-write) is cut off, and lost runs (isLostRun) are left to play
/// again.
class ResultsFile {
 public:
  /// Opens or creates `path`. @throws IoError, ParseError (a header or row that is not ours).
  explicit ResultsFile(const std::string& path);
  /// The rows present when the file was opened.
  const std::vector<EpisodeResult>& existing() const { return existing_; }
  /// Keys of the runs present when the file was opened, lost runs excepted.
  const std::set<RunKey>& done() const { return done_; }
  /// How many runs present when the file was opened were lost (and are not done).
  std::size_t lostRuns() const { return lost_.size(); }
  /// Appends rows and flushes; safe to call from several threads. @throws IoError.
  void append(const std::vector<EpisodeResult>& rows);
  /// Rewrites the file atomically with `rows` in the given order. @throws IoError.
  void rewrite(const std::vector<EpisodeResult>& rows);

 private:
  std::string path_;
  std::vector<EpisodeResult> existing_;
  std::set<RunKey> done_;
  std::set<RunKey> lost_;
  std::mutex mutex_;
  std::ofstream out_;
};

/// Reads every row of a results.csv. @throws IoError, ParseError.
std::vector<EpisodeResult> readResultsFile(const std::string& path);

}  // namespace simulator
}  // namespace ppp
