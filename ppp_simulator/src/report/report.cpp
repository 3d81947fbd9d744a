#include "ppp_simulator/report/report.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <system_error>

#include "ppp_core/error.hpp"
#include "ppp_core/gif_animation.hpp"
#include "ppp_core/picture.hpp"
#include "ppp_core/ppp_file.hpp"
#include "ppp_core/text_file.hpp"
#include "ppp_core/text_format.hpp"
#include "ppp_core/trajectory_picture.hpp"
#include "ppp_generator/tree_html.hpp"
#include "ppp_agents/agent_config.hpp"
#include "ppp_agents/episode_result.hpp"
#include "ppp_simulator/report/statistics.hpp"
#include "ppp_simulator/report/svg_plot.hpp"

namespace ppp {
namespace simulator {

namespace {

constexpr double kSignificance = 0.05;
constexpr int kPictureTargetPixels = 480;  // longer side of a failure picture, roughly

// ---------------------------------------------------------------------------------------------------------
// Numbers, independent of the C locale.

/// A rate in [0, 1] as a percentage with two decimals: 0.755 → "75.50%".
std::string percent(double rate) { return formatFixed(rate * 100, 2) + "%"; }

std::string pValue(double p) { return p < 0.0001 ? "< 0.0001" : formatFixed(p, 4); }

std::string uValue(double u) { return std::floor(u) == u ? formatFixed(u, 0) : formatFixed(u, 1); }

/// "n" or "lo–hi".
std::string range(int lo, int hi) {
  return lo == hi ? std::to_string(lo) : std::to_string(lo) + "\xE2\x80\x93" + std::to_string(hi);
}

// ---------------------------------------------------------------------------------------------------------
// Markdown and shell quoting.

/// Free text in Markdown: backslash-escapes the characters that could start markup; line breaks become spaces.
std::string mdText(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n' || c == '\r') {
      out += ' ';
    } else {
      if (std::string("\\`*_[]<>#|!~&").find(c) != std::string::npos) out += '\\';
      out += c;
    }
  }
  return out;
}

/// A name as a Markdown code span (fence longer than any backtick run inside); `in_table` escapes '|'.
std::string mdCode(const std::string& text, bool in_table) {
  std::string body;
  std::size_t run = 0;
  std::size_t longest = 0;
  for (const char c : text) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
    if (c == '\n' || c == '\r') {
      body += ' ';
    } else if (c == '|' && in_table) {
      body += "\\|";
    } else {
      body += c;
    }
  }
  const std::string fence(longest + 1, '`');
  const bool pad = !body.empty() && (body.front() == '`' || body.back() == '`');
  return fence + (pad ? " " : "") + body + (pad ? " " : "") + fence;
}

/// A fenced code block holding `text` verbatim.
std::string mdFence(const std::string& text, const std::string& info) {
  std::size_t run = 0;
  std::size_t longest = 0;
  for (const char c : text) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  const std::string fence(std::max<std::size_t>(3, longest + 1), '`');
  std::string body = text;
  if (!body.empty() && body.back() != '\n') body += '\n';
  return fence + info + "\n" + body + fence + "\n";
}

// ---------------------------------------------------------------------------------------------------------
// File names.

/// Keeps letters, digits, '.', '-' and '_'; everything else becomes '_'. Never empty, never starts with '.'.
std::string safeStem(const std::string& name) {
  std::string stem;
  for (const char c : name) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '-' || c == '_';
    stem += keep ? c : '_';
  }
  if (stem.empty() || stem.front() == '.') stem.insert(stem.begin(), '_');
  return stem;
}

/// Hands out distinct file names within one directory of the report.
class FileNames {
 public:
  /// `stem` + `extension`, or with "-2", "-3"… appended to the stem when that name is taken.
  std::string claim(const std::string& stem, const std::string& extension) {
    std::string name = stem + extension;
    for (int k = 2; !used_.insert(name).second; ++k) name = stem + "-" + std::to_string(k) + extension;
    return name;
  }

 private:
  std::set<std::string> used_;
};

// ---------------------------------------------------------------------------------------------------------
// What the report is made of, prepared before anything is written.

struct Plot {
  std::string file;        // relative to the report directory
  std::string caption;     // plain text
  std::string file_svg;    // standalone document
  std::string inline_svg;  // for the HTML
};

struct Picture {
  std::string png_file;  // relative to the report directory
  std::string gif_file;  // the animation beside it, relative to the report directory; empty without one
  int gif_width = 0;     // its size, from the GIF's header
  int gif_height = 0;
  std::string ppp_file;  // relative to the report directory
  std::string png;       // PNG bytes
  int width = 0;
  int height = 0;
  std::string shrunk_png_file;  // the shrunk PPP's picture, animation and file (FailureExample::shrunk), else empty
  std::string shrunk_gif_file;
  std::string shrunk_ppp_file;
  std::string shrunk_png;
  int shrunk_width = 0;
  int shrunk_height = 0;
};

struct SetSummary {
  int problems = 0;       // distinct PPPs with any result
  int min_runs = 0;       // per PPP and agent
  int max_runs = 0;
  long long runs = 0;     // all agents
};

std::vector<std::string> problemsOf(const PassRateTable& rates, const std::string& set) {
  std::vector<std::string> problems;
  for (const ProblemPassRate& row : rates.per_problem) {
    if (row.set == set && (problems.empty() || problems.back() != row.problem)) problems.push_back(row.problem);
  }
  return problems;  // per_problem is sorted by set, then problem: no repeats
}

SetSummary summarise(const PassRateTable& rates, const std::string& set) {
  SetSummary summary;
  summary.problems = static_cast<int>(problemsOf(rates, set).size());
  summary.min_runs = std::numeric_limits<int>::max();
  for (const ProblemPassRate& row : rates.per_problem) {
    if (row.set != set) continue;
    summary.min_runs = std::min(summary.min_runs, row.runs);
    summary.max_runs = std::max(summary.max_runs, row.runs);
    summary.runs += row.runs;
  }
  if (summary.problems == 0) summary.min_runs = 0;
  return summary;
}

std::vector<Plot> makePlots(const PassRateTable& rates) {
  std::vector<Plot> plots;
  const double missing = std::numeric_limits<double>::quiet_NaN();

  Chart by_agent;
  by_agent.title = "Mean pass rate per agent and PPP set";
  by_agent.x_label = "agent";
  by_agent.y_label = "mean pass rate over the set's PPPs (%)";
  by_agent.categories = rates.agents;
  for (const std::string& set : rates.sets) {
    PlotSeries series{set, {}};
    for (const std::string& agent : rates.agents) {
      const SetPassRate* row = rates.find(set, agent);
      series.values.push_back(row != nullptr ? row->mean_rate * 100 : missing);
    }
    by_agent.series.push_back(std::move(series));
  }
  plots.push_back(Plot{"plots/pass_rate_by_agent.svg",
                       "Mean pass rate (%) of every agent on every PPP set: one bar per set.",
                       groupedBarChartSvg(by_agent, true), groupedBarChartSvg(by_agent, false)});

  FileNames names;
  names.claim("pass_rate_by_agent", ".svg");
  for (const std::string& set : rates.sets) {
    Chart by_ppp;
    by_ppp.title = "Pass rate per PPP of set " + set;
    by_ppp.x_label = "PPP (column number; the id is in the tooltip)";
    by_ppp.y_label = "pass rate over the runs (%)";
    by_ppp.categories = problemsOf(rates, set);
    std::map<std::string, std::size_t> column;
    for (std::size_t c = 0; c < by_ppp.categories.size(); ++c) column[by_ppp.categories[c]] = c;
    for (const std::string& agent : rates.agents) {
      PlotSeries series{agent, std::vector<double>(by_ppp.categories.size(), missing)};
      for (const ProblemPassRate& row : rates.per_problem) {
        if (row.set == set && row.agent == agent) series.values[column.at(row.problem)] = row.rate() * 100;
      }
      by_ppp.series.push_back(std::move(series));
    }
    plots.push_back(Plot{"plots/" + names.claim("pass_rate_by_ppp_" + safeStem(set), ".svg"),
                         "Pass rate (%) of every agent (rows) on each PPP (columns, fittest first) of set " + set +
                             ": red cells are PPPs the agent fails, blue ones it passes; hover for the figures.",
                         heatMapSvg(by_ppp, true), heatMapSvg(by_ppp, false)});
  }
  return plots;
}

