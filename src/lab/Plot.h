#pragma once
// Line plots as standalone SVG for the lab's reports: linear or log axes, markers, dashed
// reference curves, a legend. Points that a log axis cannot show (<= 0) are left out.
#include <string>
#include <utility>
#include <vector>

namespace mms::lab {

struct Series {
  std::string name, colour;
  std::vector<std::pair<double, double>> points;
  bool dashed = false, markers = true;
};

struct PlotSpec {
  std::string title, xLabel, yLabel;
  bool logX = false, logY = false;
  double width = 640, height = 420;
};

std::string linePlot(const PlotSpec& spec, const std::vector<Series>& series);

/// A colour per series index, readable on white and distinct for up to eight series.
const char* seriesColour(size_t i);

}  // namespace mms::lab
