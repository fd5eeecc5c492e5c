#include "render/SvgRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "geometry/PolygonOps.h"
#include "render/Palette.h"
#include "util/Markup.h"

namespace mms {
namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string points(const Ring& ring) {
  std::string s;
  for (Vec2 v : ring) s += fmt(v.x) + "," + fmt(v.y) + " ";
  return s;
}

// A robot at a pose, or an obstacle: a disc as a circle, else its polygon (`attributes`
// first, each followed by a space).
std::string element(const Ring& ring, const Disc* disc, const std::string& attributes = "") {
  if (disc)
    return "<circle " + attributes + "cx=\"" + fmt(disc->center.x) + "\" cy=\"" +
           fmt(disc->center.y) + "\" r=\"" + fmt(disc->radius) + "\"/>";
  return "<polygon " + attributes + "points=\"" + points(ring) + "\"/>";
}
std::string robotAt(const Robot& r, const Pose& p, const std::string& attributes = "") {
  const Disc d{{p.x, p.y}, r.disc};
  return element(r.disc > 0 ? Ring{} : placedRing(r.shape, p), r.disc > 0 ? &d : nullptr,
                 attributes);
}

// Cumulative motion along the path (sum over robots of |dp| + radius * |dtheta|), used to
// space ghosts and to time the animation by distance rather than by waypoint count.
std::vector<double> cumulativeEffort(const Scene& scene, const Path& path) {
  std::vector<double> radii;
  for (const Robot& r : scene.robots) radii.push_back(radius(r.shape));
  std::vector<double> acc{0.0};
  for (size_t j = 1; j < path.waypoints.size(); ++j) {
    const Config &a = path.waypoints[j - 1], &b = path.waypoints[j];
    double e = 0;
    for (size_t i = 0; i < scene.robots.size(); ++i)
      e += std::hypot(b[3 * i] - a[3 * i], b[3 * i + 1] - a[3 * i + 1]) +
           radii[i] * std::fabs(b[3 * i + 2] - a[3 * i + 2]);
    acc.push_back(acc.back() + e);
  }
  return acc;
}

Pose poseAtEffort(const Path& path, const std::vector<double>& acc, size_t robot, double e) {
  size_t j = std::upper_bound(acc.begin(), acc.end(), e) - acc.begin();
  if (j == 0) return poseOf(path.waypoints.front(), robot);
  if (j >= acc.size()) return poseOf(path.waypoints.back(), robot);
  const double span = acc[j] - acc[j - 1];
  const double s = span > 0 ? (e - acc[j - 1]) / span : 0;
  const Pose a = poseOf(path.waypoints[j - 1], robot), b = poseOf(path.waypoints[j], robot);
  return {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.theta + s * (b.theta - a.theta)};
}

// The legend's rows: each robot's colour and name, wrapped to the picture's width (a rough
// 7 px per character of the 12 px font).
struct LegendItem {
  double x, y;
  size_t robot;
};
std::vector<LegendItem> legendLayout(const Scene& scene, double left, double right, double top) {
  std::vector<LegendItem> items;
  double x = left, y = top;
  for (size_t i = 0; i < scene.robots.size(); ++i) {
    const double w = 18 + 7.0 * double(scene.robots[i].name.size()) + 14;
    if (x + w > right && x > left) x = left, y += 18;
    items.push_back({x, y, i});
    x += w;
  }
  return items;
}

// The planner's cells and the lines' points, when asked for.
void drawOverlays(std::ostringstream& svg, const SvgOptions& o, double stroke) {
  if (!o.regions.empty()) {
    svg << "<g id=\"cells\" fill=\"#7fbf7f\" fill-opacity=\"0.12\" fill-rule=\"evenodd\" "
           "stroke=\"#2e7d32\" "
        << "stroke-opacity=\"0.6\" stroke-width=\"" << fmt(0.5 * stroke) << "\">\n";
    for (const std::vector<Ring>& region : o.regions) {
      svg << "<path d=\"";
      for (const Ring& r : region) svg << "M" << points(r) << "Z ";
      svg << "\"/>\n";
    }
    svg << "</g>\n";
  }
  if (!o.markers.empty()) {
    svg << "<g id=\"markers\" fill=\"#555\" fill-opacity=\"0.6\">\n";
    for (Vec2 m : o.markers)
      svg << "<circle cx=\"" << fmt(m.x) << "\" cy=\"" << fmt(m.y) << "\" r=\"" << fmt(1.5 * stroke)
          << "\"/>\n";
    svg << "</g>\n";
  }
}

// The waypoints at which robot i's motion changes: the first, the last, and each where it
// starts, stops or bends. Between two of them it moves on one straight segment or stays put, so
// drawing these alone draws the same motion.
std::vector<size_t> turningPoints(const Path& path, size_t i) {
  const std::vector<Config>& w = path.waypoints;
  std::vector<size_t> out;
  auto pose = [&](size_t j) {
    return std::array<double, 3>{w[j][3 * i], w[j][3 * i + 1], w[j][3 * i + 2]};
  };
  for (size_t j = 0; j < w.size(); ++j) {
    if (j == 0 || j + 1 == w.size()) {
      out.push_back(j);
      continue;
    }
    const auto a = pose(j - 1), b = pose(j), c = pose(j + 1);
    // Dropped only inside a stay (equal to both neighbours): the linear motion between the
    // kept waypoints around it holds the robot there all the same.
    if (!(a == b && b == c)) out.push_back(j);
  }
  return out;
}

// Each robot's reference point traced along the path, and faint poses evenly spaced by motion.
void drawTraces(std::ostringstream& svg, const Scene& scene, const Path& path, const SvgOptions& o,
                double stroke) {
  const size_t k = scene.robots.size();
  const std::vector<double> acc = cumulativeEffort(scene, path);
  const double total = acc.back();
  // Traces of the reference points.
  for (size_t i = 0; i < k; ++i) {
    svg << "<polyline fill=\"none\" stroke=\"" << robotColour(i) << "\" stroke-width=\""
        << fmt(stroke) << "\" stroke-dasharray=\"" << fmt(3 * stroke) << " " << fmt(2 * stroke)
        << "\" points=\"";
    for (size_t j : turningPoints(path, i))
      svg << fmt(path.waypoints[j][3 * i]) << "," << fmt(path.waypoints[j][3 * i + 1]) << " ";
    svg << "\"/>\n";
  }
  // Ghost poses evenly spaced by motion.
  svg << "<g id=\"ghosts\" fill=\"#888\" fill-opacity=\"0.08\" stroke=\"#555\" "
         "stroke-opacity=\"0.35\" "
      << "stroke-width=\"" << fmt(0.6 * stroke) << "\">\n";
  for (int g = 1; g < o.ghosts && total > 0; ++g)
    for (size_t i = 0; i < k; ++i)
      svg << robotAt(scene.robots[i], poseAtEffort(path, acc, i, total * g / o.ghosts)) << "\n";
  svg << "</g>\n";
}

// Every robot moving along the path, looped (SVG's own animation: no script).
void drawAnimation(std::ostringstream& svg, const Scene& scene, const Path& path,
                   const SvgOptions& o, double stroke, double extent) {
  const size_t k = scene.robots.size();
  const std::vector<double> acc = cumulativeEffort(scene, path);
  const double total = acc.back();
  const double dur = std::clamp(total / extent * o.secondsPerExtent, 2.0, 120.0);
  auto keyTime = [&](size_t j) {
    return fmt(total > 0 ? acc[j] / total : double(j) / std::max<size_t>(1, acc.size() - 1));
  };
  svg << "<g id=\"animation\">\n";
  for (size_t i = 0; i < k; ++i) {
    // Each robot's own key frames: where it starts or stops moving (hundreds of robots moving
    // one at a time would otherwise each repeat every waypoint).
    std::string moves, turns, keyTimes;
    for (size_t j : turningPoints(path, i)) {
      const Pose p = poseOf(path.waypoints[j], i);
      if (!moves.empty()) moves += ';', turns += ';', keyTimes += ';';
      moves += fmt(p.x) + " " + fmt(p.y);
      turns += fmt(p.theta * 180 / M_PI);
      keyTimes += keyTime(j);
    }
    if (path.waypoints.size() == 1) keyTimes.assign(1, '0');
    const Pose p0 = poseOf(path.waypoints.front(), i);
    const std::string timing = "dur=\"" + fmt(dur) + "s\" keyTimes=\"" + keyTimes +
                               "\" calcMode=\"linear\" repeatCount=\"indefinite\"";
    svg << "<g transform=\"translate(" << fmt(p0.x) << " " << fmt(p0.y) << ")\">"
        << "<animateTransform attributeName=\"transform\" type=\"translate\" values=\"" << moves
        << "\" " << timing << "/>\n"
        << "<g transform=\"rotate(" << fmt(p0.theta * 180 / M_PI) << ")\">"
        << "<animateTransform attributeName=\"transform\" type=\"rotate\" values=\"" << turns
        << "\" " << timing << "/>\n"
        << robotAt(scene.robots[i], {0, 0, 0},
                   "fill=\"" + std::string(k >= 2 ? robotColour(i) : "#f2b01e") +
                       "\" fill-opacity=\"0.9\" stroke=\"#333\" stroke-width=\"" + fmt(stroke) +
                       "\" ")
        << "\n</g></g>\n";
  }
  svg << "</g>\n";
}

}  // namespace