/// The box plot of path / optimal per agent (categories) and set (series), when any run passed.
std::vector<Plot> detourPlots(const PassRateTable& rates, const std::vector<DetourStats>& detours) {
  if (detours.empty()) return {};
  const double missing = std::numeric_limits<double>::quiet_NaN();
  Chart chart;
  chart.title = "Path length / optimal length of the passed runs";
  chart.x_label = "agent";
  chart.y_label = "path / optimal";
  chart.value_suffix = "";
  chart.categories = rates.agents;
  std::vector<std::vector<BoxStats>> boxes;
  double top = 1;
  for (const std::string& set : rates.sets) {
    chart.series.push_back(PlotSeries{set, std::vector<double>(rates.agents.size(), missing)});
    boxes.emplace_back(rates.agents.size(), BoxStats{missing, missing, missing, missing, missing});
    for (std::size_t a = 0; a < rates.agents.size(); ++a) {
      for (const DetourStats& d : detours) {
        if (d.set != set || d.agent != rates.agents[a]) continue;
        boxes.back()[a] = d.spread;
        top = std::max(top, d.spread.p95);
      }
    }
  }
  chart.y_max = std::ceil(top * 1.1 * 2) / 2;
  return {Plot{"plots/path_ratio.svg",
               "Path length / optimal length of every agent's passed runs on every set: the box spans the middle "
               "half of the runs with the median across it, the whiskers the 5th to the 95th percentile.",
               boxPlotSvg(chart, boxes, true), boxPlotSvg(chart, boxes, false)}};
}

PictureOptions pictureOptions(const Problem& problem) {
  PictureOptions options;
  const int side = std::max({problem.width, problem.height, 1});
  options.cell_pixels = std::clamp(kPictureTargetPixels / side, 2, 40);
  options.grid_lines = options.cell_pixels >= 6;
  return options;
}

/// The picture of a run: its trajectory in continuous motion, else its cells (the cycle's pink).
std::vector<std::uint8_t> runRgb(const Problem& ppp, const std::vector<Cell>& path, const std::vector<Cell>& cycle,
                                 const std::optional<DrivenRun>& driven, const PictureOptions& options) {
  if (driven) return renderTrajectoryRgb(ppp, driven->poses, driven->resolution, driven->radius, options);
  return renderProblemRgb(ppp, path, options, cycle);
}

std::vector<Picture> makePictures(const std::vector<FailureExample>& failures, const StopCheck& stop) {
  std::vector<Picture> pictures;
  FileNames png_names;
  FileNames ppp_names;
  std::map<std::pair<std::string, std::string>, std::pair<std::string, Problem>> ppp_files;  // (set, problem)
  for (std::size_t i = 0; i < failures.size(); ++i) {
    stopIfAsked(stop);
    const FailureExample& failure = failures[i];
    Picture picture;
    try {
      const PictureOptions options = pictureOptions(failure.ppp);
      const std::vector<std::uint8_t> rgb = runRgb(failure.ppp, failure.path, failure.cycle, failure.driven, options);
      picture.width = pictureWidth(failure.ppp.width, options);
      picture.height = pictureHeight(failure.ppp.height, options);
      picture.png = encodePng(rgb, picture.width, picture.height);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument("failures", "example " + std::to_string(i) + " (" + failure.set + " / " +
                                            failure.problem + " / " + failure.agent + "): " + e.what());
    }
    picture.png_file = "pictures/" + png_names.claim(safeStem(failure.set) + "_" + safeStem(failure.problem) + "_" +
                                                         safeStem(failure.agent),
                                                     ".png");
    const auto key = std::make_pair(failure.set, failure.problem);
    const auto known = ppp_files.find(key);
    if (known != ppp_files.end() && known->second.second == failure.ppp) {
      picture.ppp_file = known->second.first;
    } else {
      picture.ppp_file =
          "ppps/" + ppp_names.claim(safeStem(failure.set) + "_" + safeStem(failure.problem), ".ppp");
      if (known == ppp_files.end()) ppp_files.emplace(key, std::make_pair(picture.ppp_file, failure.ppp));
    }
    if (failure.shrunk) {
      const ShrunkExample& shrunk = *failure.shrunk;
      const PictureOptions options = pictureOptions(shrunk.ppp);
      picture.shrunk_png = encodePng(runRgb(shrunk.ppp, shrunk.path, shrunk.cycle, shrunk.driven, options),
                                     pictureWidth(shrunk.ppp.width, options), pictureHeight(shrunk.ppp.height, options));
      picture.shrunk_width = pictureWidth(shrunk.ppp.width, options);
      picture.shrunk_height = pictureHeight(shrunk.ppp.height, options);
      picture.shrunk_png_file = picture.png_file.substr(0, picture.png_file.size() - 4) + "_shrunk.png";
      if (!shrunk.animation_gif.empty()) {
        picture.shrunk_gif_file = picture.shrunk_png_file.substr(0, picture.shrunk_png_file.size() - 4) + ".gif";
      }
      picture.shrunk_ppp_file = "ppps/" + ppp_names.claim(safeStem(failure.set) + "_" + safeStem(failure.problem) + "_" +
                                                              safeStem(failure.agent) + "_shrunk",
                                                          ".ppp");
    }
    if (!failure.animation_gif.empty()) {
      if (!gifScreenSize(failure.animation_gif, &picture.gif_width, &picture.gif_height)) {
        throw InvalidArgument("failures", "example " + std::to_string(i) + " (" + failure.set + " / " +
                                              failure.problem + " / " + failure.agent + "): its animation is not a GIF");
      }
      picture.gif_file = picture.png_file.substr(0, picture.png_file.size() - 4) + ".gif";
    }
    pictures.push_back(std::move(picture));
  }
  return pictures;
}

