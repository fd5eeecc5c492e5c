#include "geometry/Exact.h"

#include <CGAL/Boolean_set_operations_2.h>

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

Vec2 toDouble(const Point& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

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

bool interiorsIntersect(const Ring& a, const Ring& b) {
  Polygon pa = toExact(a), pb = toExact(b);
  if (pa.is_clockwise_oriented()) pa.reverse_orientation();
  if (pb.is_clockwise_oriented()) pb.reverse_orientation();
  return CGAL::do_intersect(pa, pb);
}

}  // namespace mms::exact
