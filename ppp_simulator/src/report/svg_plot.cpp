#include "ppp_simulator/report/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include "ppp_core/error.hpp"
#include "ppp_core/text_format.hpp"

namespace ppp {
namespace simulator {

namespace {

// Layout, in SVG pixels. Text widths are estimated at kCharWidth per character of 12px sans-serif.
constexpr double kCharWidth = 7.0;
constexpr double kTop = 44;
constexpr double kLeft = 64;
constexpr double kPlotHeight = 260;
constexpr double kMinPlotWidth = 320;
constexpr double kLegendRow = 20;
constexpr std::size_t kMaxLabelChars = 28;
constexpr std::size_t kMaxLegendChars = 40;
constexpr const char* kFont = "font-family=\"sans-serif\"";

// Tableau 10: distinguishable, and not relying on red/green alone.
constexpr const char* kSeriesColours[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                                          "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#7f7f7f"};
constexpr std::size_t kSeriesColourCount = sizeof kSeriesColours / sizeof kSeriesColours[0];

const char* colour(std::size_t series) { return kSeriesColours[series % kSeriesColourCount]; }

/// A coordinate with one decimal.
std::string px(double value) { return formatFixed(value, 1); }

/// Where everything goes; computed once from the chart and the width each category needs.
struct Layout {
  double band = 0;         ///< Width of one category.
  double plot_width = 0;   ///< Width of the plotting area.
  bool rotate = false;     ///< Category labels drawn slanted.
  double label_height = 0; ///< Space under the axis for the category labels.
  double legend_x = 0;     ///< Left edge of the legend.
  double width = 0;        ///< Whole picture.
  double height = 0;       ///< Whole picture.