std::string reasonText(const std::string& reason) {
  if (reason == reason::kGoalReached) return "the agent reached the goal";
  if (reason == reason::kBudgetExhausted) return "the move budget ran out before the agent reached the goal";
  if (reason == reason::kActionLimit) {
    return "the agent took the most actions an episode allows while stays or bumps are free";
  }
  if (reason == reason::kTimeout) return "the agent did not answer in time";
  if (reason == reason::kAgentLost) return "the agent process went away";
  if (reason == reason::kInvalidAction) return "the agent sent an unusable action";
  if (reason == reason::kCollision) return "the planner drove the robot's body into an obstacle";
  if (reason == reason::kNoPath) return "the planner found no path";
  if (reason == reason::kInvalidPath) return "the planner's path was unusable";
  if (reason == reason::kInvalidCommand) return "the planner's velocity command was unusable";
  if (reason == reason::kPlannerTimeout) return "the planner did not answer in time";
  if (reason == reason::kPlannerLost) return "the planner's process went away";
  if (reason == reason::kPlannerAborted) return "the planner gave up on the goal";
  if (reason == reason::kNoProgress) return "the robot stayed in one place for the progress timeout";
  return "";
}

std::string pathText(const FailureExample& failure) {
  if (failure.driven && !failure.driven->poses.empty()) {
    const Pose2D& end = failure.driven->poses.back();
    return std::to_string(failure.driven->poses.size() - 1) + " control periods, " +
           formatFixed(failure.driven->distance, 2) + " m driven, ending at (" + formatFixed(end.x, 2) + ", " +
           formatFixed(end.y, 2) + ") m in the map frame, in cell " + cellText(failure.path.back());
  }
  if (failure.path.empty()) return "no path recorded";
  std::size_t moves = 0;
  for (std::size_t i = 1; i < failure.path.size(); ++i) {
    if (failure.path[i] != failure.path[i - 1]) ++moves;
  }
  std::string text = std::to_string(failure.path.size()) + " cells in order (" + std::to_string(moves) +
                     (moves == 1 ? " move" : " moves") + "), ending at " + cellText(failure.path.back());
  if (failure.path.back() == failure.ppp.goal) text += ", the goal";
  return text;
}

/// What the animations beside the pictures show, when any of `examples` has one; else "".
std::string animationGuide(const std::vector<FailureExample>& examples) {
  const bool animated = std::any_of(examples.begin(), examples.end(),
                                    [](const FailureExample& f) { return !f.animation_gif.empty(); });
  const bool driven = std::any_of(examples.begin(), examples.end(), [](const FailureExample& f) { return f.driven; });
  std::string guide =
      driven ? " A run in continuous motion is drawn as the robot centre's trajectory, with the robot's disc and a "
               "line along its heading at its last pose."
             : "";
  if (!animated) return guide;
  return guide +
         " Beside a picture, the same run step by step (where the map is small enough to animate): the agent as "
         "an orange disc, its scan window outlined in gold with the free cells it sees yellow, cells it has not "
         "sensed or has forgotten shaded, and a magenta mark on the side of a cell for every bump (replay with "
         "-o run.gif)" +
         (driven ? "; in continuous motion, the robot with its heading among its laser's beams (where each meets a "
                   "square, red)."
                 : ".");
}

/// How to play `failure`'s run again on the PPP in `ppp_file` (its own, or its shrunk one).
/// The shrink of the PPP in `ppp_file` through ROS for `failure`'s planner on the run's seed: it plays the run again
/// and says whether it still fails so.
std::string shrinkLaunchCommand(const FailureExample& failure, const std::string& ppp_file) {
  return "roslaunch launch/shrink.launch input:=" + shellWord(ppp_file) + " agent:=" + shellWord(failure.agent) +
         " output:=check.ppp config:=EXPERIMENT.yaml args:=\"--seed " + std::to_string(failure.seed) + "\"";
}

std::string replayCommand(const FailureExample& failure, const std::string& ppp_file) {
  if (failure.recorded && failure.driven) return shrinkLaunchCommand(failure, ppp_file);
  if (failure.recorded) return "its moves: planner_moves.csv, run " + std::to_string(failure.run);
  const std::string flags = failure.replay_flags.empty() ? "--agent " + shellWord(failure.agent) : failure.replay_flags;
  return agents::replayCommand(ppp_file, flags, failure.seed);
}

/// How to play `failure`'s run again on its shrunk PPP in `ppp_file`: ppp replay, or for a planner (which plays only
/// through ROS) the shrink of that PPP through ROS on the run's seed, which says whether it still fails so.
std::string shrunkReplayCommand(const FailureExample& failure, const std::string& ppp_file) {
  if (!failure.recorded) return replayCommand(failure, ppp_file);
  return shrinkLaunchCommand(failure, ppp_file);
}

std::string readingGuide(const ReportInput& input) {
  std::string guide =
      "Every agent ran many times, each run with its own seed, on every PPP (path-planning problem) of every set. "
      "A PPP's pass rate is the share of its runs in which the agent reached the goal within the move budget; "
      "a set's pass rate is the mean of its PPPs' pass rates (each PPP weighs the same, whatever its number of "
      "runs). Low pass rates point at faults: the PPP plots show which PPPs an agent fails on. The Mann\xE2\x80\x93"
      "Whitney U test compares, per agent, the per-PPP pass rates of two sets: p below 0.05 says the agent "
      "finds one set harder than the other, and z > 0 means higher pass rates on the first set.";
  if (!input.control.empty()) {
    guide += " The " + input.control + " agent knows the map and is the control: it should pass every valid PPP.";
  }
  guide +=
      " The hardest PPPs are shown with a failed run's path (blue; start green, goal red, obstacles grey) and "
      "the agent, run and seed that replay it.";
  return guide;
}

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:20px auto;max-width:1150px;padding:0 16px;color:#222;background:#fff;"
    "line-height:1.4}"
    "h1{font-size:24px;margin:0 0 8px}h2{font-size:19px;margin:28px 0 8px;border-bottom:1px solid #ddd;"
    "padding-bottom:3px}h3{font-size:16px;margin:18px 0 6px}"
    "p{margin:0 0 10px}p.guide{color:#444;max-width:900px}"
    "table{border-collapse:collapse;margin:6px 0 12px;font-size:14px}"
    "th,td{border:1px solid #ccc;padding:4px 10px}th{background:#f3f3f3;text-align:left}"
    "td.num,th.num{text-align:right;font-variant-numeric:tabular-nums}"
    "tr.foot td{background:#fafafa;color:#555}"
    "td.sig{font-weight:bold;color:#a11}"
    "code{font-family:monospace;font-size:13px;background:#f4f4f4;padding:0 3px;border-radius:3px}"
    "pre{background:#f6f6f6;border:1px solid #ddd;padding:10px;overflow-x:auto;font-size:13px}"
    "pre code{padding:0;background:none}"
    "figure{margin:10px 0 18px}figcaption{color:#555;font-size:13px;margin-top:4px}"
    "svg{max-width:100%;height:auto}"
    ".failure{display:flex;gap:18px;align-items:flex-start;flex-wrap:wrap;margin-bottom:16px}"
    ".failure img{image-rendering:pixelated;border:1px solid #999;max-width:100%;height:auto}"
    ".failure ul{margin:0;padding-left:18px;flex:1 1 360px}.failure li{margin-bottom:4px}"
    ".muted{color:#777}";

/// A faint red behind low pass rates, so failures stand out in the table.
std::string rateCellStyle(double rate) {
  const double alpha = 0.45 * (1 - std::clamp(rate, 0.0, 1.0));
  return "background:rgba(225,87,89," + formatFixed(alpha, 2) + ")";
}

// ---------------------------------------------------------------------------------------------------------
// Sections, each as Markdown and HTML.

struct Text {
  std::string md;
  std::string html;
};

