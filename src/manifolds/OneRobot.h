#pragma once
// The paper's two families, in the frame of a subspace: one robot moves while every other
// robot is held at a fixed pose. A slice fixes the moving robot's angle, a line its position;
// a slice and a line of one frame meet at (line point, slice angle), and manifolds of two
// frames meet where each robot stands where the other frame holds it (recursive MMS, Section
// II). Both classes are views: the slice or line stays in the vector its subspace keeps.
#include <cstdint>
#include <utility>
#include <vector>

#include "manifolds/Line.h"
#include "manifolds/Manifold.h"
#include "manifolds/Slice.h"

namespace mms {

/// Which robot moves and where the others are held.
struct HeldFrame {
  uint32_t id = 0;  // the subspace: manifolds of one frame share its held poses
  size_t robots = 1;
  size_t moving = 0;
  std::vector<std::pair<size_t, Pose>> held;
  const Pose* heldPose(size_t robot) const;
};

using OneRobotManifold = FramedManifold<HeldFrame>;

class SliceManifold final : public StoredView<OneRobotManifold, Slice> {
 public:
  static const ManifoldFamily kFamily;
  using StoredView::StoredView;
  const Slice& slice() const { return item(); }

  const ManifoldFamily& family() const override { return kFamily; }
  size_t cellCount() const override { return slice().fscCount(); }
  long locate(const Config& q) const override;
  /// Translation along a route through the cell's triangulation (CellRoute.h).
  std::optional<std::vector<Config>> motion(size_t cell, const Config& from,
                                            const Config& to) const override;
  unsigned fixes() const override { return kTheta; }
  Pose fixedAt() const override { return {0, 0, slice().theta()}; }
};

class LineManifold final : public StoredView<OneRobotManifold, Line> {
 public:
  static const ManifoldFamily kFamily;
  using StoredView::StoredView;
  const Line& line() const { return item(); }

  const ManifoldFamily& family() const override { return kFamily; }
  size_t cellCount() const override { return line().arcs().size(); }
  long locate(const Config& q) const override;
  /// Rotation in place inside the arc (on a full circle, the short way).
  std::optional<std::vector<Config>> motion(size_t cell, const Config& from,
                                            const Config& to) const override;
  unsigned fixes() const override { return kX | kY; }
  Pose fixedAt() const override { return {line().point().x, line().point().y, 0}; }
};

/// The route of a reference point inside cell `cell` of `slice` from a to b (CellRoute.h): the
/// points after a, the last b; nothing if none is found. Every slice family's motion.
std::optional<std::vector<Vec2>> slideInCell(const Slice& slice, size_t cell, Vec2 a, Vec2 b);

/// The meeting rule of any two one-robot manifolds: in one frame, the pose whose coordinates
/// the two fix together (a slice and a line; two slices or two lines share no single point);
/// across frames, each moving robot where the other frame holds it, if that lies on its own
/// manifold, with the robots held in both held alike.
bool meetOneRobot(const Manifold& a, const Manifold& b, Config& at);

}  // namespace mms
