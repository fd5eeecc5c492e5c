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

class OneRobotManifold : public Manifold {
 public:
  explicit OneRobotManifold(const HeldFrame& frame) : frame_(&frame) {}
  const HeldFrame& frame() const { return *frame_; }
  /// The moving robot's coordinates this manifold fixes (bits kX | kY | kTheta) ...
  enum : unsigned { kX = 1, kY = 2, kTheta = 4 };
  virtual unsigned fixes() const = 0;
  /// ... and their values (the other fields are 0).
  virtual Pose fixedAt() const = 0;

 private:
  const HeldFrame* frame_;
};

/// A view of item `index` of a vector its subspace keeps (the vector may grow; the item's
/// index stays).
template <class Item>
class StoredManifold : public OneRobotManifold {
 public:
  StoredManifold(const HeldFrame& frame, const std::vector<Item>& store, size_t index)
      : OneRobotManifold(frame), store_(&store), index_(index) {}
  const Item& item() const { return (*store_)[index_]; }

 private:
  const std::vector<Item>* store_;
  size_t index_;
};

class SliceManifold final : public StoredManifold<Slice> {
 public:
  static const ManifoldFamily kFamily;
  using StoredManifold::StoredManifold;
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

class LineManifold final : public StoredManifold<Line> {
 public:
  static const ManifoldFamily kFamily;
  using StoredManifold::StoredManifold;
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

/// The meeting rule of any two one-robot manifolds: in one frame, the pose whose coordinates
/// the two fix together (a slice and a line; two slices or two lines share no single point);
/// across frames, each moving robot where the other frame holds it, if that lies on its own
/// manifold, with the robots held in both held alike.
bool meetOneRobot(const Manifold& a, const Manifold& b, Config& at);

}  // namespace mms