/// Opens a report section: its heading, then `intro` as a paragraph.
void openSection(const std::string& title, const std::string& intro, Text* out) {
  out->md += "## " + title + "\n\n" + mdText(intro) + "\n\n";
  out->html += "<h2>" + escapeMarkup(title) + "</h2>\n<p>" + escapeMarkup(intro) + "</p>\n";
}

/// One cell of an agent x set table: its text, and for the HTML its pass-rate shading and tooltip.
struct TableCell {
  bool present = false;  ///< False: the agent has no results on the set (drawn as a dash).
  std::string text;      ///< What the cell says.
  double shade_rate = 1; ///< Pass rate whose shade the HTML cell gets (rateCellStyle).
  std::string title;     ///< HTML tooltip (may be empty).
};

/// Opens an agent x set table and writes its rows (rows: agents, columns: sets), leaving the HTML table open
/// for a footer: the caller closes it with "</tbody>" or a "<tfoot>".
void agentSetTable(const PassRateTable& rates, const std::string& html_class,
                   const std::function<TableCell(const std::string& set, const std::string& agent)>& cell,
                   Text* out) {
  out->md += "| Agent |";
  std::string align = "|:---|";
  out->html += "<table" + (html_class.empty() ? std::string() : " class=\"" + html_class + "\"") +
               ">\n<thead><tr><th>Agent</th>";
  for (const std::string& set : rates.sets) {
    out->md += " " + mdCode(set, true) + " |";
    align += "---:|";
    out->html += "<th class=\"num\"><code>" + escapeMarkup(set) + "</code></th>";
  }
  out->md += "\n" + align + "\n";
  out->html += "</tr></thead>\n<tbody>\n";
  for (const std::string& agent : rates.agents) {
    out->md += "| " + mdCode(agent, true) + " |";
    out->html += "<tr><td><code>" + escapeMarkup(agent) + "</code></td>";
    for (const std::string& set : rates.sets) {
      const TableCell c = cell(set, agent);
      if (!c.present) {
        out->md += " \xE2\x80\x94 |";
        out->html += "<td class=\"num muted\">\xE2\x80\x94</td>";
        continue;
      }
      out->md += " " + c.text + " |";
      out->html += "<td class=\"num\" style=\"" + rateCellStyle(c.shade_rate) + "\"" +
                   (c.title.empty() ? std::string() : " title=\"" + escapeMarkup(c.title) + "\"") + ">" +
                   escapeMarkup(c.text) + "</td>";
    }
    out->md += "\n";
    out->html += "</tr>\n";
  }
}

void passRateSection(const ReportInput& input, Text* out) {
  const PassRateTable& rates = input.rates;
  openSection("Pass rates",
              "Mean pass rate over each set's PPPs (rows: agents, columns: PPP sets); \xE2\x80\x94 marks an agent "
              "without results on a set.",
              out);

  agentSetTable(rates, "rates", [&](const std::string& set, const std::string& agent) {
    const SetPassRate* row = rates.find(set, agent);
    if (row == nullptr) return TableCell{};
    return TableCell{true, percent(row->mean_rate), row->mean_rate,
                     std::to_string(row->passes) + " of " + std::to_string(row->runs) + " runs passed on " +
                         std::to_string(row->problems) + " PPPs"};
  }, out);
  std::vector<SetSummary> summaries;
  for (const std::string& set : rates.sets) summaries.push_back(summarise(rates, set));
  const auto footer = [&](const std::string& label, auto cell) {
    out->md += "| *" + label + "* |";
    out->html += "<tr class=\"foot\"><td>" + escapeMarkup(label) + "</td>";
    for (const SetSummary& summary : summaries) {
      const std::string value = cell(summary);
      out->md += " " + value + " |";
      out->html += "<td class=\"num\">" + escapeMarkup(value) + "</td>";
    }
    out->md += "\n";
    out->html += "</tr>\n";
  };
  out->html += "</tbody>\n<tfoot>\n";
  footer("PPPs", [](const SetSummary& s) { return std::to_string(s.problems); });
  footer("runs per PPP and agent", [](const SetSummary& s) { return range(s.min_runs, s.max_runs); });
  footer("runs in total", [](const SetSummary& s) { return std::to_string(s.runs); });
  if (input.sets.size() == rates.sets.size()) {
    std::size_t column = 0;
    footer("diversity", [&](const SetSummary&) { return formatFixed(input.sets[column++].diversity, 3); });
  }
  out->html += "</tfoot>\n</table>\n";
  out->md += "\n";
}

void referenceSection(const ReportInput& input, Text* out) {
  if (input.references.empty()) return;
  openSection("Reference",
              "Published pass rates (the configuration's reference) beside the measured mean over each set's PPPs: "
              "the difference in percentage points, and whether the reference lies within the 95 % interval of the "
              "measured mean (mean \xC2\xB1 1.96 \xC3\x97 the standard deviation of the per-PPP rates / "
              "\xE2\x88\x9APPPs), that is whether another set of as many PPPs like this one could have given it.",
              out);
  out->md += "| Set | Agent | measured | reference | difference | 95 % interval | within |\n"
             "|:---|:---|---:|---:|---:|---:|:---:|\n";
  out->html += "<table>\n<thead><tr><th>Set</th><th>Agent</th><th class=\"num\">measured</th>"
               "<th class=\"num\">reference</th><th class=\"num\">difference</th>"
               "<th class=\"num\">95 % interval</th><th>within</th></tr></thead>\n<tbody>\n";
  for (const ReferenceComparison& row : input.references) {
    const std::string points = row.measured ? formatFixed((row.mean - row.reference) * 100, 2) : "\xE2\x80\x94";
    const std::vector<std::string> cells = {
        row.measured ? percent(row.mean) : "not run", percent(row.reference),
        row.measured && row.mean >= row.reference ? "+" + points : points,
        row.measured ? percent(std::max(0.0, row.mean - row.margin)) + " \xE2\x80\x93 " +
                           percent(std::min(1.0, row.mean + row.margin))
                     : "\xE2\x80\x94"};
    out->md += "| " + mdCode(row.set, true) + " | " + mdCode(row.agent, true) + " |";
    out->html += "<tr><td><code>" + escapeMarkup(row.set) + "</code></td><td><code>" + escapeMarkup(row.agent) +
                 "</code></td>";
    for (const std::string& cell : cells) {
      out->md += " " + cell + " |";
      out->html += "<td class=\"num\">" + escapeMarkup(cell) + "</td>";
    }
    out->md += row.within() ? " yes |\n" : " **no** |\n";
    out->html += row.within() ? "<td>yes</td></tr>\n" : "<td class=\"sig\">no</td></tr>\n";
  }
  out->md += "\n";
  out->html += "</tbody>\n</table>\n";
}

