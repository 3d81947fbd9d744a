#include "ppp_simulator/results_file.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_simulator/planner_moves.hpp"

namespace ppp {
namespace simulator {

namespace {

constexpr std::size_t kMaxResultsBytes = std::size_t{8} << 30;

std::string headerLine() { return csvLine(agents::resultCsvHeader()); }

/// The header of results files written before runs were diagnosed.
constexpr std::string_view kUndiagnosedHeader =
    "set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason,soft_failure";

/// The header of results files written before failed runs had signatures.
constexpr std::string_view kUnsignedHeader =
    "set,problem,agent,run,seed,pass,steps,bumps,path_length,optimal_length,reason,soft_failure,diagnosis,"
    "diagnosis_step,loop_period,endless_step";

constexpr int kLinesPerStopCheck = 1 << 14;  // lines read or written between two questions to the StopCheck

/// Parses complete lines, asking `stop` every kLinesPerStopCheck lines; returns the byte length of the text
/// that holds them (a partial tail is excluded).
std::size_t parseRows(const std::string& text, const std::string& path, std::vector<agents::EpisodeResult>* rows,
                      const StopCheck& stop = {}) {
  rows->reserve(rows->size() + text.size() / 80);  // rows are about 90 bytes long: one allocation, not a series
  std::size_t pos = 0;
  int line = 0;
  while (pos < text.size()) {
    if (line % kLinesPerStopCheck == 0) stopIfAsked(stop);
    const std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) break;  // half-written last line: dropped
    const std::string_view content = std::string_view(text).substr(pos, end - pos);
    ++line;
    if (line == 1) {
      if (content == kUndiagnosedHeader) {
        throw ParseError(path, 1, "header",
                         "written by an earlier PPP Lab, without the diagnosis columns; its runs cannot be resumed "
                         "or read with diagnosed ones: write the experiment to a new output directory (or move "
                         "this results.csv away to play every run again)");
      }
      if (content == kUnsignedHeader) {
        throw ParseError(path, 1, "header",
                         "written by an earlier PPP Lab, without the signature column; its runs cannot be resumed "
                         "or read with signed ones: write the experiment to a new output directory (or move this "
                         "results.csv away to play every run again)");
      }
      if (content != headerLine()) {
        throw ParseError(path, 1, "header", "not a PPP Lab results file; expected '" + headerLine() + "'");
      }
    } else if (!content.empty()) {
      rows->push_back(agents::parseCsvRow(content, path, line));
    }
    pos = end + 1;
  }
  return pos;
}

}  // namespace

RunKey runKey(const agents::EpisodeResult& row) { return RunKey{row.set, row.problem, row.agent, row.run}; }

bool isLostReason(const std::string& reason) { return reason == reason::kTimeout || reason == reason::kAgentLost; }

bool isLostRun(const agents::EpisodeResult& row) { return isLostReason(row.reason); }

bool leavesAgentUnreachable(const std::string& reason) {
  return isLostReason(reason) || reason == reason::kPlannerLost;
}

std::vector<agents::EpisodeResult> standingRows(std::vector<agents::EpisodeResult> rows) {
  if (std::none_of(rows.begin(), rows.end(), isLostRun)) return rows;  // no run was played twice
  std::set<RunKey> seen;
  std::vector<bool> stands(rows.size());
  for (std::size_t i = rows.size(); i-- > 0;) stands[i] = seen.insert(runKey(rows[i])).second;
  std::vector<agents::EpisodeResult> standing;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (stands[i]) standing.push_back(std::move(rows[i]));
  }
  return standing;
}

FailedRunSeeds failedRunSeeds(const std::vector<agents::EpisodeResult>& rows, const std::string& agent, int most) {
  std::vector<const agents::EpisodeResult*> failed;
  for (const agents::EpisodeResult& r : rows) {
    if (r.agent == agent && !r.passed && !leavesAgentUnreachable(r.reason)) failed.push_back(&r);
  }
  std::stable_sort(failed.begin(), failed.end(), [](const auto* a, const auto* b) { return a->run < b->run; });
  FailedRunSeeds seeds;
  for (const agents::EpisodeResult* r : failed) {
    std::vector<std::uint64_t>& list = seeds[{r->set, r->problem}];
    if (static_cast<int>(list.size()) < most) list.push_back(r->seed);
  }
  return seeds;
}

