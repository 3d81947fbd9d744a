#include "ppp_simulator/planner_moves.hpp"

#include <filesystem>
#include <map>

#include "ppp_core/csv.hpp"
#include "ppp_core/error.hpp"
#include "ppp_core/stop.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_simulator/results_file.hpp"

namespace ppp {
namespace simulator {

namespace {

/// Largest planner moves file read (a planner run is one episode at a time: far fewer rows than results.csv).
constexpr std::size_t kMaxMovesBytes = std::size_t{1} << 30;

/// The actions of a moves field. @throws ParseError naming `path`, `line` and the field.
std::vector<Action> actionsOf(const std::string& field, const std::string& path, int line) {
  std::vector<Action> actions;
  actions.reserve(field.size());
  for (const char c : field) {
    if (c < '0' || c > '8') {
      throw ParseError(path, line, "moves", std::string("expected action digits 0 to 8, got '") + c + "'");
    }
    actions.push_back(static_cast<Action>(c - '0'));
  }
  return actions;
}

}  // namespace

const std::string& plannerMovesHeader() {
  static const std::string header = "set,problem,agent,run,moves";
  return header;
}

std::string plannerMovesLine(const agents::EpisodeResult& row) {
  std::string moves;
  moves.reserve(row.actions.size());
  for (const Action a : row.actions) moves.push_back(static_cast<char>('0' + static_cast<int>(a)));
  return csvLine({row.set, row.problem, row.agent, std::to_string(row.run), moves}) + '\n';
}

void attachPlannerMoves(const std::string& path, std::vector<agents::EpisodeResult>* rows, const StopCheck& stop) {
  if (!std::filesystem::exists(path)) return;
  const std::string text = readTextFile(path, kMaxMovesBytes, stop);
  std::map<RunKey, std::vector<Action>> moves;
  std::size_t pos = 0;
  int line = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) break;  // half-written last line
    const std::string content = text.substr(pos, end - pos);
    pos = end + 1;
    ++line;
    if (line == 1) {
      if (content != plannerMovesHeader()) {
        throw ParseError(path, 1, "header", "expected '" + plannerMovesHeader() + "'");
      }
      continue;
    }
    const std::vector<std::string> fields = agents::splitCsvLine(content, path, line);
    if (fields.size() != 5) {
      throw ParseError(path, line, "moves", "expected 5 fields, got " + std::to_string(fields.size()));
    }
    int run = 0;
    try {
      std::size_t used = 0;
      run = std::stoi(fields[3], &used);
      if (used != fields[3].size() || run < 0) throw std::invalid_argument("run");
    } catch (const std::exception&) {
      throw ParseError(path, line, "run", "expected a run number, got '" + fields[3] + "'");
    }
    moves[RunKey{fields[0], fields[1], fields[2], run}] = actionsOf(fields[4], path, line);
  }
  for (agents::EpisodeResult& row : *rows) {
    const auto it = moves.find(runKey(row));
    if (it != moves.end() && static_cast<int>(it->second.size()) == row.steps) row.actions = it->second;
  }
}

void writePlannerMoves(const std::string& path, const std::vector<agents::EpisodeResult>& rows, const StopCheck& stop) {
  std::string text = plannerMovesHeader() + '\n';
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i % 4096 == 0) stopIfAsked(stop);
    if (!rows[i].actions.empty()) text += plannerMovesLine(rows[i]);
  }
  writeFileAtomically(path, text);
}

}  // namespace simulator
}  // namespace ppp