void comparisonSection(const ReportInput& input, Text* out) {
  openSection("Mann\xE2\x80\x93Whitney U tests",
              "Per agent, the per-PPP pass rates on set A against those on set B: two-sided test, normal "
              "approximation with the tie-corrected variance and no continuity correction; U is the smaller of U_A "
              "and U_B; z > 0 means higher pass rates on A.",
              out);
  if (input.comparisons.empty()) {
    out->md += "No set pairs were compared.\n\n";
    out->html += "<p class=\"muted\">No set pairs were compared.</p>\n";
    return;
  }
  for (const auto& [set_a, set_b] : input.comparisons) {
    const std::vector<AgentComparison> rows = compareSets(input.rates, set_a, set_b);
    out->md += "### " + mdCode(set_a, false) + " (A) vs " + mdCode(set_b, false) + " (B)\n\n";
    out->html += "<h3><code>" + escapeMarkup(set_a) + "</code> (A) vs <code>" + escapeMarkup(set_b) +
                 "</code> (B)</h3>\n";
    if (rows.empty()) {
      out->md += "No agent has results on both sets.\n\n";
      out->html += "<p class=\"muted\">No agent has results on both sets.</p>\n";
      continue;
    }
    out->md += "| Agent | mean A | mean B | n A | n B | U | z | p | significant at 0.05 |\n"
               "|:---|---:|---:|---:|---:|---:|---:|---:|:---:|\n";
    out->html += "<table>\n<thead><tr><th>Agent</th><th class=\"num\">mean A</th><th class=\"num\">mean B</th>"
                 "<th class=\"num\">n A</th><th class=\"num\">n B</th><th class=\"num\">U</th>"
                 "<th class=\"num\">z</th><th class=\"num\">p</th><th>significant at 0.05</th></tr></thead>\n"
                 "<tbody>\n";
    for (const AgentComparison& row : rows) {
      const bool significant = row.test.p < kSignificance;
      const std::vector<std::string> cells = {percent(row.mean_a),      percent(row.mean_b),
                                              std::to_string(row.test.n_a), std::to_string(row.test.n_b),
                                              uValue(row.test.u),       formatFixed(row.test.z, 3),
                                              pValue(row.test.p)};
      out->md += "| " + mdCode(row.agent, true) + " |";
      out->html += "<tr><td><code>" + escapeMarkup(row.agent) + "</code></td>";
      for (const std::string& cell : cells) {
        out->md += " " + cell + " |";
        out->html += "<td class=\"num\">" + escapeMarkup(cell) + "</td>";
      }
      out->md += significant ? " **yes** |\n" : " no |\n";
      out->html += significant ? "<td class=\"sig\">yes</td></tr>\n" : "<td>no</td></tr>\n";
    }
    out->md += "\n";
    out->html += "</tbody>\n</table>\n";
  }
}

void plotSection(const std::vector<Plot>& plots, Text* out) {
  out->md += "## Plots\n\n";
  out->html += "<h2>Plots</h2>\n";
  for (const Plot& plot : plots) {
    out->md += "![" + mdText(plot.caption) + "](" + plot.file + ")\n\n" + mdText(plot.caption) + "\n\n";
    out->html += "<figure>\n" + plot.inline_svg + "<figcaption>" + escapeMarkup(plot.caption) + " (file <code>" +
                 escapeMarkup(plot.file) + "</code>)</figcaption>\n</figure>\n";
  }
}

/// One failing run: heading, picture and the facts to replay it.
void failureEntry(const FailureExample& failure, const Picture& picture, const std::string& number, Text* out) {
  const std::string alt = "PPP " + failure.problem + " of set " + failure.set + " with the path of " +
                          failure.agent + " in run " + std::to_string(failure.run);
  const std::string reason = reasonText(failure.reason);
  std::string diagnosis = describeDiagnosis(failure.diagnosis, failure.reason, static_cast<int>(failure.cycle.size()));
  if (!failure.cycle.empty()) diagnosis += " (the cycle's cells are pink)";
  const std::string grid = std::to_string(failure.ppp.width) + "\xC3\x97" + std::to_string(failure.ppp.height) +
                           ", start " + cellText(failure.ppp.start) + ", goal " + cellText(failure.ppp.goal) +
                           ", " + std::to_string(decodeGrid(failure.ppp).obstacleCount()) + " obstacle cells";
  const std::string command = replayCommand(failure, picture.ppp_file);

  out->md += "### " + number + mdCode(failure.set, false) + " / " + mdCode(failure.problem, false) +
             " \xE2\x80\x94 " + mdCode(failure.agent, false) + "\n\n";
  out->md += "![" + mdText(alt) + "](" + picture.png_file + ")";
  if (!picture.gif_file.empty()) out->md += " ![" + mdText("The same run, step by step") + "](" + picture.gif_file + ")";
  out->md += "\n\n";
  out->md += "- agent " + mdCode(failure.agent, false) + ", run " + std::to_string(failure.run) + ", seed " +
             mdCode(std::to_string(failure.seed), false) + "\n";
  out->md += "- reason " + mdCode(failure.reason, false) + (reason.empty() ? "" : ": " + mdText(reason)) + "\n";
  if (!diagnosis.empty()) out->md += "- diagnosis " + mdText(diagnosis) + "\n";
  out->md += "- grid " + mdText(grid) + "\n";
  out->md += "- path " + mdText(pathText(failure)) + "\n";
  out->md += "- replay: " + mdCode(command, false) + "\n";
  std::string shrunk_command;
  if (failure.shrunk) {
    shrunk_command = shrunkReplayCommand(failure, picture.shrunk_ppp_file);
    out->md += "- shrunk: " + mdText(failure.shrunk->summary) + " (" + mdCode(picture.shrunk_ppp_file, false) +
               "; replay: " + mdCode(shrunk_command, false) + ")\n\n  ![" +
               mdText("The same run on the shrunk PPP") + "](" + picture.shrunk_png_file + ")";
    if (!picture.shrunk_gif_file.empty()) {
      out->md += " ![" + mdText("The same run on the shrunk PPP, step by step") + "](" + picture.shrunk_gif_file + ")";
    }
    out->md += "\n";
  }
  out->md += "\n";

  out->html += "<h3>" + escapeMarkup(number) + "<code>" + escapeMarkup(failure.set) + "</code> / <code>" +
               escapeMarkup(failure.problem) + "</code> \xE2\x80\x94 <code>" + escapeMarkup(failure.agent) +
               "</code></h3>\n<div class=\"failure\">\n";
  out->html += "<img src=\"data:image/png;base64," + generator::base64Encode(picture.png) + "\" width=\"" +
               std::to_string(picture.width) + "\" height=\"" + std::to_string(picture.height) + "\" alt=\"" +
               escapeMarkup(alt) + "\">\n";
  if (!picture.gif_file.empty()) {  // shown at twice its size, each pixel doubled
    out->html += "<img src=\"data:image/gif;base64," + generator::base64Encode(failure.animation_gif) +
                 "\" width=\"" + std::to_string(2 * picture.gif_width) + "\" height=\"" +
                 std::to_string(2 * picture.gif_height) + "\" alt=\"" + escapeMarkup("The same run, step by step") +
                 "\">\n";
  }
  out->html += "<ul>\n";
  out->html += "<li>agent <code>" + escapeMarkup(failure.agent) + "</code>, run " + std::to_string(failure.run) +
               ", seed <code>" + std::to_string(failure.seed) + "</code></li>\n";
  out->html += "<li>reason <code>" + escapeMarkup(failure.reason) + "</code>" +
               (reason.empty() ? "" : ": " + escapeMarkup(reason)) + "</li>\n";
  if (!diagnosis.empty()) out->html += "<li>diagnosis " + escapeMarkup(diagnosis) + "</li>\n";
  out->html += "<li>grid " + escapeMarkup(grid) + "</li>\n";
  out->html += "<li>path " + escapeMarkup(pathText(failure)) + "</li>\n";
  out->html += "<li>picture <code>" + escapeMarkup(picture.png_file) + "</code>" +
               (picture.gif_file.empty() ? "" : ", animation <code>" + escapeMarkup(picture.gif_file) + "</code>") +
               ", PPP file <code>" +
               escapeMarkup(picture.ppp_file) + "</code></li>\n";
  out->html += "<li>replay: <code>" + escapeMarkup(command) + "</code></li>\n";
  if (failure.shrunk) {
    out->html += "<li>shrunk: " + escapeMarkup(failure.shrunk->summary) + " (<code>" +
                 escapeMarkup(picture.shrunk_ppp_file) + "</code>; replay: <code>" + escapeMarkup(shrunk_command) +
                 "</code>)<br><img src=\"data:image/png;base64," + generator::base64Encode(picture.shrunk_png) +
                 "\" width=\"" + std::to_string(picture.shrunk_width) + "\" height=\"" +
                 std::to_string(picture.shrunk_height) + "\" alt=\"" + escapeMarkup("The same run on the shrunk PPP") +
                 "\">";
    if (!picture.shrunk_gif_file.empty()) {
      out->html += "<img src=\"data:image/gif;base64," + generator::base64Encode(failure.shrunk->animation_gif) +
                   "\" alt=\"" + escapeMarkup("The same run on the shrunk PPP, step by step") + "\">";
    }
    out->html += "</li>\n";
  }
  out->html += "</ul>\n</div>\n";
}

