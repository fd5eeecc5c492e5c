#pragma once
// Plain double-precision geometry values shared by every stage and the public API. The exact
// types stay inside the library (src/geometry/Exact.h), with the conversions between the two.
#include <algorithm>
#include <cmath>
#include <vector>

namespace mms {

struct Vec2 {
  double x = 0, y = 0;
  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
  friend bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }
};

inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }

/// A simple polygon as its vertex cycle; counter-clockwise once a scene is loaded.
using Ring = std::vector<Vec2>;

/// A closed disc: robots and obstacles may be exact discs (see Scene).
struct Disc {
  Vec2 center;
  double radius = 0;
};

/// Axis-aligned box; also the scene bounds.
struct Box {
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  bool overlaps(const Box& o) const {
    return xmin <= o.xmax && o.xmin <= xmax && ymin <= o.ymax && o.ymin <= ymax;
  }
  bool contains(const Box& o) const {
    return xmin <= o.xmin && o.xmax <= xmax && ymin <= o.ymin && o.ymax <= ymax;
  }
  bool contains(Vec2 p) const { return xmin <= p.x && p.x <= xmax && ymin <= p.y && p.y <= ymax; }
  double width() const { return xmax - xmin; }
  double height() const { return ymax - ymin; }
  /// The box grown by `margin` on every side.
  Box grown(double margin) const {
    return {xmin - margin, ymin - margin, xmax + margin, ymax + margin};
  }
  /// Distance between two boxes (0 when they overlap).
  double distance(const Box& o) const { return std::sqrt(distance2(o)); }
  /// std::max, not std::fmax: fmax is a call into libm (it orders NaNs), and the certifier's
  /// edge loops call this millions of times.
  double distance2(const Box& o) const {
    const double dx = std::max(0.0, std::max(o.xmin - xmax, xmin - o.xmax));
    const double dy = std::max(0.0, std::max(o.ymin - ymax, ymin - o.ymax));
    return dx * dx + dy * dy;
  }
};

Box boundingBox(const Ring& ring);

/// Placement of one robot: rotate its shape by theta (counter-clockwise, radians) about the
/// frame origin, then translate by (x, y).
struct Pose {
  double x = 0, y = 0, theta = 0;
};

/// Rigid transform with its rotation precomputed; the hot loops transform many vertices.
struct Transform {
  double c = 1, s = 0, tx = 0, ty = 0;
  explicit Transform(const Pose& p)
      : c(std::cos(p.theta)), s(std::sin(p.theta)), tx(p.x), ty(p.y) {}
  /// From a rotation's cosine and sine already at hand (kept while a robot's angle stays).
  Transform(double cosine, double sine, double x, double y) : c(cosine), s(sine), tx(x), ty(y) {}
  Vec2 operator()(Vec2 v) const { return {tx + c * v.x - s * v.y, ty + s * v.x + c * v.y}; }
};

/// `v` turned by `theta` about the origin.
inline Vec2 rotated(Vec2 v, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

/// Transforms a ring into a caller-owned buffer (no allocation once the buffer is large enough).
inline void transformRing(const Ring& in, const Pose& pose, Ring& out) {
  Transform t(pose);
  out.resize(in.size());
  for (size_t i = 0; i < in.size(); ++i) out[i] = t(in[i]);
}

/// The ring placed at `pose`, as a new ring (outside hot loops).
inline Ring placedRing(const Ring& shape, const Pose& pose) {
  Ring out;
  transformRing(shape, pose, out);
  return out;
}

}  // namespace mms
