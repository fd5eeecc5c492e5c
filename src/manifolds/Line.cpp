#include "manifolds/Line.h"

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <cmath>

#include "geometry/PolygonOps.h"

namespace mms {

namespace {

constexpr double kTwoPi = 2 * M_PI;

double wrap(double theta) {  // into [-pi, pi)
  double t = std::fmod(theta + M_PI, kTwoPi);
  if (t < 0) t += kTwoPi;
  return t - M_PI;
}

inline Vec2 perp(Vec2 v) { return {-v.y, v.x}; }
inline Vec2 rot(Vec2 v, double c, double s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }

// Sign of A^2 + B^2 - C^2 where A, B, C are given as exact expressions of double inputs.
using Q = CGAL::Exact_rational;

struct Solver {
  LineStats* stats;
  std::vector<double>* out;

  // Roots of A cos t + B sin t + C = 0; `exactDisc` recomputes the discriminant exactly.
  template <class ExactDisc, class OnContact>
  void solve(double A, double B, double C, ExactDisc exactDisc, OnContact onContact) {
    const double r2 = A * A + B * B;
    if (r2 == 0) return;
    const double disc = r2 - C * C;
    // The inputs are exact doubles; A, B, C carry a few roundings each, so the computed
    // discriminant is within ~1e-14 (A^2 + B^2 + C^2) of the true one.
    const double err = 1e-12 * (r2 + C * C);
    double halfWidth;
    if (disc > err) {
      halfWidth = std::acos(std::clamp(-C / std::sqrt(r2), -1.0, 1.0));
    } else if (disc < -err) {
      return;
    } else {
      if (stats) ++stats->exactFallbacks;
      const int sign = exactDisc();
      if (sign < 0) return;
      halfWidth = sign == 0 ? 0.0 : std::acos(std::clamp(-C / std::sqrt(r2), -1.0, 1.0));
    }
    const double phi = std::atan2(B, A);
    onContact(phi + halfWidth);
    if (halfWidth > 0) onContact(phi - halfWidth);
  }
};

int sign(const Q& q) { return q < 0 ? -1 : (q > 0 ? 1 : 0); }

}  // namespace

bool Arc::contains(double theta) const { return unwrap(theta) <= hi; }

double Arc::unwrap(double theta) const {
  double t = std::fmod(theta - lo, kTwoPi);
  if (t < 0) t += kTwoPi;
  return lo + t;
}

LineWorld::LineWorld(const Scene& scene, size_t robot, const std::vector<Ring>& extraObstacles)
    : shapes_{scene.robots[robot].shape}, obstacles_(scene.obstacles), bounds_(scene.bounds) {
  obstacles_.insert(obstacles_.end(), extraObstacles.begin(), extraObstacles.end());
}

LineWorld::LineWorld(std::vector<Ring> shapes, std::vector<Ring> obstacles, const Box& bounds)
    : shapes_(std::move(shapes)), obstacles_(std::move(obstacles)), bounds_(bounds) {}

namespace {
// The critical angles of one ring of the robot, appended to `roots`.
void ringCriticalAngles(const LineWorld& world, const Ring& robot, Vec2 p, LineStats* stats,
                        std::vector<double>& roots) {
  Solver solver{stats, &roots};
  const size_t n = robot.size();
  // Margins keep the filters inclusive: an extra candidate only adds a harmless split.
  constexpr double kSlack = 1e-9;
  double reach = 0;
  std::vector<double> vertexRadius(n);
  for (size_t i = 0; i < n; ++i) reach = std::max(reach, vertexRadius[i] = norm(robot[i]));
  const double reachMargin = reach * (1 + kSlack) + 1e-12;

  auto vertexEdge = [&](Vec2 o1, Vec2 o2) {
    const double dist = pointSegmentDistance(p, o1, o2);
    if (dist > reachMargin) return;
    const Vec2 e = o2 - o1, nrm = perp(e);
    const double len2 = dot(e, e);
    for (size_t i = 0; i < n; ++i) {
      if (dist > vertexRadius[i] * (1 + kSlack) + 1e-12) continue;
      if (stats) ++stats->candidates;
      const Vec2 v = robot[i];
      // nrm . (p + Rot(t) v - o1) = 0 with Rot(t) v = cos t v + sin t perp(v).
      const double A = dot(nrm, v), B = dot(nrm, perp(v)), C = dot(nrm, p - o1);
      auto exactDisc = [&] {
        const Q ex = Q(-o2.y) + Q(o1.y), ey = Q(o2.x) - Q(o1.x);  // perp(e), exactly
        const Q a = ex * Q(v.x) + ey * Q(v.y), b = ex * Q(-v.y) + ey * Q(v.x);
        const Q c = ex * (Q(p.x) - Q(o1.x)) + ey * (Q(p.y) - Q(o1.y));
        return sign(a * a + b * b - c * c);
      };
      solver.solve(A, B, C, exactDisc, [&](double t) {
        const Vec2 w = p + rot(v, std::cos(t), std::sin(t)) - o1;
        const double s = dot(w, e) / len2;
        if (s >= -kSlack && s <= 1 + kSlack) roots.push_back(wrap(t));
      });
    }
  };

  auto edgeVertex = [&](Vec2 o) {
    const Vec2 w = o - p;
    const double dist = norm(w);
    if (dist > reachMargin) return;
    for (size_t i = 0; i < n; ++i) {
      const Vec2 v1 = robot[i], v2 = robot[(i + 1) % n];
      if (dist > std::max(vertexRadius[i], vertexRadius[(i + 1) % n]) * (1 + kSlack) + 1e-12)
        continue;
      if (stats) ++stats->candidates;
      const Vec2 d = v2 - v1;
      const double len2 = dot(d, d);
      // cross(Rot(t) d, w - Rot(t) v1) = 0.
      const double A = cross(d, w), B = -dot(d, w), C = -cross(d, v1);
      auto exactDisc = [&] {
        const Q dx = Q(v2.x) - Q(v1.x), dy = Q(v2.y) - Q(v1.y);
        const Q wx = Q(o.x) - Q(p.x), wy = Q(o.y) - Q(p.y);
        const Q a = dx * wy - dy * wx, b = -(dx * wx + dy * wy), c = -(dx * Q(v1.y) - dy * Q(v1.x));
        return sign(a * a + b * b - c * c);
      };
      solver.solve(A, B, C, exactDisc, [&](double t) {
        const double c = std::cos(t), s = std::sin(t);
        const Vec2 local{c * w.x + s * w.y, -s * w.x + c * w.y};  // Rot(-t) w
        const double u = dot(local - v1, d) / len2;
        if (u >= -kSlack && u <= 1 + kSlack) roots.push_back(wrap(t));
      });
    }
  };

  for (const Ring& o : world.obstacles()) {
    for (size_t j = 0, jp = o.size() - 1; j < o.size(); jp = j++) {
      vertexEdge(o[jp], o[j]);
      edgeVertex(o[j]);
    }
  }
  // The bounds: a vertex leaving the box crosses one of its sides.
  const Box& b = world.bounds();
  const Vec2 corners[4] = {{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}};
  for (int k = 0; k < 4; ++k) vertexEdge(corners[k], corners[(k + 1) % 4]);
}
}  // namespace

std::vector<double> criticalAngles(const LineWorld& world, Vec2 p, LineStats* stats) {
  std::vector<double> roots;
  for (const Ring& robot : world.shapes()) ringCriticalAngles(world, robot, p, stats, roots);
  std::sort(roots.begin(), roots.end());
  if (stats) stats->criticalAngles += roots.size();
  return roots;
}

Line::Line(const LineWorld& world, const PoseTest& isFree, Vec2 p, LineStats* stats) : p_(p) {
  const std::vector<double> roots = criticalAngles(world, p, stats);
  auto freeAt = [&](double theta) { return isFree({p.x, p.y, theta}); };
  if (roots.empty()) {
    if (freeAt(0.0)) arcs_.push_back({-M_PI, M_PI});
    return;
  }
  // Intervals between consecutive roots, cyclically; the last wraps through +-pi.
  const size_t m = roots.size();
  std::vector<Arc> intervals;
  for (size_t k = 0; k < m; ++k) {
    const double lo = roots[k], hi = k + 1 < m ? roots[k + 1] : roots[0] + kTwoPi;
    if (hi - lo <= 0) continue;
    if (freeAt(0.5 * (lo + hi))) intervals.push_back({lo, hi});
  }
  // Merge touching free intervals (they meet at a critical angle that does not block).
  for (const Arc& a : intervals) {
    if (!arcs_.empty() && arcs_.back().hi == a.lo)
      arcs_.back().hi = a.hi;
    else
      arcs_.push_back(a);
  }
  if (arcs_.size() > 1 && arcs_.back().hi == arcs_.front().lo + kTwoPi) {  // across +-pi
    arcs_.front() = {arcs_.back().lo, arcs_.front().hi + kTwoPi};
    arcs_.pop_back();
  }
  if (arcs_.size() == 1 && arcs_[0].hi - arcs_[0].lo >= kTwoPi) arcs_[0] = {-M_PI, M_PI};
  for (Arc& a : arcs_) {  // normalise lo into [-pi, pi)
    const double shift = wrap(a.lo) - a.lo;
    a.lo += shift;
    a.hi += shift;
  }
}

int Line::arcContaining(double theta) const {
  for (size_t i = 0; i < arcs_.size(); ++i)
    if (arcs_[i].contains(theta)) return int(i);
  return -1;
}

void sketchArcs(const Line& line, RecordManifold& out, bool geometry) {
  out.point = line.point();
  if (geometry)
    for (const Arc& a : line.arcs()) out.arcs.emplace_back(a.lo, a.hi);
}

}  // namespace mms