std::string renderSvg(const Scene& scene, const Path* path, const SvgOptions& o) {
  const Box& b = scene.bounds;
  const double extent = std::max(b.width(), b.height());
  const double margin = 20, nameH = scene.name.empty() ? 0 : 24;
  // With two robots or more, a legend under the name: each robot's colour and name.
  const double legendTop = margin + nameH + 10;  // the first row's baseline
  const std::vector<LegendItem> legend =
      scene.robots.size() >= 2 ? legendLayout(scene, margin, o.widthPx - margin, legendTop)
                               : std::vector<LegendItem>{};
  const double titleH = nameH + (legend.empty() ? 0 : legend.back().y - legendTop + 18);
  const double scale = (o.widthPx - 2 * margin) / b.width();
  const double heightPx = b.height() * scale + 2 * margin + titleH;
  const double stroke = extent / 400;

  std::ostringstream svg;
  svg << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(o.widthPx) << "\" height=\""
      << fmt(heightPx) << "\" viewBox=\"0 0 " << fmt(o.widthPx) << " " << fmt(heightPx) << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!scene.name.empty())
    svg << "<text x=\"" << fmt(margin) << "\" y=\"" << fmt(margin + 8)
        << "\" font-family=\"sans-serif\" font-size=\"16\">" << escapeMarkup(scene.name)
        << "</text>\n";
  if (!legend.empty()) {
    svg << "<g id=\"legend\" font-family=\"sans-serif\" font-size=\"12\">\n";
    for (const LegendItem& it : legend)
      svg << "<rect x=\"" << fmt(it.x) << "\" y=\"" << fmt(it.y - 10) << "\" width=\"12\" "
          << "height=\"12\" fill=\"" << robotColour(it.robot) << "\"/><text x=\"" << fmt(it.x + 16)
          << "\" y=\"" << fmt(it.y) << "\">" << escapeMarkup(scene.robots[it.robot].name)
          << "</text>\n";
    svg << "</g>\n";
  }
  // World coordinates: y up, as in the scene file.
  svg << "<g transform=\"translate(" << fmt(margin) << " " << fmt(heightPx - margin) << ") scale("
      << fmt(scale) << " " << fmt(-scale) << ") translate(" << fmt(-b.xmin) << " " << fmt(-b.ymin)
      << ")\" stroke-linejoin=\"round\">\n";
  svg << "<rect x=\"" << fmt(b.xmin) << "\" y=\"" << fmt(b.ymin) << "\" width=\"" << fmt(b.width())
      << "\" height=\"" << fmt(b.height()) << "\" fill=\"#f4f4f0\" stroke=\"#333\" stroke-width=\""
      << fmt(2 * stroke) << "\"/>\n";
  svg << "<g id=\"obstacles\" fill=\"#4a74b4\" stroke=\"#23406e\" stroke-width=\"" << fmt(stroke)
      << "\">\n";
  for (size_t i = 0; i < scene.obstacles.size(); ++i)
    svg << element(scene.obstacles[i], scene.obstacleDisc(i)) << "\n";
  svg << "</g>\n";

  drawOverlays(svg, o, stroke);

  if (path && !path->waypoints.empty()) drawTraces(svg, scene, *path, o, stroke);
  svg << "<g id=\"starts\" fill=\"#2ca02c\" fill-opacity=\"0.55\" stroke=\"#1a631a\" "
         "stroke-width=\""
      << fmt(stroke) << "\">\n";
  for (const Robot& r : scene.robots) svg << robotAt(r, r.start) << "\n";
  svg << "</g>\n<g id=\"goals\" fill=\"#d62728\" fill-opacity=\"0.55\" stroke=\"#7f1516\" "
         "stroke-width=\""
      << fmt(stroke) << "\">\n";
  for (const Robot& r : scene.robots) svg << robotAt(r, r.goal) << "\n";
  svg << "</g>\n";

  if (path && !path->waypoints.empty() && o.animate)
    drawAnimation(svg, scene, *path, o, stroke, extent);
  svg << "</g>\n</svg>\n";
  return svg.str();
}

}  // namespace mms
