#include "ppp_simulator/report/svg_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ppp_core/error.hpp"

namespace ppp::simulator {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

Chart twoByThree() {
  Chart chart;
  chart.title = "Pass <rates> & more";
  chart.x_label = "agent";
  chart.y_label = "pass rate (%)";
  chart.categories = {"astar", "random", "explorer"};
  chart.series = {{"set \"A\"", {100, 12.5, 50}}, {"set B", {100, std::nan(""), 0}}};
  return chart;
}

TEST(GroupedBarChartSvg, DrawsOneBarPerValueWithTooltipsAndEscapedText) {
  const std::string svg = groupedBarChartSvg(twoByThree(), false);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_EQ(count(svg, "</svg>"), 1u);
  // Five values (one missing) → five bars, each with its tooltip.
  EXPECT_EQ(count(svg, "<title>set &quot;A&quot; on "), 3u);
  EXPECT_EQ(count(svg, "<title>set B on "), 2u);
  EXPECT_NE(svg.find("set &quot;A&quot; on random: 12.50%"), std::string::npos);
  EXPECT_NE(svg.find("Pass &lt;rates&gt; &amp; more"), std::string::npos);
  EXPECT_EQ(svg.find("<rates>"), std::string::npos);
  EXPECT_EQ(svg.find("http"), std::string::npos);  // inline: no namespace URL, nothing to fetch
}

TEST(GroupedBarChartSvg, StandaloneHasTheXmlDeclarationAndNamespace) {
  const std::string svg = groupedBarChartSvg(twoByThree(), true);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
}

TEST(HeatMapSvg, OneCellPerValueColouredByRateAndGreyWhereMissing) {
  Chart chart = twoByThree();
  chart.series[1].values = {100, std::nan(""), 0};
  const std::string svg = heatMapSvg(chart, false);
  EXPECT_EQ(count(svg, "<title>set B on "), 3u);
  EXPECT_EQ(count(svg, ": no data</title>"), 1u);
  // 0 % is the scale's red end, 100 % its blue end, 50 % the near-white middle.
  EXPECT_NE(svg.find("fill=\"#b2182b\"><title>set B on"), std::string::npos) << svg;
  EXPECT_NE(svg.find("fill=\"#2166ac\"><title>set B on"), std::string::npos);
  EXPECT_NE(svg.find("fill=\"#cccccc\"><title>set B on"), std::string::npos);
  chart.series[1].values = {50, 50, 50};
  EXPECT_EQ(count(heatMapSvg(chart, false), "fill=\"#f7f7f7\"><title>set B on"), 3u);
}

TEST(Charts, EmptyChartsStillRender) {
  Chart chart;
  chart.title = "nothing";
  EXPECT_NE(groupedBarChartSvg(chart, false).find("no data"), std::string::npos);
  EXPECT_NE(heatMapSvg(chart, false).find("no data"), std::string::npos);
}

TEST(Charts, ManyLongCategoriesAreSlantedAndShortened) {
  Chart chart;
  chart.title = "many";
  for (int i = 0; i < 40; ++i) {
    chart.categories.push_back("a_rather_long_problem_identifier_number_" + std::to_string(i));
  }
  chart.series = {{"x", std::vector<double>(40, 50.0)}};
  const std::string svg = groupedBarChartSvg(chart, false);
  EXPECT_NE(svg.find("rotate(-40)"), std::string::npos);
  EXPECT_NE(svg.find("\xE2\x80\xA6"), std::string::npos);  // ellipsis in the shortened label
  EXPECT_NE(svg.find("<title>a_rather_long_problem_identifier_number_39</title>"), std::string::npos);
}

TEST(Chart, ValidateRejectsMismatchedSeriesAndBadScale) {
  Chart chart = twoByThree();
  chart.series[0].values.pop_back();
  try {
    groupedBarChartSvg(chart, false);
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "series");
  }
  chart = twoByThree();
  chart.y_max = 0;
  try {
    heatMapSvg(chart, false);
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.name(), "y_max");
  }
}

}  // namespace
}  // namespace ppp::simulator

namespace ppp::simulator {
namespace {

TEST(BoxPlotSvg, DrawsOneBoxPerSampleWithItsFiguresAndRefusesMissingBoxes) {
  Chart chart = twoByThree();
  const double none = std::nan("");
  std::vector<std::vector<BoxStats>> boxes = {
      {{1, 1.2, 1.5, 2, 3}, {1, 2, 3, 4, 5}, {1, 1, 1, 1, 1}},
      {{1, 1.1, 1.2, 1.3, 1.4}, {none, none, none, none, none}, {2, 2.5, 3, 3.5, 4}}};
  chart.y_max = 6;
  const std::string svg = boxPlotSvg(chart, boxes, true);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_EQ(count(svg, "<g><title>"), 5u);  // one box left empty
  EXPECT_NE(svg.find("set B on explorer: median 3.00, quartiles 2.50-3.50, 5th-95th percentile 2.00-4.00"),
            std::string::npos);
  boxes[1].pop_back();
  EXPECT_THROW(boxPlotSvg(chart, boxes, false), InvalidArgument);
}

}  // namespace
}  // namespace ppp::simulator
