#pragma once

#include <string>
#include <vector>

namespace ppp {
namespace simulator {

/// One coloured series of a chart: a legend name and one value per category.
struct PlotSeries {
  std::string name;            ///< Legend text.
  std::vector<double> values;  ///< One value per category; NaN where the series has none.
};

/// What a chart shows: categories along x, values from 0 to `y_max` along y, one colour per series.
struct Chart {
  std::string title;                    ///< Drawn above the plot.
  std::string x_label;                  ///< Caption under the x axis (may be empty).
  std::string y_label;                  ///< Caption along the y axis (may be empty).
  std::vector<std::string> categories;  ///< x axis labels, left to right.
  std::vector<PlotSeries> series;       ///< Drawn in order; colours and marker shapes follow the order.
  double y_max = 100;                   ///< Top of the y axis; values are clamped to [0, y_max].
  std::string value_suffix = "%";       ///< Appended to values in tick labels and tooltips.

  /// Checks that y_max is positive and finite and every series has one value per category.
  /// @throws InvalidArgument naming "y_max" or "series".
  void validate() const;
};

/// Grouped bar chart as an `<svg>` element: per category, one bar per series side by side, a legend on the
/// right, each bar with a tooltip. `standalone` adds the XML declaration and SVG namespace a `.svg` file
/// needs; without it the element is meant to be inlined in HTML (and has no URL in it at all).
/// @throws InvalidArgument as Chart::validate().
std::string groupedBarChartSvg(const Chart& chart, bool standalone);

/// Heat map as an `<svg>` element: one row per series, one cell per category, coloured from red (0) through
/// near-white (y_max / 2) to blue (y_max), grey where a value is missing; every cell has a tooltip, columns are
/// numbered (the first, every tenth, the last) and a colour scale is drawn underneath. Readable for dozens of
/// series over hundreds of categories. `standalone` as for groupedBarChartSvg().
/// @throws InvalidArgument as Chart::validate().
std::string heatMapSvg(const Chart& chart, bool standalone);

/// The spread of one sample, as a box plot draws it.
struct BoxStats {
  double p5 = 0;      ///< Lower whisker: the 5th percentile.
  double p25 = 0;     ///< Bottom of the box: the first quartile.
  double median = 0;  ///< The line across the box.
  double p75 = 0;     ///< Top of the box: the third quartile.
  double p95 = 0;     ///< Upper whisker: the 95th percentile.
};

/// Box plot as an `<svg>` element: per category, one box per series side by side (`boxes[series][category]`;
/// a NaN median leaves the slot empty), the box from the first to the third quartile with the median across it,
/// whiskers from the 5th to the 95th percentile, a legend on the right and a tooltip with the five figures.
/// `chart`'s series give the names (their values are unused). `standalone` as for groupedBarChartSvg().
/// @throws InvalidArgument as Chart::validate(), and naming "boxes" unless there is one box per series and category.
std::string boxPlotSvg(const Chart& chart, const std::vector<std::vector<BoxStats>>& boxes, bool standalone);

}  // namespace simulator
}  // namespace ppp
