#include "render/Plot.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "util/Markup.h"

namespace mms {

namespace {

std::string tickLabel(double v) {
  std::ostringstream o;
  o << std::setprecision(6) << v;
  return o.str();
}

// Tick values covering [lo, hi]: powers of ten on a log axis, 1-2-5 steps on a linear one.
std::vector<double> ticks(double lo, double hi, bool log) {
  std::vector<double> t;
  if (log) {
    for (double e = std::floor(std::log10(lo)); e <= std::ceil(std::log10(hi)); ++e) {
      double v = std::pow(10.0, e);
      if (v >= lo * 0.999 && v <= hi * 1.001) t.push_back(v);
    }
    return t;
  }
  double span = hi - lo, raw = span / 6, mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = raw / mag < 2 ? 2 * mag : raw / mag < 5 ? 5 * mag : 10 * mag;
  if (raw / mag < 1.5) step = mag;
  for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step) t.push_back(v);
  return t;
}

// One series: its line, markers or crosses, error bars and labels, and its legend entry at the
// plot's right edge `right` (row `legendRow`, counted up when it has a name).
template <class Usable, class Fx, class Fy>
void drawSeries(std::ostringstream& svg, const Series& s, size_t i, const Usable& usable,
                const Fx& fx, const Fy& fy, double right, double top, size_t& legendRow) {
  std::ostringstream pts;
  pts << std::fixed << std::setprecision(1);
  for (auto [x, y] : s.points)
    if (usable(x, y)) pts << fx(x) << "," << fy(y) << " ";
  if (s.line)
    svg << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"1.6\""
        << (s.dashed ? " stroke-dasharray=\"5,4\"" : "") << " points=\"" << pts.str() << "\"/>\n";
  for (size_t k = 0; k < s.points.size(); ++k) {
    const auto [x, y] = s.points[k];
    if (!usable(x, y)) continue;
    if (k < s.bars.size() && usable(x, s.bars[k].first) && usable(x, s.bars[k].second))
      svg << "<line x1=\"" << fx(x) << "\" y1=\"" << fy(s.bars[k].first) << "\" x2=\"" << fx(x)
          << "\" y2=\"" << fy(s.bars[k].second) << "\" stroke=\"" << s.colour << "\"/>\n";
    if (s.markers && s.cross)
      svg << "<path d=\"M" << fx(x) - 4 << "," << fy(y) - 4 << "l8,8m0,-8l-8,8\" stroke=\""
          << s.colour << "\" stroke-width=\"2\"/>\n";
    else if (s.markers)
      svg << "<circle cx=\"" << fx(x) << "\" cy=\"" << fy(y) << "\" r=\"2.6\" fill=\"" << s.colour
          << "\"/>\n";
    if (k < s.labels.size() && !s.labels[k].empty())
      svg << "<text x=\"" << fx(x) << "\" y=\"" << fy(y) - 8 - 10 * double(i % 3)
          << "\" text-anchor=\"middle\" font-size=\"9\" fill=\"" << s.colour << "\">"
          << escapeMarkup(s.labels[k]) << "</text>\n";
  }
  if (s.name.empty()) return;
  double ly = top + 8 + 18 * double(legendRow++);
  svg << "<line x1=\"" << right + 12 << "\" y1=\"" << ly << "\" x2=\"" << right + 34 << "\" y2=\""
      << ly << "\" stroke=\"" << s.colour << "\" stroke-width=\"2\""
      << (s.dashed ? " stroke-dasharray=\"5,4\"" : "") << "/>\n<text x=\"" << right + 40
      << "\" y=\"" << ly + 4 << "\">" << escapeMarkup(s.name) << "</text>\n";
}

// The document's opening: its size, a white ground and the title; numbers to a tenth of a pixel.
void openSvg(std::ostringstream& svg, const PlotSpec& spec) {
  svg << std::fixed << std::setprecision(1);
  svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
      << "width=\"" << spec.width << "\" height=\"" << spec.height << "\" viewBox=\"0 0 "
      << spec.width << " " << spec.height << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << spec.width / 2 << "\" y=\"20\" text-anchor=\"middle\" font-size=\"14\">"
      << escapeMarkup(spec.title) << "</text>\n";
}

}  // namespace