void failureSection(const ReportInput& input, const std::vector<Picture>& pictures, Text* out) {
  out->md += "## Hardest PPPs\n\n";
  out->html += "<h2>Hardest PPPs</h2>\n";
  if (input.failures.empty()) {
    out->md += "No failed runs on the hardest PPPs were recorded.\n\n";
    out->html += "<p class=\"muted\">No failed runs on the hardest PPPs were recorded.</p>\n";
    return;
  }
  const std::string intro =
      "A failed run on each of the hardest PPPs: the agent's path in blue (dots on the cells it stood on), start "
      "green, goal red, obstacles dark grey. Run the replay command from this report's directory to reproduce it.";
  const std::string text = intro + animationGuide(input.failures);
  out->md += mdText(text) + "\n\n";
  out->html += "<p>" + escapeMarkup(text) + "</p>\n";
  for (std::size_t i = 0; i < input.failures.size(); ++i) {
    failureEntry(input.failures[i], pictures[i], std::to_string(i + 1) + ". ", out);
  }
}

/// Per agent and set, how many runs of each diagnosis kind.
void diagnosisSection(const PassRateTable& rates, Text* out) {
  std::vector<const SetPassRate*> rows;
  DiagnosisCounts total;
  for (const SetPassRate& row : rates.per_set) {
    DiagnosisCounts none;
    if (row.diagnoses.kinds == none.kinds) continue;
    rows.push_back(&row);
    total.add(row.diagnoses);
  }
  openSection("Diagnoses",
              rows.empty() ? "No run failed or made a detour."
                           : "Per agent and set, how its failed runs (and soft failures, as detours) ended, in "
                             "runs. stuck: it stopped moving; loop: it repeated a cycle of cells to the end (endless: "
                             "a planner's whole state recurred, so it can never leave); confined: it moved only over "
                             "cells it had stood on before; wandering: it was still reaching new cells when the "
                             "budget ran out; missed_route / no_route: a planner's \"no path\" when its map had a "
                             "route / had none; reported: the reason column says it (a collision, a timeout, ...). "
                             "results.csv has each run's diagnosis, the step it began and a loop's period.",
              out);
  if (rows.empty()) return;
  std::vector<int> kinds;  // the kinds some run has
  for (int k = 0; k < diagnosis::kKindCount; ++k) {
    if (total.kinds[static_cast<std::size_t>(k)] > 0) kinds.push_back(k);
  }
  out->md += "| Agent | Set |";
  std::string align = "|:---|:---|";
  out->html += "<table>\n<thead><tr><th>Agent</th><th>Set</th>";
  for (const int k : kinds) {
    const std::string kind = diagnosis::kKinds[k];
    out->md += " " + kind + " |";
    align += "---:|";
    out->html += "<th class=\"num\">" + escapeMarkup(kind) + "</th>";
  }
  out->md += "\n" + align + "\n";
  out->html += "</tr></thead>\n<tbody>\n";
  for (const SetPassRate* row : rows) {
    out->md += "| " + mdCode(row->agent, true) + " | " + mdCode(row->set, true) + " |";
    out->html += "<tr><td><code>" + escapeMarkup(row->agent) + "</code></td><td><code>" + escapeMarkup(row->set) +
                 "</code></td>";
    for (const int k : kinds) {
      const int n = row->diagnoses.kinds[static_cast<std::size_t>(k)];
      std::string cell = n == 0 ? "\xE2\x80\x94" : std::to_string(n);
      if (std::string(diagnosis::kKinds[k]) == diagnosis::kLoop && row->diagnoses.endless > 0) {
        cell += " (" + std::to_string(row->diagnoses.endless) + " endless)";
      }
      out->md += " " + cell + " |";
      out->html += "<td class=\"num" + std::string(n == 0 ? " muted" : "") + "\">" + escapeMarkup(cell) + "</td>";
    }
    out->md += "\n";
    out->html += "</tr>\n";
  }
  out->md += "\n";
  out->html += "</tbody>\n</table>\n";
}

/// Each agent played in both motion models: its mean pass rates side by side, and how its failed runs ended.
void motionSection(const ReportInput& input, Text* out) {
  if (input.motion_pairs.empty()) return;
  openSection("Both motion models",
              "Agents played on the grid (one cell per command, no heading) and in continuous motion (a robot with a "
              "heading, a velocity and a laser; docs/reference/continuous-motion.md): per set, the mean pass rate "
              "in each model and how the failed runs ended. A collision exists only in continuous motion: on the "
              "grid a move into an obstacle bumps.",
              out);
  out->md += "| Grid agent | Continuous agent | Set | Grid | Continuous | Grid failures | Continuous failures |\n"
             "|:---|:---|:---|---:|---:|:---|:---|\n";
  out->html += "<table>\n<thead><tr><th>Grid agent</th><th>Continuous agent</th><th>Set</th><th class=\"num\">Grid"
               "</th><th class=\"num\">Continuous</th><th>Grid failures</th><th>Continuous failures</th></tr></thead>\n"
               "<tbody>\n";
  for (const MotionPair& pair : input.motion_pairs) {
    for (const std::string& set : input.rates.sets) {
      const SetPassRate* grid = input.rates.find(set, pair.grid_agent);
      const SetPassRate* continuous = input.rates.find(set, pair.continuous_agent);
      if (grid == nullptr || continuous == nullptr) continue;
      const std::string cells[] = {percent(grid->mean_rate), percent(continuous->mean_rate), failureKinds(*grid),
                                   failureKinds(*continuous)};
      out->md += "| " + mdCode(pair.grid_agent, true) + " | " + mdCode(pair.continuous_agent, true) + " | " +
                 mdCode(set, true) + " | " + cells[0] + " | " + cells[1] + " | " + cells[2] + " | " + cells[3] + " |\n";
      out->html += "<tr><td><code>" + escapeMarkup(pair.grid_agent) + "</code></td><td><code>" +
                   escapeMarkup(pair.continuous_agent) + "</code></td><td><code>" + escapeMarkup(set) +
                   "</code></td><td class=\"num\" style=\"" + rateCellStyle(grid->mean_rate) + "\">" + cells[0] +
                   "</td><td class=\"num\" style=\"" + rateCellStyle(continuous->mean_rate) + "\">" + cells[1] +
                   "</td><td>" +
                   escapeMarkup(cells[2]) + "</td><td>" + escapeMarkup(cells[3]) + "</td></tr>\n";
    }
  }
  out->md += "\n";
  out->html += "</tbody>\n</table>\n";
}

