#include "ppp_simulator/results_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/text_file.hpp"

namespace ppp {
namespace simulator {

namespace {

constexpr std::size_t kMaxResultsBytes = std::size_t{8} << 30;

std::string headerLine() { return csvLine(resultCsvHeader()); }

/// Parses complete lines; returns the byte length of the text that holds them (a partial tail is excluded).
std::size_t parseRows(const std::string& text, const std::string& path, std::vector<EpisodeResult>* rows) {
  std::size_t pos = 0;
  int line = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) break;  // half-written last line: dropped
    const std::string content = text.substr(pos, end - pos);
    ++line;
    if (line == 1) {
      if (content != headerLine()) {
        throw ParseError(path, 1, "header", "not a PPP Lab results file; expected '" + headerLine() + "'");
      }
    } else if (!content.empty()) {
      rows->push_back(fromCsvFields(splitCsvLine(content, path, line), path, line));
    }
    pos = end + 1;
  }
  return pos;
}

}  // namespace

RunKey runKey(const EpisodeResult& row) { return RunKey{row.set, row.problem, row.agent, row.run}; }

bool isLostRun(const EpisodeResult& row) { return row.reason == reason::kTimeout || row.reason == reason::kAgentLost; }

std::vector<EpisodeResult> standingRows(std::vector<EpisodeResult> rows) {
  if (std::none_of(rows.begin(), rows.end(), isLostRun)) return rows;  // no run was played twice
  std::set<RunKey> seen;
  std::vector<bool> stands(rows.size());
  for (std::size_t i = rows.size(); i-- > 0;) stands[i] = seen.insert(runKey(rows[i])).second;
  std::vector<EpisodeResult> standing;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (stands[i]) standing.push_back(std::move(rows[i]));
  }
  return standing;
}

std::vector<EpisodeResult> readResultsFile(const std::string& path) {
  std::vector<EpisodeResult> rows;
  parseRows(readTextFile(path, kMaxResultsBytes), path, &rows);
  return rows;
}

ResultsFile::ResultsFile(const std::string& path) : path_(path) {
  namespace fs = std::filesystem;
  if (fs::exists(path)) {
    const std::string text = readTextFile(path, kMaxResultsBytes);
    const std::size_t complete = parseRows(text, path, &existing_);
    if (complete < text.size()) fs::resize_file(path, complete);
    for (const EpisodeResult& r : existing_) {  // a run's last row decides, as in standingRows
      const RunKey key = runKey(r);
      (isLostRun(r) ? lost_ : done_).insert(key);
      (isLostRun(r) ? done_ : lost_).erase(key);
    }
  }
  out_.open(path, std::ios::app);
  if (!out_) throw IoError(path, std::string("cannot write: ") + std::strerror(errno));
  if (existing_.empty() && fs::file_size(path) == 0) {
    out_ << headerLine() << '\n';
    out_.flush();
  }
}

void ResultsFile::append(const std::vector<EpisodeResult>& rows) {
  std::string block;
  for (const EpisodeResult& r : rows) block += csvLine(toCsvFields(r)) + '\n';
  std::lock_guard<std::mutex> lock(mutex_);
  out_ << block;
  out_.flush();
  if (!out_) throw IoError(path_, "write failed");
}

void ResultsFile::rewrite(const std::vector<EpisodeResult>& rows) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::string text = headerLine() + '\n';
  for (const EpisodeResult& r : rows) text += csvLine(toCsvFields(r)) + '\n';
  out_.close();
  writeFileAtomically(path_, text);
  out_.open(path_, std::ios::app);
}

}  // namespace simulator
}  // namespace ppp
