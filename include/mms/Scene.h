#pragma once
// The planning problem: bounds, obstacles and robots with their start and goal placements.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "mms/Geometry.h"

namespace mms {

enum class Motion { Rigid, Translate };

struct Robot {
  std::string name;
  Ring shape;  // counter-clockwise, in the robot's frame
  Pose start, goal;
  Motion motion = Motion::Rigid;
  /// Radius of the exact disc about the frame origin this robot is; 0 for a polygon robot.
  /// A disc robot's `shape` is its polygonal stand-in (geometry's discStandIn, around the
  /// disc): planners that need polygons plan on it, while the collision checker, the loader's
  /// start and goal tests and every certificate use the disc itself.
  double disc = 0;
};

struct Scene {
  std::string name;  // may be empty
  Box bounds;
  std::vector<Ring> obstacles;  // counter-clockwise; may overlap each other
  /// The obstacles that are exact discs, by obstacle index (shorter than `obstacles` when the
  /// last ones are polygons). Such an obstacle's ring is its polygonal stand-in, as for robots.
  std::vector<std::optional<Disc>> obstacleDiscs;
  std::vector<Robot> robots;

  /// Obstacle i as an exact disc, or null when it is a polygon.
  const Disc* obstacleDisc(size_t i) const {
    return i < obstacleDiscs.size() && obstacleDiscs[i] ? &*obstacleDiscs[i] : nullptr;
  }
  /// Appends an exact disc obstacle (and its stand-in ring).
  void addObstacleDisc(const Disc& d);
  /// Whether a robot or an obstacle is an exact disc.
  bool hasDiscs() const;

  /// Contacts up to this depth count as touching, not colliding (see docs/formats.md).
  double tolerance() const {
    return kRelativeTolerance * std::max(bounds.width(), bounds.height());
  }
  static constexpr double kRelativeTolerance = 1e-6;

  /// Number of coordinates of a full configuration (x, y, theta per robot).
  size_t dof() const { return 3 * robots.size(); }
};

/// One configuration of all robots: x, y, theta per robot, in scene order.
using Config = std::vector<double>;

inline Pose poseOf(const Config& q, size_t robot) {
  return {q[3 * robot], q[3 * robot + 1], q[3 * robot + 2]};
}
/// The configuration a fraction `t` of the way from `a` to `b`, every coordinate alike, into
/// `out` (no allocation once it is large enough).
inline void lerp(const Config& a, const Config& b, double t, Config& out) {
  out.resize(a.size());
  for (size_t c = 0; c < a.size(); ++c) out[c] = a[c] + t * (b[c] - a[c]);
}
/// The same, as a new configuration.
inline Config lerp(const Config& a, const Config& b, double t) {
  Config q;
  lerp(a, b, t, q);
  return q;
}
inline void setPose(Config& q, size_t robot, const Pose& p) {
  q[3 * robot] = p.x;
  q[3 * robot + 1] = p.y;
  q[3 * robot + 2] = p.theta;
}
Config startConfig(const Scene& scene);
Config goalConfig(const Scene& scene);

}  // namespace mms