/// Where the report writes each agent's failure kinds' smallest PPPs: "ppps/failures/SET_PROBLEM.ppp", one file per
/// PPP however many kinds it is the smallest of; parallel to `agents` and their shown kinds.
std::vector<std::vector<std::string>> failureKindFiles(const std::vector<AgentFailureKinds>& agents) {
  FileNames names;
  std::map<std::pair<std::string, std::string>, std::string> claimed;
  std::vector<std::vector<std::string>> files;
  for (const AgentFailureKinds& a : agents) {
    files.emplace_back();
    for (const FailureKind& k : a.shown) {
      std::string& file = claimed[{k.set, k.problem}];
      if (file.empty()) file = "ppps/failures/" + names.claim(safeStem(k.set) + "_" + safeStem(k.problem), ".ppp");
      files.back().push_back(file);
    }
  }
  return files;
}

/// How to play kind `k`'s run of `agent` again on its PPP in `file`: ppp replay, or for a planner its shrink
/// through ROS on the run's seed.
std::string failureKindReplay(const std::string& agent, const FailureKind& k, const std::string& file) {
  FailureExample run;
  run.agent = agent;
  run.seed = k.seed;
  run.replay_flags = k.replay_flags;
  return k.replay_flags.empty() ? shrinkLaunchCommand(run, file) : replayCommand(run, file);
}

/// Per agent, its failures grouped by signature: one row per kind with its runs, PPPs, smallest PPP and replay.
void failureKindTables(const std::vector<AgentFailureKinds>& agents, const std::vector<std::vector<std::string>>& files,
                       Text* out) {
  if (agents.empty()) return;
  const std::string intro =
      "Per agent, its failed and soft-failed runs grouped by failure signature (how and where a run failed: "
      "docs/reference/signatures.md), so that one trap failed a hundred times reads as one line and a second fault "
      "as a second: the most common first (at most " + std::to_string(kShownFailureKinds) + "; results.csv's "
      "signature column has every run's), each with its runs, the PPPs they happened on, the smallest of those "
      "(fewest obstacle cells, written under ppps/failures/) and the command that plays its run there again, from "
      "this report's directory.";
  out->md += "### Distinct failures\n\n" + mdText(intro) + "\n\n";
  out->html += "<h3>Distinct failures</h3>\n<p>" + escapeMarkup(intro) + "</p>\n";
  for (std::size_t i = 0; i < agents.size(); ++i) {
    const AgentFailureKinds& a = agents[i];
    const int hidden = a.kinds - static_cast<int>(a.shown.size());
    std::string heading = std::to_string(a.kinds) + " distinct failure" + (a.kinds == 1 ? "" : "s") + " in " +
                          std::to_string(a.runs) + " failed run" + (a.runs == 1 ? "" : "s");
    if (hidden > 0) heading += " (the " + std::to_string(hidden) + " least common not listed)";
    out->md += mdCode(a.agent, false) + ": " + heading + "\n\n| Signature | Diagnosis | Runs | PPPs | Smallest PPP | "
               "Replay |\n|:---|:---|---:|---:|:---|:---|\n";
    out->html += "<p><code>" + escapeMarkup(a.agent) + "</code>: " + escapeMarkup(heading) +
                 "</p>\n<table>\n<thead><tr><th>Signature</th><th>Diagnosis</th><th class=\"num\">Runs</th><th "
                 "class=\"num\">PPPs</th><th>Smallest PPP</th><th>Replay</th></tr></thead>\n<tbody>\n";
    for (std::size_t j = 0; j < a.shown.size(); ++j) {
      const FailureKind& k = a.shown[j];
      const std::string smallest =
          k.set + "/" + k.problem + " (" + std::to_string(k.failure.smallest_cells) + " obstacle cells)";
      const std::string replay = failureKindReplay(a.agent, k, files[i][j]);
      out->md += "| " + mdCode(k.failure.key, true) + " | " + k.diagnosis + " | " + std::to_string(k.failure.count) +
                 " | " + std::to_string(k.failure.places) + " | " + mdCode(smallest, true) + " | " +
                 mdCode(replay, true) + " |\n";
      out->html += "<tr><td><code>" + escapeMarkup(k.failure.key) + "</code></td><td>" + escapeMarkup(k.diagnosis) +
                   "</td><td class=\"num\">" + std::to_string(k.failure.count) + "</td><td class=\"num\">" +
                   std::to_string(k.failure.places) + "</td><td><code>" + escapeMarkup(smallest) +
                   "</code></td><td><code>" + escapeMarkup(replay) + "</code></td></tr>\n";
    }
    out->md += "\n";
    out->html += "</tbody>\n</table>\n";
  }
}

/// Per agent and set, how many PPPs the agent fails; each agent's failures by signature and worst PPP; the sets'
/// archives.
void faultSection(const ReportInput& input, const std::vector<Picture>& pictures,
                  const std::vector<std::vector<std::string>>& kind_files, Text* out) {
  const PassRateTable& rates = input.rates;
  out->md += "## Faults found\n\n";
  out->html += "<h2>Faults found</h2>\n";
  const std::string intro =
      "Per agent and set: the PPPs the agent passes in fewer than half of its runs, out of the set's PPPs. "
      "Below, every agent that fails somewhere with a failing run on its worst PPP (not the control or the random "
      "baseline; a planner's run is drawn from its recorded moves, planner_moves.csv, or in continuous motion from the "
      "velocity commands it sent).";
  const std::string text = intro + animationGuide(input.worst);
  out->md += mdText(text) + "\n\n";
  out->html += "<p>" + escapeMarkup(text) + "</p>\n";
  std::map<std::pair<std::string, std::string>, std::pair<int, int>> failed;  // (set, agent) -> (failed, PPPs)
  for (const ProblemPassRate& row : rates.per_problem) {
    auto& count = failed[{row.set, row.agent}];
    count.first += row.rate() < kFailedBelow ? 1 : 0;
    ++count.second;
  }
  agentSetTable(rates, "", [&](const std::string& set, const std::string& agent) {
    const auto found = failed.find({set, agent});
    if (found == failed.end()) return TableCell{};
    const auto [fails, problems] = found->second;
    return TableCell{true, std::to_string(fails) + " of " + std::to_string(problems),
                     1.0 - static_cast<double>(fails) / problems, ""};
  }, out);
  out->md += "\n";
  out->html += "</tbody>\n</table>\n";
  failureKindTables(input.failure_kinds, kind_files, out);
  for (std::size_t i = 0; i < input.worst.size(); ++i) {
    failureEntry(input.worst[i], pictures[i], "", out);
  }
  for (const SetInfo& set : input.sets) {
    if (set.archive_svg.empty()) continue;
    const std::string caption = "The MAP-Elites archive of set " + set.name +
                                ": each cell keeps the fittest PPP whose characters fall into it; darker is fitter.";
    out->md += "### Archive of " + mdCode(set.name, false) + "\n\n" + mdText(caption) +
               " (archive.svg in the set's directory)\n\n";
    const std::string inline_svg = set.archive_svg.substr(std::min(set.archive_svg.find("<svg"), set.archive_svg.size()));
    out->html += "<h3>Archive of <code>" + escapeMarkup(set.name) + "</code></h3>\n<figure>\n" + inline_svg +
                 "<figcaption>" + escapeMarkup(caption) + "</figcaption>\n</figure>\n";
  }
}

