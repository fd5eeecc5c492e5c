#pragma once
// The exact world: CGAL's exact-construction kernel, rotations by rational tan(theta/2) so a
// rotated robot has exact rational vertices, and the only conversions between exact and
// double geometry in the code base.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <array>
#include <vector>

#include "mms/Geometry.h"

namespace mms::exact {

using Kernel = CGAL::Epeck;
using FT = Kernel::FT;
using Point = Kernel::Point_2;
using Polygon = CGAL::Polygon_2<Kernel>;

/// The exact kernel's number type (rationals), behind the lazy one.
using ExactFT = Kernel::Exact_kernel::FT;

/// A point born exact: its exact coordinates and their intervals are stored at once, so a
/// predicate that its interval cannot decide reads the rationals instead of first evaluating a
/// lazy construction of two lazy numbers. CGAL's call_once still runs, once per point and with
/// nothing to compute, instead of once for the point and once for each coordinate.
inline Point exactPoint(const ExactFT& x, const ExactFT& y) {
  return Point(Point::Rep(Kernel::Exact_kernel::Point_2(x, y)));
}

/// An angle whose rotation is exact: rotation by 2*atan(t), then by pi when `half` is set.
/// With |t| <= 1 every angle is reachable, including pi (t = 0, half = true), which plain
/// tan(theta/2) cannot express.
struct RationalAngle {
  FT t = 0;
  bool half = false;
  double radians() const;  // in (-pi, pi]
  /// cos and sin of the angle, exactly: ((1 - t^2), 2t) / (1 + t^2), negated for `half`.
  std::pair<FT, FT> cosSin() const;
};

/// The rational angle nearest to theta with tan denominator 2^bits (|error| < 2^-bits rad).
RationalAngle rationalAngleNear(double theta, int bits = 24);

Point toExact(Vec2 v);
Polygon toExact(const Ring& ring);
Vec2 toDouble(const Point& p);
Ring toDouble(const Polygon& poly);

/// The polygon rotated by `angle` about the origin, exactly.
Polygon rotated(const Polygon& poly, const RationalAngle& angle);

/// The Minkowski sum of two convex polygons (either orientation), exactly: their edges merged
/// in order of angle, n + m exact additions where the hull of all n * m vertex sums took a
/// quarter of a two-disc plan. Counter-clockwise from its lowest (then leftmost) vertex, without
/// collinear or repeated vertices. Its vertices store their exact value (no lazy construction
/// to evaluate). Empty when either polygon has no area.
Polygon convexMinkowskiSum(const Polygon& a, const Polygon& b);

/// Exact predicate: the interiors of the two simple polygons (given in doubles, taken as
/// exact values) intersect. Touching boundaries do not count. The independent reference for
/// the floating-point collision checker.
bool interiorsIntersect(const Ring& a, const Ring& b);

/// A polygon with holes in doubles (import only: scenes hold simple polygons). The outer
/// boundary may touch itself at vertices (as CGAL's unions do).
struct PolygonWithHoles {
  Ring outer;
  std::vector<Ring> holes;
  /// When there are holes: simple convex polygons with disjoint interiors whose union is the
  /// polygon (CGAL's vertical decomposition of the exact union).
  std::vector<Ring> convexPieces;
};

/// The union of triangles, computed exactly (CGAL's aggregated join) from the doubles taken as
/// exact values, as polygons with holes; collinear boundary vertices are dropped before the
/// result is rounded to doubles. Triangles of zero area are skipped and counted in
/// `degenerate`.
std::vector<PolygonWithHoles> unionOfTriangles(const std::vector<std::array<Vec2, 3>>& triangles,
                                               size_t& degenerate);

/// The convex hull of the points (exact predicates), counter-clockwise.
Ring convexHull(const std::vector<Vec2>& points);

}  // namespace mms::exact
