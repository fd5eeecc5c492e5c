#include "geometry/PolygonOps.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mms {

Box boundingBox(const Ring& ring) {
  Box b{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (Vec2 v : ring) {
    b.xmin = std::min(b.xmin, v.x);
    b.ymin = std::min(b.ymin, v.y);
    b.xmax = std::max(b.xmax, v.x);
    b.ymax = std::max(b.ymax, v.y);
  }
  return b;
}

double signedArea2(const Ring& ring) {
  double a = 0;
  const size_t n = ring.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) a += cross(ring[j], ring[i]);
  return a;
}

double radius(const Ring& ring) {
  double r = 0;
  for (Vec2 v : ring) r = std::max(r, norm(v));
  return r;
}

namespace {
Ring regularPolygon(Vec2 c, double vertexRadius, int sides, double firstAngle) {
  Ring ring;
  for (int i = 0; i < sides; ++i) {
    const double a = firstAngle + 2 * M_PI * i / sides;
    ring.push_back({c.x + vertexRadius * std::cos(a), c.y + vertexRadius * std::sin(a)});
  }
  return ring;
}
}  // namespace

Box discBox(const Disc& d) {
  return {d.center.x - d.radius, d.center.y - d.radius, d.center.x + d.radius,
          d.center.y + d.radius};
}

Ring discStandIn(const Disc& disc, int sides) {
  // Vertices half a step off the axes put edge midpoints on them. The factor keeps rounding
  // from pulling an edge inside the circle.
  const double R = disc.radius / std::cos(M_PI / sides) * (1 + 1e-12);
  return regularPolygon(disc.center, R, sides, M_PI / sides);
}

Ring discInscribed(const Disc& disc, int sides) {
  // Rounding may put a vertex a hair outside: pull it in by as much.
  return regularPolygon(disc.center, disc.radius * (1 - 1e-12), sides, 0);
}

bool insideRing(const Ring& ring, Vec2 p) {
  bool in = false;
  const size_t n = ring.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 a = ring[j], b = ring[i];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double xCross = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < xCross) in = !in;
    }
  }
  return in;
}

namespace {

inline double orient(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); }

// c is known collinear with [a,b]; is it within the segment's box?
inline bool withinBox(Vec2 a, Vec2 b, Vec2 c) {
  return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
         c.y <= std::max(a.y, b.y);
}

inline Box segmentBox(Vec2 a, Vec2 b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
}

}  // namespace

bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double d1 = orient(c, d, a), d2 = orient(c, d, b);
  if ((d1 > 0 && d2 > 0) || (d1 < 0 && d2 < 0)) return false;
  const double d3 = orient(a, b, c), d4 = orient(a, b, d);
  if ((d3 > 0 && d4 > 0) || (d3 < 0 && d4 < 0)) return false;
  if (d1 != 0 || d2 != 0 || d3 != 0 || d4 != 0) return true;
  // All four points collinear: the segments meet when their extents overlap.
  return withinBox(a, b, c) || withinBox(a, b, d) || withinBox(c, d, a) || withinBox(c, d, b);
}

Vec2 closestPointOnSegment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b) {
  return norm(p - closestPointOnSegment(p, a, b));
}

double distanceToEdges(const Ring& ring, Vec2 p) {
  double d = std::numeric_limits<double>::infinity();
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    d = std::min(d, pointSegmentDistance(p, ring[j], ring[i]));
  return d;
}

Disc inscribedDisc(const Ring& ring) {
  // The distance to the boundary inside the ring, -1 outside.
  auto depth = [&](Vec2 p) { return insideRing(ring, p) ? distanceToEdges(ring, p) : -1.0; };
  const Box b = boundingBox(ring);
  constexpr int kGrid = 32;
  Disc best;
  for (int i = 0; i <= kGrid; ++i)
    for (int j = 0; j <= kGrid; ++j) {
      const Vec2 p{b.xmin + b.width() * i / kGrid, b.ymin + b.height() * j / kGrid};
      if (const double d = depth(p); d > best.radius) best = {p, d};
    }
  if (best.radius <= 0) return {};
  // Pattern search: the eight neighbours at a step halved until it is small against the box.
  const double smallest = 1e-4 * std::max(b.width(), b.height());
  for (double step = std::max(b.width(), b.height()) / kGrid; step > smallest;) {
    bool moved = false;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        const Vec2 p = best.center + step * Vec2{double(dx), double(dy)};
        if (const double d = depth(p); d > best.radius) best = {p, d}, moved = true;
      }
    if (!moved) step /= 2;
  }
  return best;
}