std::vector<agents::EpisodeResult> readResultsFile(const std::string& path, const StopCheck& stop) {
  return parseResultsCsv(readTextFile(path, kMaxResultsBytes, stop), path, stop);
}

std::vector<agents::EpisodeResult> parseResultsCsv(const std::string& text, const std::string& path, const StopCheck& stop) {
  std::vector<agents::EpisodeResult> rows;
  parseRows(text, path, &rows, stop);
  return rows;
}

ResultsFile::ResultsFile(const std::string& path, const StopCheck& stop) : path_(path) {
  namespace fs = std::filesystem;
  if (fs::exists(path)) {
    const std::string text = readTextFile(path, kMaxResultsBytes, stop);
    const std::size_t complete = parseRows(text, path, &existing_, stop);
    for (std::size_t i = 0; i < existing_.size(); ++i) {  // a run's last row decides, as in standingRows
      if (i % kLinesPerStopCheck == 0) stopIfAsked(stop);
      const agents::EpisodeResult& r = existing_[i];
      const RunKey key = runKey(r);
      (isLostRun(r) ? lost_ : done_).insert(key);
      (isLostRun(r) ? done_ : lost_).erase(key);
    }
    if (complete < text.size()) fs::resize_file(path, complete);  // only once the reading can no longer stop
  }
  out_ = std::make_unique<AppendFile>(path, false);
  if (existing_.empty() && out_->size() == 0) out_->append(headerLine() + '\n');
}

void ResultsFile::append(const std::vector<agents::EpisodeResult>& rows) {
  std::string block;
  std::string moves;
  for (const agents::EpisodeResult& r : rows) {
    agents::appendCsvRow(r, &block);
    if (!r.actions.empty()) moves += plannerMovesLine(r);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (!moves.empty()) {
    // The moves first: a run whose row is written has its moves on file.
    if (moves_out_ == nullptr) {
      const std::string path = (std::filesystem::path(path_).parent_path() / kPlannerMovesFile).string();
      moves_out_ = std::make_unique<AppendFile>(path, false);
      if (moves_out_->size() == 0) moves_out_->append(plannerMovesHeader() + '\n');
    }
    moves_out_->append(moves);
  }
  out_->append(block);
}

void ResultsFile::rewrite(const std::vector<agents::EpisodeResult>& rows, const StopCheck& stop) {
  constexpr std::size_t kBlockBytes = std::size_t{4} << 20;  // written a block at a time: no copy of the whole file
  std::lock_guard<std::mutex> lock(mutex_);
  AtomicFile file(path_);
  std::string block = headerLine() + '\n';
  block.reserve(kBlockBytes + 1024);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i % kLinesPerStopCheck == 0) stopIfAsked(stop);
    agents::appendCsvRow(rows[i], &block);
    if (block.size() >= kBlockBytes) {
      file.write(block);
      block.clear();
    }
  }
  file.write(block);
  file.commit();
  out_ = std::make_unique<AppendFile>(path_, false);
}

void OrderedAppender::add(std::size_t number, std::vector<agents::EpisodeResult> rows) {
  std::lock_guard<std::mutex> lock(mutex_);
  waiting_.emplace(number, std::move(rows));
  while (!waiting_.empty() && waiting_.begin()->first == next_) {
    file_->append(waiting_.begin()->second);
    waiting_.erase(waiting_.begin());
    ++next_;
  }
}

void OrderedAppender::flush() {
  std::lock_guard<std::mutex> lock(mutex_);
  while (!waiting_.empty()) {
    file_->append(waiting_.begin()->second);
    next_ = waiting_.begin()->first + 1;
    waiting_.erase(waiting_.begin());
  }
}

}  // namespace simulator
}  // namespace ppp
