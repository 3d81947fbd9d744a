#include "ppp_simulator/results_file.hpp"

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
    for (const EpisodeResult& r : existing_) done_.insert(RunKey{r.set, r.problem, r.agent, r.run});
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
