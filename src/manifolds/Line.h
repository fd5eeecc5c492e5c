#pragma once
// A vertical line of the C-space of one robot: the reference point is fixed at p and the robot
// rotates. Its free-space cells are the maximal free arcs of angles, bounded by critical angles
// where a robot vertex touches an obstacle edge or a robot edge touches an obstacle vertex
// (the paper's appendix; also the bounds' sides).
//
// Each contact is an equation A cos(theta) + B sin(theta) + C = 0 (the appendix's quadratic in
// tau = tan(theta/2), solved in theta so that theta = pi needs no special case). Roots come
// from doubles; where the discriminant A^2 + B^2 - C^2 is too close to zero for doubles to
// decide (a tangency), its sign is decided exactly, so a grazing contact is neither lost nor
// split. Spurious extra critical angles are harmless: the free status of every interval
// between consecutive critical angles is decided by the collision checker at its middle.
#include <cmath>
#include <functional>
#include <vector>

#include "geometry/CollisionChecker.h"
#include "mms/Record.h"

namespace mms {

/// An arc of angles [lo, hi] with lo in [-pi, pi) and lo <= hi <= lo + 2 pi.
struct Arc {
  double lo = 0, hi = 0;
  bool full() const { return hi - lo >= 2 * M_PI; }
  /// theta (any real) lies on the arc, modulo 2 pi.
  bool contains(double theta) const;
  /// The representative of theta (modulo 2 pi) inside [lo, lo + 2 pi).
  double unwrap(double theta) const;
  /// The signed turn from angle `from` to angle `to` staying inside the arc (on a full circle,
  /// the short way).
  double turn(double from, double to) const {
    return full() ? std::remainder(to - from, 2 * M_PI) : unwrap(to) - unwrap(from);
  }
};

struct LineStats {
  size_t candidates = 0;      // contact pairs that passed the distance filter
  size_t criticalAngles = 0;  // roots kept
  size_t exactFallbacks = 0;  // discriminants decided exactly
};

/// The obstacles' geometry a line needs, in doubles, built once per robot and scene (plus any
/// extra obstacles, such as another robot held fixed).
class LineWorld {
 public:
  LineWorld(const Scene& scene, size_t robot, const std::vector<Ring>& extraObstacles = {});
  /// A rigid compound turning about the origin of its frame: `shapes` in that frame (two
  /// robots in a fixed relative pose turn as one).
  LineWorld(std::vector<Ring> shapes, std::vector<Ring> obstacles, const Box& bounds);
  const std::vector<Ring>& shapes() const { return shapes_; }
  const std::vector<Ring>& obstacles() const { return obstacles_; }
  const Box& bounds() const { return bounds_; }

 private:
  std::vector<Ring> shapes_;
  std::vector<Ring> obstacles_;
  Box bounds_;
};

/// Whether the moving robot is free at a pose (the collision checker, with whatever is held
/// fixed): decides the status of the intervals between critical angles.
using PoseTest = std::function<bool(const Pose&)>;

class Line {
 public:
  Line(const LineWorld& world, const PoseTest& isFree, Vec2 p, LineStats* stats = nullptr);

  Vec2 point() const { return p_; }
  const std::vector<Arc>& arcs() const { return arcs_; }
  /// Index of the arc containing theta, or -1.
  int arcContaining(double theta) const;

 private:
  Vec2 p_;
  std::vector<Arc> arcs_;
};

/// A record's view of a line (mms/Record.h): its point, and its free arcs when `geometry`.
void sketchArcs(const Line& line, RecordManifold& out, bool geometry);

/// Critical angles of a robot at p in [-pi, pi), sorted (exposed for tests).
std::vector<double> criticalAngles(const LineWorld& world, Vec2 p, LineStats* stats = nullptr);

}  // namespace mms