  double plotBottom() const { return kTop + kPlotHeight; }
  double plotRight() const { return kLeft + plot_width; }
};

/// Displayed characters of the longest series name (capped at kMaxLegendChars).
std::size_t longestSeriesName(const Chart& chart) {
  std::size_t longest = 0;
  for (const PlotSeries& s : chart.series) longest = std::max(longest, std::min(displayLength(s.name), kMaxLegendChars));
  return longest;
}

Layout layOut(const Chart& chart, double min_band) {
  Layout layout;
  const std::size_t n = chart.categories.size();
  layout.plot_width = std::max(kMinPlotWidth, static_cast<double>(n) * min_band);
  layout.band = n > 0 ? layout.plot_width / static_cast<double>(n) : layout.plot_width;
  std::size_t longest_label = 0;
  for (const std::string& label : chart.categories) {
    longest_label = std::max(longest_label, std::min(displayLength(label), kMaxLabelChars));
  }
  layout.rotate = static_cast<double>(longest_label) * kCharWidth > layout.band - 4;
  // Slanted at 40°, a label of w pixels reaches w · sin 40° ≈ 0.64 w below the axis; kCharWidth is generous,
  // so 0.57 of it is about the real reach.
  layout.label_height = layout.rotate ? 14 + static_cast<double>(longest_label) * kCharWidth * 0.57 : 22;
  const std::size_t longest_name = longestSeriesName(chart);
  layout.legend_x = layout.plotRight() + 24;
  layout.width = layout.legend_x + 26 + static_cast<double>(longest_name) * kCharWidth + 12;
  const double below = layout.label_height + (chart.x_label.empty() ? 8 : 30);
  const double legend_bottom = kTop + static_cast<double>(chart.series.size()) * kLegendRow + 8;
  layout.height = std::max(layout.plotBottom() + below, legend_bottom);
  return layout;
}

std::string openSvg(const Chart& chart, const Layout& layout, bool standalone, const std::string& kind) {
  std::string svg;
  if (standalone) svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += "<svg";
  // The namespace is a name, not something fetched; inline SVG in HTML does not need it.
  if (standalone) svg += " xmlns=\"http://www.w3.org/2000/svg\"";
  svg += " width=\"" + px(layout.width) + "\" height=\"" + px(layout.height) + "\" viewBox=\"0 0 " +
         px(layout.width) + " " + px(layout.height) + "\" role=\"img\" aria-label=\"" +
         escapeMarkup(kind + ": " + chart.title) + "\" " + kFont + " font-size=\"12\">\n";
  svg += "<rect x=\"0\" y=\"0\" width=\"" + px(layout.width) + "\" height=\"" + px(layout.height) +
         "\" fill=\"#ffffff\"/>\n";
  svg += "<text x=\"" + px(kLeft) + "\" y=\"24\" font-size=\"15\" font-weight=\"bold\" fill=\"#222\">" +
         escapeMarkup(chart.title) + "</text>\n";
  return svg;
}

/// Grid lines, the y axis with its ticks and caption, the x axis with the category labels and caption.
std::string axes(const Chart& chart, const Layout& layout) {
  std::string svg;
  const double step = tickStep(chart.y_max);
  for (int t = 0; t * step <= chart.y_max * (1 + 1e-9); ++t) {
    const double y = layout.plotBottom() - t * step / chart.y_max * kPlotHeight;
    svg += "<line x1=\"" + px(kLeft) + "\" y1=\"" + px(y) + "\" x2=\"" + px(layout.plotRight()) + "\" y2=\"" +
           px(y) + "\" stroke=\"" + (t == 0 ? "#444" : "#e4e4e4") + "\"/>\n";
    svg += "<text x=\"" + px(kLeft - 6) + "\" y=\"" + px(y) + "\" dy=\"0.35em\" text-anchor=\"end\" fill=\"#444\">" +
           formatGeneral(t * step, 6) + escapeMarkup(chart.value_suffix) + "</text>\n";
  }
  svg += "<line x1=\"" + px(kLeft) + "\" y1=\"" + px(kTop) + "\" x2=\"" + px(kLeft) + "\" y2=\"" +
         px(layout.plotBottom()) + "\" stroke=\"#444\"/>\n";
  if (!chart.y_label.empty()) {
    const double y = kTop + kPlotHeight / 2;
    svg += "<text transform=\"translate(16 " + px(y) + ") rotate(-90)\" text-anchor=\"middle\" fill=\"#222\">" +
           escapeMarkup(chart.y_label) + "</text>\n";
  }
  for (std::size_t c = 0; c < chart.categories.size(); ++c) {
    const double x = kLeft + (static_cast<double>(c) + 0.5) * layout.band;
    const double y = layout.plotBottom() + 14;
    const std::string label = escapeMarkup(shortenText(chart.categories[c], kMaxLabelChars));
    const std::string full = escapeMarkup(chart.categories[c]);
    if (layout.rotate) {
      svg += "<text transform=\"translate(" + px(x + 3) + " " + px(y - 4) +
             ") rotate(-40)\" text-anchor=\"end\" fill=\"#222\"><title>" + full + "</title>" + label + "</text>\n";
    } else {
      svg += "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\" text-anchor=\"middle\" fill=\"#222\"><title>" + full +
             "</title>" + label + "</text>\n";
    }
  }
  if (chart.categories.empty()) {
    svg += "<text x=\"" + px(kLeft + layout.plot_width / 2) + "\" y=\"" + px(kTop + kPlotHeight / 2) +
           "\" text-anchor=\"middle\" fill=\"#888\">no data</text>\n";
  }
  if (!chart.x_label.empty()) {
    svg += "<text x=\"" + px(kLeft + layout.plot_width / 2) + "\" y=\"" +
           px(layout.plotBottom() + layout.label_height + 18) + "\" text-anchor=\"middle\" fill=\"#222\">" +
           escapeMarkup(chart.x_label) + "</text>\n";
  }
  return svg;
}

/// The legend on the right: a swatch and the series name.
std::string legend(const Chart& chart, const Layout& layout) {
  std::string svg;
  for (std::size_t s = 0; s < chart.series.size(); ++s) {
    const double y = kTop + static_cast<double>(s) * kLegendRow + 8;
    const std::string name = escapeMarkup(chart.series[s].name);
    svg += "<rect x=\"" + px(layout.legend_x) + "\" y=\"" + px(y - 6) + "\" width=\"18\" height=\"12\" fill=\"" +
           colour(s) + "\"/>\n";
    svg += "<text x=\"" + px(layout.legend_x + 26) + "\" y=\"" + px(y) + "\" dy=\"0.35em\" fill=\"#222\"><title>" +
           name + "</title>" + escapeMarkup(shortenText(chart.series[s].name, kMaxLegendChars)) + "</text>\n";
  }
  return svg;
}

double valueY(const Chart& chart, double value) {
  const double clamped = std::clamp(value, 0.0, chart.y_max);
  return kTop + kPlotHeight - clamped / chart.y_max * kPlotHeight;
}

std::string tooltip(const Chart& chart, std::size_t s, std::size_t c) {
  return escapeMarkup(chart.series[s].name + " on " + chart.categories[c] + ": " +
                      formatFixed(chart.series[s].values[c], 2) + chart.value_suffix);
}

}  // namespace

void Chart::validate() const {
  if (!std::isfinite(y_max) || y_max <= 0) {
    throw InvalidArgument("y_max", "expected a positive finite number, got " + formatGeneral(y_max, 6));
  }
  for (const PlotSeries& s : series) {
    if (s.values.size() != categories.size()) {
      throw InvalidArgument("series", "'" + s.name + "' has " + std::to_string(s.values.size()) + " values for " +
                                          std::to_string(categories.size()) + " categories, expected one each");
    }
  }
}

std::string groupedBarChartSvg(const Chart& chart, bool standalone) {
  chart.validate();
  const double min_band = std::max(36.0, static_cast<double>(chart.series.size()) * 14 + 14);
  const Layout layout = layOut(chart, min_band);
  std::string svg = openSvg(chart, layout, standalone, "bar chart") + axes(chart, layout);
  const double group = layout.band * 0.8;
  const double bar = chart.series.empty() ? 0 : group / static_cast<double>(chart.series.size());
  for (std::size_t c = 0; c < chart.categories.size(); ++c) {
    const double left = kLeft + static_cast<double>(c) * layout.band + (layout.band - group) / 2;
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
      const double value = chart.series[s].values[c];
      if (std::isnan(value)) continue;
      const double top = valueY(chart, value);
      // A zero bar still gets a hairline so "0 %" is distinguishable from "not run".
      const double height = std::max(1.0, layout.plotBottom() - top);
      svg += "<rect x=\"" + px(left + static_cast<double>(s) * bar + 0.5) + "\" y=\"" +
             px(layout.plotBottom() - height) + "\" width=\"" + px(std::max(1.0, bar - 1)) + "\" height=\"" +
             px(height) + "\" fill=\"" + colour(s) + "\"><title>" + tooltip(chart, s, c) + "</title></rect>\n";
    }
  }
  svg += legend(chart, layout);
  svg += "</svg>\n";
  return svg;
}

std::string boxPlotSvg(const Chart& chart, const std::vector<std::vector<BoxStats>>& boxes, bool standalone) {
  chart.validate();
  bool fits = boxes.size() == chart.series.size();
  for (const auto& row : boxes) fits = fits && row.size() == chart.categories.size();
  if (!fits) throw InvalidArgument("boxes", "expected one box per series and category");
  const double min_band = std::max(36.0, static_cast<double>(chart.series.size()) * 16 + 14);
  const Layout layout = layOut(chart, min_band);
  std::string svg = openSvg(chart, layout, standalone, "box plot") + axes(chart, layout);
  const double group = layout.band * 0.8;
  const double slot = chart.series.empty() ? 0 : group / static_cast<double>(chart.series.size());
  for (std::size_t c = 0; c < chart.categories.size(); ++c) {
    const double left = kLeft + static_cast<double>(c) * layout.band + (layout.band - group) / 2;
    for (std::size_t s = 0; s < chart.series.size(); ++s) {
      const BoxStats& b = boxes[s][c];
      if (std::isnan(b.median)) continue;
      const double x0 = left + static_cast<double>(s) * slot + 1.5, x1 = x0 + std::max(2.0, slot - 3);
      const double mid = (x0 + x1) / 2;
      const std::string tip = escapeMarkup(chart.series[s].name + " on " + chart.categories[c] + ": median " +
                                           formatFixed(b.median, 2) + ", quartiles " + formatFixed(b.p25, 2) + "-" +
                                           formatFixed(b.p75, 2) + ", 5th-95th percentile " + formatFixed(b.p5, 2) +
                                           "-" + formatFixed(b.p95, 2) + chart.value_suffix);
      svg += "<g><title>" + tip + "</title>\n";
      svg += "<line x1=\"" + px(mid) + "\" y1=\"" + px(valueY(chart, b.p5)) + "\" x2=\"" + px(mid) + "\" y2=\"" +
             px(valueY(chart, b.p95)) + "\" stroke=\"" + colour(s) + "\"/>\n";
      const double top = valueY(chart, b.p75);
      svg += "<rect x=\"" + px(x0) + "\" y=\"" + px(top) + "\" width=\"" + px(x1 - x0) + "\" height=\"" +
             px(std::max(1.0, valueY(chart, b.p25) - top)) + "\" fill=\"" + colour(s) + "\" fill-opacity=\"0.35\" stroke=\"" +
             colour(s) + "\"/>\n";
      svg += "<line x1=\"" + px(x0) + "\" y1=\"" + px(valueY(chart, b.median)) + "\" x2=\"" + px(x1) + "\" y2=\"" +
             px(valueY(chart, b.median)) + "\" stroke=\"#222\" stroke-width=\"2\"/>\n</g>\n";
    }
  }
  svg += legend(chart, layout);
  svg += "</svg>\n";
  return svg;
}

std::string heatMapSvg(const Chart& chart, bool standalone) {
  chart.validate();
  const std::size_t columns = chart.categories.size();
  const std::size_t rows = chart.series.size();
  const double left = 12 + static_cast<double>(longestSeriesName(chart)) * kCharWidth;
  const double cell_width = columns > 0 ? std::clamp(900.0 / static_cast<double>(columns), 6.0, 24.0) : 24.0;
  const double cell_height = 18;
  const double plot_width = std::max(kMinPlotWidth, cell_width * static_cast<double>(columns));
  const double plot_bottom = kTop + cell_height * static_cast<double>(rows);
  Layout layout;
  layout.width = left + plot_width + 20;
  layout.height = plot_bottom + 74;
  std::string svg = openSvg(chart, layout, standalone, "heat map");
  if (columns == 0 || rows == 0) {
    svg += "<text x=\"" + px(left) + "\" y=\"" + px(kTop + 20) + "\" fill=\"#777\">no data</text>\n</svg>\n";
    return svg;
  }
  // Diverging scale: 0 red, the middle near white, y_max blue (readable without telling red from green).
  const auto fill = [&](double value) {
    if (std::isnan(value)) return std::string("#cccccc");
    const double t = std::clamp(value / chart.y_max, 0.0, 1.0);
    const double low[3] = {178, 24, 43}, mid[3] = {247, 247, 247}, high[3] = {33, 102, 172};
    const double* a = t < 0.5 ? low : mid;
    const double* b = t < 0.5 ? mid : high;
    const double u = t < 0.5 ? t * 2 : (t - 0.5) * 2;
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", static_cast<int>(std::lround(a[0] + (b[0] - a[0]) * u)),
                  static_cast<int>(std::lround(a[1] + (b[1] - a[1]) * u)),
                  static_cast<int>(std::lround(a[2] + (b[2] - a[2]) * u)));
    return std::string(hex);
  };
  for (std::size_t r = 0; r < rows; ++r) {
    const double y = kTop + cell_height * static_cast<double>(r);
    svg += "<text x=\"" + px(left - 6) + "\" y=\"" + px(y + cell_height / 2) +
           "\" dy=\"0.35em\" text-anchor=\"end\" fill=\"#222\"><title>" + escapeMarkup(chart.series[r].name) +
           "</title>" + escapeMarkup(shortenText(chart.series[r].name, kMaxLegendChars)) + "</text>\n";
    for (std::size_t c = 0; c < columns; ++c) {
      const double value = chart.series[r].values[c];
      const std::string tip = std::isnan(value) ? escapeMarkup(chart.series[r].name + " on " + chart.categories[c] +
                                                               ": no data")
                                                : tooltip(chart, r, c);
      svg += "<rect x=\"" + px(left + cell_width * static_cast<double>(c)) + "\" y=\"" + px(y) + "\" width=\"" +
             px(cell_width - 1) + "\" height=\"" + px(cell_height - 1) + "\" fill=\"" + fill(value) + "\"><title>" +
             tip + "</title></rect>\n";
    }
  }
  // Column labels: the first, the last and every tenth.
  for (std::size_t c = 0; c < columns; ++c) {
    if (c != 0 && c + 1 != columns && c % 10 != 0) continue;
    svg += "<text x=\"" + px(left + cell_width * (static_cast<double>(c) + 0.5)) + "\" y=\"" + px(plot_bottom + 14) +
           "\" text-anchor=\"middle\" font-size=\"10\" fill=\"#444\"><title>" + escapeMarkup(chart.categories[c]) +
           "</title>" + std::to_string(c) + "</text>\n";
  }
  if (!chart.x_label.empty()) {
    svg += "<text x=\"" + px(left) + "\" y=\"" + px(plot_bottom + 32) + "\" fill=\"#444\">" +
           escapeMarkup(chart.x_label) + "</text>\n";
  }
  // The scale.
  const double scale_y = plot_bottom + 44;
  for (int i = 0; i <= 20; ++i) {
    svg += "<rect x=\"" + px(left + 8.0 * i) + "\" y=\"" + px(scale_y) + "\" width=\"8\" height=\"10\" fill=\"" +
           fill(chart.y_max * i / 20.0) + "\"/>\n";
  }
  svg += "<text x=\"" + px(left - 4) + "\" y=\"" + px(scale_y + 5) + "\" dy=\"0.35em\" text-anchor=\"end\" "
         "font-size=\"10\" fill=\"#444\">0" + escapeMarkup(chart.value_suffix) + "</text>\n";
  svg += "<text x=\"" + px(left + 172) + "\" y=\"" + px(scale_y + 5) + "\" dy=\"0.35em\" font-size=\"10\" "
         "fill=\"#444\">" + formatGeneral(chart.y_max, 6) + escapeMarkup(chart.value_suffix) +
         " (grey: no data)</text>\n";
  svg += "</svg>\n";
  return svg;
}

}  // namespace simulator
}  // namespace ppp