/// Per agent and set, how much longer than the optimum its passed runs were and how many were soft failures;
/// each agent's longest detour.
void detourSection(const ReportInput& input, const std::vector<Picture>& pictures, Text* out) {
  if (input.detours.empty()) return;
  openSection("Detours",
              "Per agent and set, path length / optimal length of the passed runs: the median, the 95th percentile "
              "and the largest, then the soft failures (passed runs longer than the configured soft_failure_ratio "
              "allows). The box plot under Plots shows the whole spread. Below, per agent, its longest run on the PPP "
              "where its passed runs were longest on average." + animationGuide(input.detour_examples),
              out);
  agentSetTable(input.rates, "", [&](const std::string& set, const std::string& agent) {
    for (const DetourStats& d : input.detours) {
      if (d.set != set || d.agent != agent) continue;
      const double soft = static_cast<double>(d.soft_failures) / d.passed;
      return TableCell{true,
                       formatFixed(d.spread.median, 2) + " / " + formatFixed(d.spread.p95, 2) + " / " +
                           formatFixed(d.max, 2) + ", soft " + std::to_string(d.soft_failures),
                       1.0 - soft,
                       std::to_string(d.passed) + " passed runs; worst PPP " + d.worst_problem + " (mean " +
                           formatFixed(d.worst_mean, 2) + ")"};
    }
    return TableCell{};
  }, out);
  out->md += "\n";
  out->html += "</tbody>\n</table>\n";
  for (std::size_t i = 0; i < input.detour_examples.size(); ++i) {
    failureEntry(input.detour_examples[i], pictures[i], "", out);
  }
}

void configurationSection(const ReportInput& input, Text* out) {
  out->md += "## Configuration\n\n";
  out->html += "<h2>Configuration</h2>\n";
  if (input.config_text.empty()) {
    out->md += "No configuration was given.\n";
    out->html += "<p class=\"muted\">No configuration was given.</p>\n";
    return;
  }
  out->md += "The experiment configuration, verbatim:\n\n" + mdFence(input.config_text, "yaml");
  out->html += "<p>The experiment configuration, verbatim:</p>\n<pre><code>" + escapeMarkup(input.config_text) +
               "</code></pre>\n";
}

void checkComparisons(const ReportInput& input) {
  for (std::size_t i = 0; i < input.comparisons.size(); ++i) {
    for (const std::string* set : {&input.comparisons[i].first, &input.comparisons[i].second}) {
      if (std::find(input.rates.sets.begin(), input.rates.sets.end(), *set) == input.rates.sets.end()) {
        throw InvalidArgument("comparisons", "pair " + std::to_string(i) + " names set '" + *set +
                                                 "', which the pass-rate table does not have");
      }
    }
  }
}

void makeDirectory(const std::string& path) {
  std::error_code error;
  std::filesystem::create_directories(path, error);
  if (error) throw IoError(path, "cannot create directory: " + error.message());
}

}  // namespace

void writeReport(const std::string& dir, const ReportInput& input, const StopCheck& stop) {
  checkComparisons(input);
  std::vector<Plot> plots = makePlots(input.rates);
  for (Plot& plot : detourPlots(input.rates, input.detours)) plots.push_back(std::move(plot));
  std::vector<FailureExample> shown = input.failures;
  shown.insert(shown.end(), input.worst.begin(), input.worst.end());
  shown.insert(shown.end(), input.detour_examples.begin(), input.detour_examples.end());
  const std::vector<Picture> all_pictures = makePictures(shown, stop);
  const auto failures_end = all_pictures.begin() + static_cast<long>(input.failures.size());
  const auto worst_end = failures_end + static_cast<long>(input.worst.size());
  const std::vector<Picture> pictures(all_pictures.begin(), failures_end);
  const std::vector<Picture> worst_pictures(failures_end, worst_end);
  const std::vector<Picture> detour_pictures(worst_end, all_pictures.end());

  Text text;
  const std::string title = input.title.empty() ? "PPP experiment report" : input.title;
  const std::string guide = readingGuide(input);
  text.md = "# " + mdText(title) + "\n\n" + mdText(guide) + "\n\n";
  text.html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escapeMarkup(title) +
              "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" + escapeMarkup(title) +
              "</h1>\n<p class=\"guide\">" + escapeMarkup(guide) + "</p>\n";
  passRateSection(input, &text);
  referenceSection(input, &text);
  comparisonSection(input, &text);
  diagnosisSection(input.rates, &text);
  motionSection(input, &text);
  const std::vector<std::vector<std::string>> kind_files = failureKindFiles(input.failure_kinds);
  faultSection(input, worst_pictures, kind_files, &text);
  detourSection(input, detour_pictures, &text);
  plotSection(plots, &text);
  failureSection(input, pictures, &text);
  configurationSection(input, &text);
  text.html += "</body>\n</html>\n";

  const std::filesystem::path root(dir);
  makeDirectory(dir);
  makeDirectory((root / "plots").string());
  if (!shown.empty()) {
    makeDirectory((root / "pictures").string());
    makeDirectory((root / "ppps").string());
  }
  const auto write = [&](const std::string& file, const std::string& contents) {
    stopIfAsked(stop);
    writeFileAtomically((root / file).string(), contents);
  };
  for (const Plot& plot : plots) write(plot.file, plot.file_svg);
  std::set<std::string> written_ppps;
  for (std::size_t i = 0; i < all_pictures.size(); ++i) {
    write(all_pictures[i].png_file, all_pictures[i].png);
    if (!all_pictures[i].gif_file.empty()) write(all_pictures[i].gif_file, shown[i].animation_gif);
    if (written_ppps.insert(all_pictures[i].ppp_file).second) write(all_pictures[i].ppp_file, formatPpp(shown[i].ppp));
    if (shown[i].shrunk) {
      write(all_pictures[i].shrunk_png_file, all_pictures[i].shrunk_png);
      if (!all_pictures[i].shrunk_gif_file.empty()) {
        write(all_pictures[i].shrunk_gif_file, shown[i].shrunk->animation_gif);
      }
      write(all_pictures[i].shrunk_ppp_file, formatPpp(shown[i].shrunk->ppp));
    }
  }
  if (!input.failure_kinds.empty()) makeDirectory((root / "ppps" / "failures").string());
  std::set<std::string> written_kinds;
  for (std::size_t i = 0; i < input.failure_kinds.size(); ++i) {
    for (std::size_t j = 0; j < input.failure_kinds[i].shown.size(); ++j) {
      const std::string& file = kind_files[i][j];
      if (written_kinds.insert(file).second) write(file, formatPpp(input.failure_kinds[i].shown[j].ppp));
    }
  }
  write("report.md", text.md);
  write("report.html", text.html);
}

}  // namespace simulator
}  // namespace ppp