namespace {
// Squared distances: the certifier asks for millions of clearances, and one square root per
// pair of rings costs less than a hypot per pair of segments.
double pointSegmentDistance2(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = p - closestPointOnSegment(p, a, b);
  return dot(d, d);
}
double segmentSegmentDistance2(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (segmentsIntersect(a, b, c, d)) return 0.0;
  return std::min(std::min(pointSegmentDistance2(a, c, d), pointSegmentDistance2(b, c, d)),
                  std::min(pointSegmentDistance2(c, a, b), pointSegmentDistance2(d, a, b)));
}
}  // namespace

double segmentSegmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  return std::sqrt(segmentSegmentDistance2(a, b, c, d));
}

bool ringsIntersect(const Ring& a, const Box& boxA, const Ring& b, const Box& boxB) {
  if (!boxA.overlaps(boxB)) return false;
  const size_t n = a.size(), m = b.size();
  for (size_t i = 0, ip = n - 1; i < n; ip = i++) {
    const Vec2 p = a[ip], q = a[i];
    const Box e = segmentBox(p, q);
    if (!e.overlaps(boxB)) continue;
    for (size_t j = 0, jp = m - 1; j < m; jp = j++) {
      const Vec2 r = b[jp], s = b[j];
      if (std::max(r.x, s.x) < e.xmin || std::min(r.x, s.x) > e.xmax ||
          std::max(r.y, s.y) < e.ymin || std::min(r.y, s.y) > e.ymax)
        continue;
      if (segmentsIntersect(p, q, r, s)) return true;
    }
  }
  // No boundary crossing: they meet only if one lies inside the other.
  if (boxB.contains(boxA) && insideRing(b, a[0])) return true;
  if (boxA.contains(boxB) && insideRing(a, b[0])) return true;
  return false;
}

double ringDistance(const Ring& a, const Box& boxA, const Ring& b, const Box& boxB, double bound) {
  if (ringsIntersect(a, boxA, b, boxB)) return 0.0;
  // Squared; a bound just past 0 (a denormal) must not square to 0, or every pair that does
  // not intersect would come out at distance 0, a contact.
  double best2 = bound * bound;
  if (bound > 0 && best2 < std::numeric_limits<double>::min())
    best2 = std::numeric_limits<double>::min();
  const size_t n = a.size(), m = b.size();
  for (size_t i = 0, ip = n - 1; i < n; ip = i++) {
    const Box e = segmentBox(a[ip], a[i]);
    if (e.distance2(boxB) >= best2) continue;
    for (size_t j = 0, jp = m - 1; j < m; jp = j++) {
      if (e.distance2(segmentBox(b[jp], b[j])) >= best2) continue;
      best2 = std::min(best2, segmentSegmentDistance2(a[ip], a[i], b[jp], b[j]));
    }
  }
  return std::sqrt(best2);
}

ShrinkResult shrinkRing(const Ring& ring, double delta) {
  ShrinkResult out;
  const size_t n = ring.size();
  out.ring.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const Vec2 prev = ring[(i + n - 1) % n], v = ring[i], next = ring[(i + 1) % n];
    const Vec2 e1 = v - prev, e2 = next - v;
    // Left normals point inside a counter-clockwise ring.
    const Vec2 n1 = (1.0 / norm(e1)) * Vec2{-e1.y, e1.x};
    const Vec2 n2 = (1.0 / norm(e2)) * Vec2{-e2.y, e2.x};
    const double denom = 1.0 + dot(n1, n2);
    // The mitre point m satisfies m.n1 = m.n2 = delta; a hairpin vertex has no usable mitre.
    if (denom < 1e-12) {
      out.error = "vertex " + std::to_string(i) + " is a hairpin (its edges fold back)";
      return out;
    }
    out.ring[i] = v + (delta / denom) * (n1 + n2);
  }
  return out;
}

}  // namespace mms
