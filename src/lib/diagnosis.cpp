#include "ppp_core/diagnosis.hpp"

#include <algorithm>
#include <string>

#include "ppp_core/episode_reason.hpp"

namespace ppp {

int diagnosis::kindIndex(std::string_view text) {
  for (int i = 0; i < kKindCount; ++i) {
    if (text == kKinds[i]) return i;
  }
  return -1;
}

const char* diagnosis::kindNamed(std::string_view text) {
  const int index = kindIndex(text);
  return index < 0 ? nullptr : kKinds[index];
}

int finalWindow(int steps) { return std::max((steps + 3) / 4, std::min(steps, 4)); }

namespace {

/// The first step t of the loop's tail with states[t] == states[t + period] (a digest given), or -1.
int recurringState(const std::vector<std::uint64_t>& states, int start, int period) {
  for (int t = start; t + period < static_cast<int>(states.size()); ++t) {
    if (states[t] != 0 && states[t] == states[t + period]) return t;
  }
  return -1;
}

/// The last step at which the robot stood on a cell for the first time (0: the start).
int lastFirstVisit(const std::vector<Cell>& cells) {
  int min_x = cells[0].x, max_x = cells[0].x, min_y = cells[0].y, max_y = cells[0].y;
  for (const Cell& c : cells) {
    min_x = std::min(min_x, c.x);
    max_x = std::max(max_x, c.x);
    min_y = std::min(min_y, c.y);
    max_y = std::max(max_y, c.y);
  }
  const long width = static_cast<long>(max_x) - min_x + 1;
  const std::size_t words = static_cast<std::size_t>((width * (static_cast<long>(max_y) - min_y + 1) + 63) / 64);
  std::uint64_t small[64] = {};  // the box of a run on a map of up to 4,096 cells: no allocation
  std::vector<std::uint64_t> large(words <= 64 ? 0 : words, 0);
  std::uint64_t* visited = words <= 64 ? small : large.data();
  int last = 0;
  for (std::size_t t = 0; t < cells.size(); ++t) {
    const auto bit = static_cast<std::size_t>((cells[t].y - min_y) * width + (cells[t].x - min_x));
    const std::uint64_t mask = std::uint64_t{1} << (bit % 64);
    if ((visited[bit / 64] & mask) == 0) last = static_cast<int>(t);
    visited[bit / 64] |= mask;
  }
  return last;
}

}  // namespace

Diagnosis diagnoseTrajectory(const std::vector<Cell>& cells, const std::vector<std::uint64_t>& states) {
  Diagnosis d;
  const int last = static_cast<int>(cells.size()) - 1;  // the number of actions
  if (last < 1) {
    d.kind = diagnosis::kStuck;
    d.step = 0;
    return d;
  }
  const int window = finalWindow(last);
  int since = last;
  while (since > 0 && cells[since - 1] == cells[last]) --since;
  if (last - since >= window) {
    d.kind = diagnosis::kStuck;
    d.step = since;
    return d;
  }
  // The smallest period p >= 2 whose tail covers the final window and two whole cycles.
  for (int period = 2; 2 * period <= last; ++period) {
    if (cells[last - period] != cells[last]) continue;
    const int needed = std::max(window, 2 * period);
    bool periodic = true;
    for (int t = last; periodic && t >= last - needed + period; --t) periodic = cells[t] == cells[t - period];
    if (!periodic) continue;
    int start = last - needed;
    while (start > 0 && cells[start - 1] == cells[start - 1 + period]) --start;
    d.kind = diagnosis::kLoop;
    d.step = start;
    d.period = period;
    d.endless_step = recurringState(states, start, period);
    return d;
  }
  const int first_visit = lastFirstVisit(cells);
  if (first_visit <= last - window) {
    d.kind = diagnosis::kConfined;
    d.step = first_visit + 1;
  } else {
    d.kind = diagnosis::kWandering;
    d.step = first_visit;
  }
  return d;
}

Diagnosis diagnoseRun(bool passed, bool soft_failure, const std::string& reason, const std::vector<Cell>& cells,
                      const std::vector<std::uint64_t>& states, const char* reported_kind) {
  Diagnosis d;
  if (passed) {
    if (soft_failure) d.kind = diagnosis::kDetour;
    return d;
  }
  if (reason == reason::kBudgetExhausted || reason == reason::kActionLimit) return diagnoseTrajectory(cells, states);
  d.kind = reported_kind != nullptr ? reported_kind : diagnosis::kReported;
  return d;
}

std::vector<Cell> cycleCells(const Diagnosis& d, const std::vector<Cell>& cells) {
  std::vector<Cell> cycle;
  if (std::string(d.kind) != diagnosis::kLoop || d.step < 0 || d.step + d.period > static_cast<int>(cells.size())) {
    return cycle;
  }
  for (int t = d.step; t < d.step + d.period; ++t) {
    if (std::find(cycle.begin(), cycle.end(), cells[t]) == cycle.end()) cycle.push_back(cells[t]);
  }
  return cycle;
}

std::string describeDiagnosis(const Diagnosis& d, const std::string& reason, int cycle_cells) {
  const std::string kind = d.kind;
  const std::string step = std::to_string(d.step);
  if (kind == diagnosis::kLoop) {
    std::string text = "loop: from step " + step + " the robot repeats a cycle of " + std::to_string(d.period) +
                       " actions";
    if (cycle_cells > 0) text += " over " + std::to_string(cycle_cells) + (cycle_cells == 1 ? " cell" : " cells");
    text += " to the end, sensing nothing new";
    if (d.endless_step >= 0) {
      text += "; endless: the whole state at step " + std::to_string(d.endless_step) + " (the robot's cell, its map, "
              "the path it follows) recurred at step " + std::to_string(d.endless_step + d.period) +
              " and the agent answered it the same way, so an agent that is a function of its input never leaves "
              "the cycle";
    }
    return text;
  }
  if (kind == diagnosis::kStuck) return "stuck: the robot did not leave its cell from step " + step + " on";
  if (kind == diagnosis::kConfined) {
    return "confined: from step " + step + " on the robot stood only on cells it had stood on before (so it sensed "
           "nothing new), though not in a cycle";
  }
  if (kind == diagnosis::kWandering) {
    return "wandering: the robot still reached a cell it had never stood on at step " + step + ", late in the run: " +
           (reason == reason::kNoProgress ? "the progress timeout" : "the budget") + ", not a trap, ended it";
  }
  if (kind == diagnosis::kDetour) return "detour: it passed, on a path longer than the soft failure ratio allows";
  if (kind == diagnosis::kMissedRoute) {
    return "missed route: the planner answered no path while the map it was given had a route for the robot's "
           "body through cells not known to be obstacles";
  }
  if (kind == diagnosis::kNoRoute) {
    return "no route: the planner answered no path and the map it was given had none for the robot's body; what "
           "the robot knew was wrong";
  }
  if (kind == diagnosis::kReported) return "reported: the run ended as " + reason;
  return "";
}

Diagnosis diagnoseContinuousTrajectory(const std::vector<Cell>& cells) {
  const int last = static_cast<int>(cells.size()) - 1;  // control periods
  Diagnosis d = diagnoseTrajectory(cells);
  if (last < 1 || std::string(d.kind) == diagnosis::kStuck) return d;
  // The cells entered, each with the period it was entered at.
  std::vector<Cell> entered;
  std::vector<int> entered_at;
  for (int t = 0; t <= last; ++t) {
    if (t == 0 || cells[t] != cells[t - 1]) entered.push_back(cells[t]), entered_at.push_back(t);
  }
  const int final_start = last - finalWindow(last);  // the final window: periods after final_start
  const int n = static_cast<int>(entered.size()) - 1;
  // The first entry of the final window (the cell the robot stood on as it began counts).
  int window_entry = n;
  while (window_entry > 0 && entered_at[window_entry] > final_start) --window_entry;
  for (int period = 2; 2 * period <= n; ++period) {
    const int needed = std::max(n - window_entry, 2 * period);
    if (needed > n) break;
    bool periodic = true;
    for (int i = n; periodic && i >= n - needed + period; --i) periodic = entered[i] == entered[i - period];
    if (!periodic) continue;
    int start = n - needed;
    while (start > 0 && entered[start - 1] == entered[start - 1 + period]) --start;
    d = Diagnosis{};
    d.kind = diagnosis::kLoop;
    d.step = entered_at[start];
    d.period = period;
    return d;
  }
  if (std::string(d.kind) == diagnosis::kLoop) {  // periodic in time but not as cells entered: judge it again
    const int first_visit = lastFirstVisit(cells);
    d = Diagnosis{};
    d.kind = first_visit <= final_start ? diagnosis::kConfined : diagnosis::kWandering;
    d.step = first_visit <= final_start ? first_visit + 1 : first_visit;
  }
  return d;
}

Diagnosis diagnoseContinuousRun(bool passed, bool soft_failure, const std::string& reason,
                                const std::vector<Cell>& cells) {
  if (!passed && (reason == reason::kBudgetExhausted || reason == reason::kNoProgress)) {
    return diagnoseContinuousTrajectory(cells);
  }
  return diagnoseRun(passed, soft_failure, reason, cells);
}

}  // namespace ppp
