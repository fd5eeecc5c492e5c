#include "manifolds/Pivot.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Min_circle_2.h>
#include <CGAL/Min_circle_2_traits_2.h>

#include <algorithm>
#include <cmath>

#include "geometry/Exact.h"
#include "geometry/PolygonOps.h"
#include "manifolds/OneRobot.h"

namespace mms {

const ManifoldFamily PivotLineManifold::kFamily{"pivot-line"};

Disc smallestCircle(const Ring& ring) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Traits = CGAL::Min_circle_2_traits_2<K>;
  std::vector<K::Point_2> points;
  for (const Vec2 v : ring) points.emplace_back(v.x, v.y);
  CGAL::Random random(1);  // the circle is unique; the seed fixes only the work's order
  // GCC 12 takes the empty traits object passed by reference for uninitialised.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
  const CGAL::Min_circle_2<Traits> circle(points.begin(), points.end(), true, random);
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
  const K::Point_2 c = circle.circle().center();
  return {{CGAL::to_double(c.x()), CGAL::to_double(c.y())},
          std::sqrt(CGAL::to_double(circle.circle().squared_radius()))};
}

// On a grid fine against the shape (a pocket's play is a few hundredths of its size); among
// discs within a grid step of the largest, the one nearest the reference point.
std::optional<Disc> pocketDisc(const Ring& shape) {
  const Ring hull = exact::convexHull(std::vector<Vec2>(shape.begin(), shape.end()));
  const Box b = boundingBox(hull);
  constexpr int kGrid = 160;
  const double step = std::max(b.width(), b.height()) / kGrid;
  auto depth = [&](Vec2 p) {
    if (!insideRing(hull, p) || insideRing(shape, p)) return 0.0;
    return std::min(distanceToEdges(shape, p), distanceToEdges(hull, p));
  };
  std::vector<Disc> discs;
  double deepest = 0;
  for (int i = 0; i <= kGrid; ++i)
    for (int j = 0; j <= kGrid; ++j) {
      const Vec2 p{b.xmin + step * i, b.ymin + step * j};
      if (const double d = depth(p); d > 0) {
        discs.push_back({p, d});
        deepest = std::max(deepest, d);
      }
    }
  if (deepest < 2 * step) return std::nullopt;
  std::optional<Disc> best;
  for (const Disc& c : discs)
    if (c.radius >= deepest - step && (!best || norm(c.center) < norm(best->center))) best = c;
  return best;
}

LineWorld pivotWorld(const Scene& scene, Vec2 pivot) {
  Ring moved;
  for (const Vec2 v : scene.robots.at(0).shape) moved.push_back(v - pivot);
  return LineWorld({moved}, scene.obstacles, scene.bounds);
}

PivotLineManifold::PivotLineManifold(const LineWorld& world, const PoseTest& robotFree, Vec2 pivot,
                                     Vec2 at, LineStats* stats)
    : pivot_(pivot),
      line_(
          world,
          [&](const Pose& p) {
            const Vec2 ref = Vec2{p.x, p.y} - Transform({0, 0, p.theta})(pivot);
            return robotFree({ref.x, ref.y, p.theta});
          },
          at, stats) {}

Config PivotLineManifold::at(double theta) const {
  const Vec2 ref = line_.point() - Transform({0, 0, theta})(pivot_);
  return {ref.x, ref.y, theta};
}

std::optional<std::vector<Config>> PivotLineManifold::motion(size_t cell, const Config& from,
                                                             const Config& to) const {
  const double theta = from[2], turn = line_.arcs()[cell].turn(theta, to[2]);
  const int steps = std::max(1, int(std::ceil(std::abs(turn) / kStep)));
  std::vector<Config> out;
  for (int i = 1; i <= steps; ++i) out.push_back(at(theta + turn * i / steps));
  return out;
}

bool meetPivotSlice(const Manifold& pivotLine, const Manifold& slice, Config& at) {
  const auto& s = static_cast<const SliceManifold&>(slice);
  if (s.frame().robots != 1 || !s.frame().held.empty()) return false;
  at = static_cast<const PivotLineManifold&>(pivotLine).at(s.fixedAt().theta);
  return true;
}

}  // namespace mms
