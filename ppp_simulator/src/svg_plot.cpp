#include "ppp_simulator/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

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
constexpr const char* kPalette[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                                    "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#7f7f7f"};
constexpr std::size_t kPaletteSize = sizeof kPalette / sizeof kPalette[0];

const char* colour(std::size_t series) { return kPalette[series % kPaletteSize]; }

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
  std::size_t longest_name = 0;
  for (const PlotSeries& s : chart.series) {
    longest_name = std::max(longest_name, std::min(displayLength(s.name), kMaxLegendChars));
  }
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

/// A marker of the given shape (cycling circle, square, triangle, diamond) centred on (x, y).
std::string marker(std::size_t series, double x, double y, const std::string& tooltip) {
  const std::string fill = std::string(" fill=\"") + colour(series) + "\" stroke=\"#fff\" stroke-width=\"0.8\"";
  const std::string title = "<title>" + tooltip + "</title>";
  const double r = 3.6;
  switch (series % 4) {
    case 0:
      return "<circle cx=\"" + px(x) + "\" cy=\"" + px(y) + "\" r=\"" + px(r) + "\"" + fill + ">" + title +
             "</circle>\n";
    case 1:
      return "<rect x=\"" + px(x - r) + "\" y=\"" + px(y - r) + "\" width=\"" + px(2 * r) + "\" height=\"" +
             px(2 * r) + "\"" + fill + ">" + title + "</rect>\n";
    case 2:
      return "<path d=\"M" + px(x) + " " + px(y - r - 0.8) + "L" + px(x + r + 0.6) + " " + px(y + r * 0.8) + "L" +
             px(x - r - 0.6) + " " + px(y + r * 0.8) + "Z\"" + fill + ">" + title + "</path>\n";
    default:
      return "<path d=\"M" + px(x) + " " + px(y - r - 0.8) + "L" + px(x + r + 0.8) + " " + px(y) + "L" + px(x) +
             " " + px(y + r + 0.8) + "L" + px(x - r - 0.8) + " " + px(y) + "Z\"" + fill + ">" + title + "</path>\n";
  }
}

/// The legend on the right: a swatch (bars) or a line with its marker (lines) and the series name.
std::string legend(const Chart& chart, const Layout& layout, bool lines) {
  std::string svg;
  for (std::size_t s = 0; s < chart.series.size(); ++s) {
    const double y = kTop + static_cast<double>(s) * kLegendRow + 8;
    const std::string name = escapeMarkup(chart.series[s].name);
    if (lines) {
      svg += "<line x1=\"" + px(layout.legend_x) + "\" y1=\"" + px(y) + "\" x2=\"" + px(layout.legend_x + 18) +
             "\" y2=\"" + px(y) + "\" stroke=\"" + colour(s) + "\" stroke-width=\"1.6\"/>\n";
      svg += marker(s, layout.legend_x + 9, y, name);
    } else {
      svg += "<rect x=\"" + px(layout.legend_x) + "\" y=\"" + px(y - 6) + "\" width=\"18\" height=\"12\" fill=\"" +
             colour(s) + "\"/>\n";
    }
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
  svg += legend(chart, layout, false);
  svg += "</svg>\n";
  return svg;
}

std::string lineChartSvg(const Chart& chart, bool standalone) {
  chart.validate();
  const double min_band = 22 + 1.5 * static_cast<double>(chart.series.size());
  const Layout layout = layOut(chart, min_band);
  std::string svg = openSvg(chart, layout, standalone, "line chart") + axes(chart, layout);
  const std::size_t n_series = chart.series.size();
  const double nudge = n_series > 1 ? std::min(3.0, layout.band * 0.5 / static_cast<double>(n_series)) : 0.0;
  std::string markers;
  for (std::size_t s = 0; s < n_series; ++s) {
    const double offset = (static_cast<double>(s) - static_cast<double>(n_series - 1) / 2) * nudge;
    std::string d;
    bool pen_down = false;
    for (std::size_t c = 0; c < chart.categories.size(); ++c) {
      const double value = chart.series[s].values[c];
      if (std::isnan(value)) {
        pen_down = false;
        continue;
      }
      const double x = kLeft + (static_cast<double>(c) + 0.5) * layout.band + offset;
      const double y = valueY(chart, value);
      d += (pen_down ? "L" : "M") + px(x) + " " + px(y);
      pen_down = true;
      markers += marker(s, x, y, tooltip(chart, s, c));
    }
    if (!d.empty()) {
      svg += "<path d=\"" + d + "\" fill=\"none\" stroke=\"" + colour(s) +
             "\" stroke-width=\"1.6\" stroke-opacity=\"0.75\"/>\n";
    }
  }
  svg += markers;  // above every line
  svg += legend(chart, layout, true);
  svg += "</svg>\n";
  return svg;
}

}  // namespace simulator
}  // namespace ppp
