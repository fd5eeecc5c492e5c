#pragma once
// Turns about a pivot: a line of one robot whose turning centre is a point of the robot other
// than its reference point. A U that holds a part in its mouth turns about the part; turned
// about its reference point it sweeps a larger circle, and slices (fixed angle) and lines (fixed
// reference point) then contain the turn only as a staircase of many angles (the swallow scenes
// took four rounds, up to 128 angles). A pivot line fixes the pivot's world position and frees
// the angle: its cells are the free arcs of the robot's shape moved so that the pivot is its
// origin (Line.h: exact critical angles, as any line), and it meets a slice of the robot at that
// slice's angle. Inside an arc the robot turns about the pivot in steps of at most kStep
// radians, its reference point on a circle; the straight steps between them stray from it by at
// most |pivot| kStep^2 / 8, and the path checker certifies them.
#include <optional>
#include <vector>

#include "geometry/PolygonOps.h"
#include "manifolds/Line.h"
#include "manifolds/Manifold.h"

namespace mms {

/// The smallest disc enclosing a ring's vertices (CGAL's Min_circle_2).
Disc smallestCircle(const Ring& ring);

/// Where a robot can hold a part in a pocket: the largest disc inside its convex hull but outside
/// it, the one nearest its reference point among equals (on a grid a 160th of the robot's
/// size). None when the robot is convex or its pocket is thinner than two grid steps.
std::optional<Disc> pocketDisc(const Ring& shape);

class PivotLineManifold final : public Manifold {
 public:
  static const ManifoldFamily kFamily;
  static constexpr double kStep = 0.01;
  /// The robot (a scene of one) turning about `pivot` (its frame) placed at `at` (the world);
  /// `world`: the robot's shape moved so that the pivot is its origin, and the obstacles.
  PivotLineManifold(const LineWorld& world, const PoseTest& robotFree, Vec2 pivot, Vec2 at,
                    LineStats* stats = nullptr);

  const ManifoldFamily& family() const override { return kFamily; }
  size_t cellCount() const override { return line_.arcs().size(); }
  long locate(const Config& q) const override { return line_.arcContaining(q[2]); }
  std::optional<std::vector<Config>> motion(size_t cell, const Config& from,
                                            const Config& to) const override;
  const Line& line() const { return line_; }
  /// Its point is where the pivot stands.
  void sketch(RecordManifold& out, bool geometry) const override {
    Manifold::sketch(out, geometry);
    sketchArcs(line_, out, geometry);
  }
  /// The robot's configuration turned to `theta` about the pivot.
  Config at(double theta) const;

 private:
  Vec2 pivot_;
  Line line_;
};

/// A pivot line and a slice of the one-robot planner meet at the slice's angle.
bool meetPivotSlice(const Manifold& pivotLine, const Manifold& slice, Config& at);

/// The world of a pivot's lines: `scene`'s only robot moved so that `pivot` is its origin.
LineWorld pivotWorld(const Scene& scene, Vec2 pivot);

}  // namespace mms
