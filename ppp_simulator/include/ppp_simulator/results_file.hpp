#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "ppp_core/append_file.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_agents/episode_result.hpp"

namespace ppp {
namespace simulator {

/// Identity of one run: (set, problem, agent, run).
using RunKey = std::tuple<std::string, std::string, std::string, int>;

/// The identity of a row's run.
RunKey runKey(const agents::EpisodeResult& row);

/// Whether a row records a run lost to the simulator <-> agent link rather than played out: the agent process did
/// not answer in time (timeout) or went away (agent_lost), as when a node crashes or a network link is cut. Such a
/// row says nothing about the agent, so a resume plays the run again and its new row supersedes this one.
bool isLostRun(const agents::EpisodeResult& row);

/// Whether `reason` is a lost run's (isLostRun()): timeout or agent_lost.
bool isLostReason(const std::string& reason);

/// Whether a run ending for `reason` leaves the agent unable to play on: a lost run's, or planner_lost (a planner
/// that went away stays away). A shrink through ROS cannot judge candidates after one.
bool leavesAgentUnreachable(const std::string& reason);

/// The rows of `rows` that stand, in their order: of several rows of one run (a lost run played again), the last.
std::vector<agents::EpisodeResult> standingRows(std::vector<agents::EpisodeResult> rows);

/// The seeds of failed runs, per (set, PPP).
using FailedRunSeeds = std::map<std::pair<std::string, std::string>, std::vector<std::uint64_t>>;

/// The seeds of `agent`'s failed runs in `rows`, in run order, at most `most` per PPP; runs that left the agent
/// unreachable (leavesAgentUnreachable()) are left out: they cannot be played again.
FailedRunSeeds failedRunSeeds(const std::vector<agents::EpisodeResult>& rows, const std::string& agent, int most);

/// results.csv of an experiment, appended to as runs finish (each batch written whole, or not at all when the
/// disk is full), so that nothing written is lost when the process dies; reopening it resumes: the rows already
/// there are kept, a half-written last line (the process died mid-write) is cut off, and lost runs (isLostRun)
/// are left to play again.
class ResultsFile {
 public:
  /// Opens or creates `path`, asking `stop` while it reads the rows already there (the file is then as before).
  /// @throws IoError, ParseError (a header or row that is not ours), Interrupted.
  explicit ResultsFile(const std::string& path, const StopCheck& stop = {});
  /// The rows present when the file was opened.
  const std::vector<agents::EpisodeResult>& existing() const { return existing_; }
  /// Keys of the runs present when the file was opened, lost runs excepted.
  const std::set<RunKey>& done() const { return done_; }
  /// How many runs present when the file was opened were lost (and are not done).
  std::size_t lostRuns() const { return lost_.size(); }
  /// Appends rows in one write, and the actions of those that carry any (planner runs) to planner_moves.csv
  /// beside the file (planner_moves.hpp); safe to call from several threads. @throws IoError naming the file and
  /// the system's reason (the file is then as before the call).
  void append(const std::vector<agents::EpisodeResult>& rows);
  /// Rewrites the file atomically with `rows` in the given order, asking `stop` as it goes (the file is then
  /// as before). @throws IoError, Interrupted.
  void rewrite(const std::vector<agents::EpisodeResult>& rows, const StopCheck& stop = {});

 private:
  std::string path_;
  std::vector<agents::EpisodeResult> existing_;
  std::set<RunKey> done_;
  std::set<RunKey> lost_;
  std::mutex mutex_;
  std::unique_ptr<AppendFile> out_;
  std::unique_ptr<AppendFile> moves_out_;  // opened at the first row with actions
};

/// Reads every row of a results.csv, asking `stop` as it goes. @throws IoError, ParseError, Interrupted.
std::vector<agents::EpisodeResult> readResultsFile(const std::string& path, const StopCheck& stop = {});

/// readResultsFile() on text: the rows of results.csv text read from `path` (named in errors); a half-written
/// last line is left out. @throws ParseError, Interrupted.
std::vector<agents::EpisodeResult> parseResultsCsv(const std::string& text, const std::string& path,
                                           const StopCheck& stop = {});

/// Appends numbered blocks of rows (0, 1, 2, ...) to a ResultsFile in number order, whatever order they are
/// finished in: a block waits in memory while a lower-numbered one is still being played, so workers that take
/// their blocks in canonical order leave the file in canonical order. Safe to call from several threads.
class OrderedAppender {
 public:
  /// Appends to `file`, which must outlive this appender.
  explicit OrderedAppender(ResultsFile* file) : file_(file) {}
  /// Block `number` is finished: it is written, with every waiting block after it, once no lower number is
  /// missing. @throws IoError (see ResultsFile::append).
  void add(std::size_t number, std::vector<agents::EpisodeResult> rows);
  /// Writes every waiting block now, in number order (when the work stops before every block is finished).
  /// @throws IoError.
  void flush();

 private:
  ResultsFile* file_;
  std::mutex mutex_;
  std::size_t next_ = 0;                                      // the lowest number not written yet
  std::map<std::size_t, std::vector<agents::EpisodeResult>> waiting_;  // finished blocks above it
};

}  // namespace simulator
}  // namespace ppp
