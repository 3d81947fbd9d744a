#include "ppp_generator/set_csv.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/evaluation.hpp"

namespace ppp {
namespace generator {

namespace {

constexpr std::size_t kShownNameBytes = 60;  // of a bad file name in an error

/// A file name for an error message: quoted, control bytes as \xNN, cut after kShownNameBytes.
std::string shownName(const std::string& name) {
  std::string shown;
  for (std::size_t i = 0; i < name.size() && i < kShownNameBytes; ++i) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    if (c >= 0x20 && c != 0x7f) {
      shown.push_back(static_cast<char>(c));
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      shown += hex;
    }
  }
  return "'" + shown + (name.size() > kShownNameBytes ? "...'" : "'");
}

/// Whether `name` is a .ppp file directly in the set's directory, as writeProblemSetDirectory names them.
bool isPppFileName(const std::string& name) {
  const std::string extension = ".ppp";
  if (name.size() <= extension.size() || name.compare(name.size() - extension.size(), extension.size(), extension)) {
    return false;
  }
  for (unsigned char c : name) {
    if (c < 0x20 || c == 0x7f || c == '/' || c == '\\' || c == '"') return false;
  }
  return true;
}

}  // namespace

std::vector<std::string> setCsvHeader() {
  std::vector<std::string> header{"id", "file", "fitness", "fitness_value"};
  for (const std::string& name : characterNames()) header.push_back(name);
  header.push_back("nearest_difference");
  return header;
}

std::vector<std::string> parseSetCsv(const std::string& text, const std::string& csv_path) {
  std::vector<std::string> before_diversity = setCsvHeader();
  before_diversity.pop_back();  // sets written before nearest_difference existed are read too
  const std::size_t header_end = std::min(text.find('\n'), text.size());
  const std::string header = text.substr(0, header_end);
  if (header != csvLine(setCsvHeader()) && header != csvLine(before_diversity)) {
    throw ParseError(csv_path, 1, "header", "not a PPP set file (expected the header written by ppp generate)");
  }
  std::vector<std::string> files;
  std::map<std::string, int> listed_at;  // file name -> its line
  int line_number = 1;
  for (std::size_t pos = header_end + 1; pos < text.size();) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    if (line.empty()) continue;
    const auto comma = line.find(',');
    const auto second = comma == std::string::npos ? comma : line.find(',', comma + 1);
    if (second == std::string::npos) throw ParseError(csv_path, line_number, "file", "expected id,file,...");
    const std::string file = line.substr(comma + 1, second - comma - 1);
    if (!isPppFileName(file)) {
      throw ParseError(csv_path, line_number, "file",
                       shownName(file) + " is not a .ppp file name in the set's directory");
    }
    const auto [at, added] = listed_at.emplace(file, line_number);
    if (!added) {
      throw ParseError(csv_path, line_number, "file",
                       shownName(file) + " is listed twice (first on line " + std::to_string(at->second) + ")");
    }
    files.push_back(file);
  }
  if (files.empty()) throw ParseError(csv_path, line_number, "set", "lists no PPPs");
  return files;
}

}  // namespace generator
}  // namespace ppp