const char* seriesColour(size_t i) {
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                  "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
  return colours[i % 8];
}

std::string linePlot(const PlotSpec& spec, const std::vector<Series>& series) {
  auto usable = [&](double x, double y) {
    return std::isfinite(x) && std::isfinite(y) && (!spec.logX || x > 0) && (!spec.logY || y > 0);
  };
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  auto extend = [&](double x, double y) {
    if (!usable(x, y)) return;
    x0 = std::min(x0, x), x1 = std::max(x1, x);
    y0 = std::min(y0, y), y1 = std::max(y1, y);
  };
  for (const Series& s : series)
    for (size_t i = 0; i < s.points.size(); ++i) {
      extend(s.points[i].first, s.points[i].second);
      if (i < s.bars.size()) {
        extend(s.points[i].first, s.bars[i].first);
        extend(s.points[i].first, s.bars[i].second);
      }
    }
  for (const auto& [y, label] : spec.rules)
    if (x0 <= x1) extend(x0, y);
  if (!(x0 <= x1)) x0 = 1, x1 = 10, y0 = 1, y1 = 10;
  if (spec.logX)
    x0 = std::pow(10.0, std::floor(std::log10(x0))), x1 = std::pow(10.0, std::ceil(std::log10(x1)));
  if (spec.logY)
    y0 = std::pow(10.0, std::floor(std::log10(y0))), y1 = std::pow(10.0, std::ceil(std::log10(y1)));
  if (x0 == x1) x0 -= 1, x1 += 1;
  if (y0 == y1) y0 = spec.logY ? y0 / 10 : y0 - 1, y1 = spec.logY ? y1 * 10 : y1 + 1;
  if (!spec.logY && y0 > 0 && y0 < 0.3 * y1) y0 = 0;

  const double left = 70, right = 190, top = 36, bottom = 52;
  const double pw = spec.width - left - right, ph = spec.height - top - bottom;
  auto fx = [&](double x) {
    double t = spec.logX ? std::log(x / x0) / std::log(x1 / x0) : (x - x0) / (x1 - x0);
    return left + t * pw;
  };
  auto fy = [&](double y) {
    double t = spec.logY ? std::log(y / y0) / std::log(y1 / y0) : (y - y0) / (y1 - y0);
    return top + (1 - t) * ph;
  };

  std::ostringstream svg;
  openSvg(svg, spec);
  for (double t : ticks(x0, x1, spec.logX)) {
    svg << "<line x1=\"" << fx(t) << "\" y1=\"" << top << "\" x2=\"" << fx(t) << "\" y2=\""
        << top + ph << "\" stroke=\"#eee\"/>\n<text x=\"" << fx(t) << "\" y=\"" << top + ph + 16
        << "\" text-anchor=\"middle\">" << tickLabel(t) << "</text>\n";
  }
  for (double t : ticks(y0, y1, spec.logY)) {
    svg << "<line x1=\"" << left << "\" y1=\"" << fy(t) << "\" x2=\"" << left + pw << "\" y2=\""
        << fy(t) << "\" stroke=\"#eee\"/>\n<text x=\"" << left - 6 << "\" y=\"" << fy(t) + 4
        << "\" text-anchor=\"end\">" << tickLabel(t) << "</text>\n";
  }
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
      << "\" fill=\"none\" stroke=\"#444\"/>\n"
      << "<text x=\"" << left + pw / 2 << "\" y=\"" << spec.height - 12
      << "\" text-anchor=\"middle\">" << escapeMarkup(spec.xLabel) << "</text>\n"
      << "<text transform=\"translate(16," << top + ph / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << escapeMarkup(spec.yLabel) << "</text>\n";
  for (const auto& [y, label] : spec.rules)
    if (usable(x0, y))
      svg << "<line x1=\"" << left << "\" y1=\"" << fy(y) << "\" x2=\"" << left + pw << "\" y2=\""
          << fy(y) << "\" stroke=\"black\" stroke-dasharray=\"4,3\"/>\n<text x=\"" << left + 4
          << "\" y=\"" << fy(y) - 4 << "\">" << escapeMarkup(label) << "</text>\n";
  size_t legendRow = 0;
  for (size_t i = 0; i < series.size(); ++i)
    drawSeries(svg, series[i], i, usable, fx, fy, left + pw, top, legendRow);
  if (!spec.footnote.empty())
    svg << "<text x=\"" << left + pw + 12 << "\" y=\"" << top + 8 + 18 * double(legendRow) + 10
        << "\" font-size=\"10\">" << escapeMarkup(spec.footnote) << "</text>\n";
  svg << "</svg>\n";
  return svg.str();
}

