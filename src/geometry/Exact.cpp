#include "geometry/Exact.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_vertical_decomposition_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <cmath>

namespace mms::exact {

double RationalAngle::radians() const {
  const double a = 2 * std::atan(CGAL::to_double(t));
  if (!half) return a;
  return a > 0 ? a - M_PI : a + M_PI;
}

std::pair<FT, FT> RationalAngle::cosSin() const {
  const FT d = 1 + t * t;
  FT c = (1 - t * t) / d, s = 2 * t / d;
  if (half) return {-c, -s};
  return {c, s};
}

RationalAngle rationalAngleNear(double theta, int bits) {
  // Wrap to (-pi, pi], then fold angles beyond +-pi/2 onto the half turn so |t| <= 1.
  double a = std::remainder(theta, 2 * M_PI);
  RationalAngle r;
  if (a > M_PI_2 || a < -M_PI_2) {
    r.half = true;
    a = a > 0 ? a - M_PI : a + M_PI;
  }
  const double scale = std::ldexp(1.0, bits);
  r.t = FT(std::nearbyint(std::tan(a / 2) * scale)) / FT(scale);  // both exact doubles
  return r;
}

Point toExact(Vec2 v) { return Point(v.x, v.y); }

Polygon toExact(const Ring& ring) {
  Polygon p;
  for (Vec2 v : ring) p.push_back(toExact(v));
  return p;
}

namespace {
// CGAL's to_double settles for an interval 1e-5 wide relative to the value; callers here (point
// location in doubles, with margins of 1e-9) need far closer, so an interval wider than 1e-12
// is refined by the exact value. Intervals are rarely that wide: this costs nothing in general.
double nearestDouble(const FT& v) {
  const std::pair<double, double> i = CGAL::to_interval(v);
  if (i.second - i.first <= 1e-12 * (1 + std::max(std::fabs(i.first), std::fabs(i.second))))
    return 0.5 * i.first + 0.5 * i.second;
  return CGAL::to_double(CGAL::exact(v));
}
}  // namespace

Vec2 toDouble(const Point& p) { return {nearestDouble(p.x()), nearestDouble(p.y())}; }

Ring toDouble(const Polygon& poly) {
  Ring r;
  for (const Point& p : poly.vertices()) r.push_back(toDouble(p));
  return r;
}

Polygon rotated(const Polygon& poly, const RationalAngle& angle) {
  const auto [c, s] = angle.cosSin();
  Polygon out;
  for (const Point& p : poly.vertices())
    out.push_back(Point(c * p.x() - s * p.y(), s * p.x() + c * p.y()));
  return out;
}

namespace {

using ExactPoint = Kernel::Exact_kernel::Point_2;
using ExactVector = Kernel::Exact_kernel::Vector_2;

// A convex polygon's vertices, exact, counter-clockwise from its lowest (then leftmost) vertex,
// without repeated or collinear vertices: its edges then turn strictly left, in order of angle
// from 0 to 2 pi. Fewer than three when it has no area.
std::vector<ExactPoint> convexFromLowest(const Polygon& poly) {
  std::vector<ExactPoint> v;
  v.reserve(poly.size());
  for (const Point& p : poly.vertices())
    if (v.empty() || CGAL::exact(p) != v.back()) v.push_back(CGAL::exact(p));
  while (v.size() > 1 && v.front() == v.back()) v.pop_back();
  const size_t n = v.size();
  // A convex polygon turns one way at every vertex that is not collinear.
  CGAL::Orientation turn = CGAL::COLLINEAR;
  for (size_t i = 0; i < n && turn == CGAL::COLLINEAR; ++i)
    turn = CGAL::orientation(v[(i + n - 1) % n], v[i], v[(i + 1) % n]);
  if (turn == CGAL::RIGHT_TURN) std::reverse(v.begin(), v.end());
  std::vector<ExactPoint> out;
  out.reserve(n);
  for (size_t i = 0; i < n; ++i)
    if (CGAL::orientation(v[(i + n - 1) % n], v[i], v[(i + 1) % n]) == CGAL::LEFT_TURN)
      out.push_back(v[i]);
  const auto lowest = std::min_element(out.begin(), out.end(), [](const auto& p, const auto& q) {
    return p.y() < q.y() || (p.y() == q.y() && p.x() < q.x());
  });
  std::rotate(out.begin(), lowest, out.end());
  return out;
}

// Whether direction d's angle in [0, 2 pi) is below e's.
bool angleBelow(const ExactVector& d, const ExactVector& e) {
  auto upper = [](const ExactVector& v) { return v.y() > 0 || (v.y() == 0 && v.x() > 0); };
  if (upper(d) != upper(e)) return upper(d);
  return CGAL::orientation(d, e) == CGAL::LEFT_TURN;
}

}  // namespace

Polygon convexMinkowskiSum(const Polygon& a, const Polygon& b) {
  const std::vector<ExactPoint> p = convexFromLowest(a), q = convexFromLowest(b);
  const size_t n = p.size(), m = q.size();
  Polygon sum;
  if (n < 3 || m < 3) return sum;
  size_t i = 0, j = 0;
  while (i < n || j < m) {
    const ExactPoint& u = p[i % n];
    const ExactPoint& w = q[j % m];
    sum.push_back(exactPoint(u.x() + w.x(), u.y() + w.y()));
    if (i == n) {
      ++j;
    } else if (j == m) {
      ++i;
    } else {
      const ExactVector d = p[(i + 1) % n] - u, e = q[(j + 1) % m] - w;
      if (angleBelow(d, e))
        ++i;
      else if (angleBelow(e, d))
        ++j;
      else
        ++i, ++j;  // parallel edges, same direction: one edge of the sum
    }
  }
  return sum;
}

bool interiorsIntersect(const Ring& a, const Ring& b) {
  Polygon pa = toExact(a), pb = toExact(b);
  if (pa.is_clockwise_oriented()) pa.reverse_orientation();
  if (pb.is_clockwise_oriented()) pb.reverse_orientation();
  return CGAL::do_intersect(pa, pb);
}

namespace {

using PolygonWithHolesE = CGAL::Polygon_with_holes_2<Kernel>;

// Drops vertices whose neighbours are collinear with them (the union keeps the corners of the
// triangles it merged along straight edges), exactly, before rounding.
Ring roundedWithoutCollinear(const Polygon& poly) {
  std::vector<Point> pts(poly.vertices_begin(), poly.vertices_end());
  bool changed = true;
  while (changed && pts.size() > 3) {
    changed = false;
    for (size_t i = 0; i < pts.size() && pts.size() > 3; ++i) {
      const Point& a = pts[(i + pts.size() - 1) % pts.size()];
      const Point& c = pts[(i + 1) % pts.size()];
      if (CGAL::collinear(a, pts[i], c)) {
        pts.erase(pts.begin() + long(i));
        changed = true;
        --i;
      }
    }
  }
  Ring r;
  for (const Point& p : pts) r.push_back(toDouble(p));
  return r;
}

}  // namespace

std::vector<PolygonWithHoles> unionOfTriangles(const std::vector<std::array<Vec2, 3>>& triangles,
                                               size_t& degenerate) {
  degenerate = 0;
  std::vector<Polygon> pieces;
  for (const auto& t : triangles) {
    Polygon p;
    for (const Vec2& v : t) p.push_back(toExact(v));
    const CGAL::Orientation o = CGAL::orientation(p[0], p[1], p[2]);
    if (o == CGAL::COLLINEAR) {
      ++degenerate;
      continue;
    }
    if (o == CGAL::CLOCKWISE) p.reverse_orientation();
    pieces.push_back(std::move(p));
  }
  std::vector<PolygonWithHolesE> joined;
  if (!pieces.empty()) CGAL::join(pieces.begin(), pieces.end(), std::back_inserter(joined));
  std::vector<PolygonWithHoles> out;
  for (const PolygonWithHolesE& pwh : joined) {
    PolygonWithHoles r;
    r.outer = roundedWithoutCollinear(pwh.outer_boundary());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) {
      Polygon hole = *h;
      hole.reverse_orientation();  // counter-clockwise, like every ring of a scene
      r.holes.push_back(roundedWithoutCollinear(hole));
    }
    if (pwh.has_holes()) {
      // Decomposed here, from the exact union as CGAL produced it (valid input for it).
      std::vector<Polygon> pieces;
      CGAL::Polygon_vertical_decomposition_2<Kernel> decompose;
      decompose(pwh, std::back_inserter(pieces));
      for (Polygon& p : pieces) {
        if (p.is_clockwise_oriented()) p.reverse_orientation();
        r.convexPieces.push_back(roundedWithoutCollinear(p));
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

Ring convexHull(const std::vector<Vec2>& points) {
  std::vector<Point> in, out;
  for (Vec2 v : points) in.push_back(toExact(v));
  CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(out));
  Ring r;
  for (const Point& p : out) r.push_back(toDouble(p));
  return r;
}

}  // namespace mms::exact
