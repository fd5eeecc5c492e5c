#pragma once
// Plots as standalone SVG, for every plot mms writes (the lab's reports, the benchmark's
// time-against-tightness plot, its box plots and success charts): line plots with linear or
// log axes, markers or crosses, error bars, point labels, dashed reference curves and lines, a
// legend; box plots and bar charts of categories in groups. Values that a log axis cannot show
// (<= 0) are left out.
#include <string>
#include <utility>
#include <vector>

namespace mms {

struct Series {
  std::string name, colour;  // no name: not in the legend
  std::vector<std::pair<double, double>> points;
  bool dashed = false, markers = true;
  bool line = true;    // join the points
  bool cross = false;  // markers drawn as crosses (e.g. runs that failed)
  /// Per point, when given: an error bar from .first to .second.
  std::vector<std::pair<double, double>> bars{};
  /// Per point, when given: a small label above it.
  std::vector<std::string> labels{};
};

struct PlotSpec {
  std::string title, xLabel, yLabel;
  bool logX = false, logY = false;
  double width = 640, height = 420;
  /// Horizontal reference lines (dashed, labelled), e.g. a time limit.
  std::vector<std::pair<double, std::string>> rules{};
  std::string footnote{};  // under the legend
};

std::string linePlot(const PlotSpec& spec, const std::vector<Series>& series);

/// One category of a box plot or bar chart: drawn side by side with the others of its group
/// (a scene), coloured and named in the legend by its label (a planner).
struct Category {
  std::string group, label, colour;
  std::vector<double> values;  // a box plot's sample; a bar chart's one value
  std::string note{};          // under it, e.g. "2/12 unsolved"
};

/// Boxes (quartiles, the median as a line, whiskers to the extremes, every value as a dot),
/// groups side by side: the spread of times per planner and scene, as Planner Arena shows it.
std::string boxPlot(const PlotSpec& spec, const std::vector<Category>& categories);

/// Bars, one per category, groups side by side: e.g. the share of runs solved.
std::string barChart(const PlotSpec& spec, const std::vector<Category>& categories);

/// A colour per series index, readable on white and distinct for up to eight series.
const char* seriesColour(size_t i);

}  // namespace mms