namespace {

// The frame both category charts draw: title, y axis with ticks and label, group names under
// their categories, a legend of the labels. `y` maps a value to its height; `at` gives each
// category's centre.
struct CategoryFrame {
  const PlotSpec& spec;
  double y0, y1;
  static constexpr double left = 70, right = 150, top = 36, bottom = 64;
  double plotWidth() const { return spec.width - left - right; }
  double plotHeight() const { return spec.height - top - bottom; }
  double y(double v) const {
    const double t = spec.logY ? std::log(v / y0) / std::log(y1 / y0) : (v - y0) / (y1 - y0);
    return top + (1 - std::clamp(t, 0.0, 1.0)) * plotHeight();
  }
};

// Each category's x centre: categories of one group together, a gap between groups.
std::vector<double> categoryCentres(const std::vector<Category>& cs, double left, double width,
                                    double& slot) {
  size_t groups = 0;
  for (size_t i = 0; i < cs.size(); ++i) groups += i == 0 || cs[i].group != cs[i - 1].group;
  const double units = double(cs.size()) + 0.8 * double(std::max<size_t>(groups, 1));
  slot = width / std::max(units, 1.0);
  std::vector<double> x;
  double at = left + 0.4 * slot;
  for (size_t i = 0; i < cs.size(); ++i) {
    if (i > 0 && cs[i].group != cs[i - 1].group) at += 0.8 * slot;
    x.push_back(at + slot / 2);
    at += slot;
  }
  return x;
}

// One category at `x`, `half` wide each side: a bar to its value, or a box of its values.
void drawCategory(std::ostringstream& svg, const CategoryFrame& f, const Category& c, double x,
                  double half, bool boxes) {
  std::vector<double> v;
  for (double d : c.values)
    if (std::isfinite(d) && (!f.spec.logY || d > 0)) v.push_back(d);
  std::sort(v.begin(), v.end());
  if (!boxes && !v.empty()) {
    const double base = f.spec.logY ? f.y0 : std::max(f.y0, 0.0);
    svg << "<rect x=\"" << x - half << "\" y=\"" << f.y(v.back()) << "\" width=\"" << 2 * half
        << "\" height=\"" << f.y(base) - f.y(v.back()) << "\" fill=\"" << c.colour << "\"/>\n";
  } else if (!v.empty()) {
    auto q = [&](double p) {  // the p-quantile, interpolated
      const double at = p * double(v.size() - 1);
      const size_t k = size_t(at);
      return k + 1 < v.size() ? v[k] + (at - double(k)) * (v[k + 1] - v[k]) : v[k];
    };
    svg << "<line x1=\"" << x << "\" y1=\"" << f.y(v.front()) << "\" x2=\"" << x << "\" y2=\""
        << f.y(v.back()) << "\" stroke=\"" << c.colour << "\"/>\n"
        << "<rect x=\"" << x - half << "\" y=\"" << f.y(q(0.75)) << "\" width=\"" << 2 * half
        << "\" height=\"" << std::max(1.0, f.y(q(0.25)) - f.y(q(0.75))) << "\" fill=\"white\" "
        << "stroke=\"" << c.colour << "\" stroke-width=\"1.5\"/>\n"
        << "<line x1=\"" << x - half << "\" y1=\"" << f.y(q(0.5)) << "\" x2=\"" << x + half
        << "\" y2=\"" << f.y(q(0.5)) << "\" stroke=\"" << c.colour << "\" stroke-width=\"2.5\"/>\n";
    for (double d : v)
      svg << "<circle cx=\"" << x << "\" cy=\"" << f.y(d) << "\" r=\"1.6\" fill=\"" << c.colour
          << "\" fill-opacity=\"0.6\"/>\n";
  }
  if (!c.note.empty())
    svg << "<text x=\"" << x << "\" y=\"" << CategoryFrame::top + f.plotHeight() + 14
        << "\" text-anchor=\"middle\" font-size=\"9\" fill=\"" << c.colour << "\">"
        << escapeMarkup(c.note) << "</text>\n";
}

std::string categoryChart(const PlotSpec& spec, const std::vector<Category>& cs, bool boxes) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Category& c : cs)
    for (double v : c.values)
      if (std::isfinite(v) && (!spec.logY || v > 0)) lo = std::min(lo, v), hi = std::max(hi, v);
  for (const auto& [v, label] : spec.rules) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(lo <= hi)) lo = 1, hi = 10;
  if (!boxes && !spec.logY) lo = std::min(lo, 0.0);
  if (spec.logY)
    lo = std::pow(10.0, std::floor(std::log10(lo))), hi = std::pow(10.0, std::ceil(std::log10(hi)));
  if (lo == hi) lo = spec.logY ? lo / 10 : lo - 1, hi = spec.logY ? hi * 10 : hi + 1;
  const CategoryFrame f{spec, lo, hi};
  double slot = 0;
  const std::vector<double> x = categoryCentres(cs, CategoryFrame::left, f.plotWidth(), slot);
  const double half = std::min(0.32 * slot, 18.0);
  std::ostringstream svg;
  openSvg(svg, spec);
  const double left = CategoryFrame::left, top = CategoryFrame::top, pw = f.plotWidth(),
               ph = f.plotHeight();
  for (double t : ticks(lo, hi, spec.logY))
    svg << "<line x1=\"" << left << "\" y1=\"" << f.y(t) << "\" x2=\"" << left + pw << "\" y2=\""
        << f.y(t) << "\" stroke=\"#eee\"/>\n<text x=\"" << left - 6 << "\" y=\"" << f.y(t) + 4
        << "\" text-anchor=\"end\">" << tickLabel(t) << "</text>\n";
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
      << "\" fill=\"none\" stroke=\"#444\"/>\n"
      << "<text transform=\"translate(16," << top + ph / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << escapeMarkup(spec.yLabel) << "</text>\n";
  for (const auto& [v, label] : spec.rules)
    svg << "<line x1=\"" << left << "\" y1=\"" << f.y(v) << "\" x2=\"" << left + pw << "\" y2=\""
        << f.y(v) << "\" stroke=\"black\" stroke-dasharray=\"4,3\"/>\n<text x=\"" << left + 4
        << "\" y=\"" << f.y(v) - 4 << "\">" << escapeMarkup(label) << "</text>\n";
  std::vector<std::pair<std::string, std::string>> legend;  // label, colour
  for (size_t i = 0; i < cs.size(); ++i) {
    const Category& c = cs[i];
    if (std::none_of(legend.begin(), legend.end(),
                     [&](const auto& l) { return l.first == c.label; }))
      legend.push_back({c.label, c.colour});
    drawCategory(svg, f, c, x[i], half, boxes);
    if (i == 0 || c.group != cs[i - 1].group) {
      size_t n = i;
      while (n < cs.size() && cs[n].group == c.group) ++n;
      svg << "<text x=\"" << (x[i] + x[n - 1]) / 2 << "\" y=\"" << top + ph + 34
          << "\" text-anchor=\"middle\">" << escapeMarkup(c.group) << "</text>\n";
    }
  }
  for (size_t k = 0; k < legend.size(); ++k) {
    const double ly = top + 8 + 18 * double(k);
    svg << "<rect x=\"" << left + pw + 12 << "\" y=\"" << ly - 6 << "\" width=\"16\" height=\"12\" "
        << "fill=\"" << legend[k].second << "\"/>\n<text x=\"" << left + pw + 34 << "\" y=\""
        << ly + 4 << "\">" << escapeMarkup(legend[k].first) << "</text>\n";
  }
  if (!spec.footnote.empty())
    svg << "<text x=\"" << left << "\" y=\"" << spec.height - 10 << "\" font-size=\"10\">"
        << escapeMarkup(spec.footnote) << "</text>\n";
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace

std::string boxPlot(const PlotSpec& spec, const std::vector<Category>& categories) {
  return categoryChart(spec, categories, true);
}

std::string barChart(const PlotSpec& spec, const std::vector<Category>& categories) {
  return categoryChart(spec, categories, false);
}

}  // namespace mms
