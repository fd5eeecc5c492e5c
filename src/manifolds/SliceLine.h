#pragma once
// The paper's two families over any frame that moves one rigid body: a slice fixes the body's
// angle (it translates inside a cell), a line its reference point (it turns inside an arc).
// The frame says which robot's coordinates they are and where the others go when it moves: a
// subspace moves one robot with the rest held (HeldFrame, OneRobot.h); a compound moves a pair
// in a fixed relative pose (CompoundFrame, Compound.h). Both are views: the slice or line stays
// in the vector its planner keeps. A Frame provides mover(), moved(q, pose), turnSteps(turn)
// (how many straight steps make the turn certifiable) and the two families' identities,
// kSliceFamily and kLineFamily, defined where the frame is.
#include <algorithm>
#include <optional>
#include <vector>

#include "manifolds/Line.h"
#include "manifolds/Manifold.h"
#include "manifolds/Slice.h"

namespace mms {

/// The route of a reference point inside cell `cell` of `slice` from a to b (CellRoute.h): the
/// points after a, the last b; nothing if none is found.
std::optional<std::vector<Vec2>> slideInCell(const Slice& slice, size_t cell, Vec2 a, Vec2 b);

template <class Frame>
class SliceOf final : public StoredView<FramedManifold<Frame>, Slice> {
 public:
  static constexpr const ManifoldFamily& kFamily = Frame::kSliceFamily;
  using StoredView<FramedManifold<Frame>, Slice>::StoredView;
  const Slice& slice() const { return this->item(); }

  const ManifoldFamily& family() const override { return kFamily; }
  size_t cellCount() const override { return slice().fscCount(); }
  long locate(const Config& q) const override {
    const size_t m = this->frame().mover();
    return slice().locate({q[3 * m], q[3 * m + 1]});
  }
  /// Translation along a route through the cell's triangulation.
  std::optional<std::vector<Config>> motion(size_t cell, const Config& from,
                                            const Config& to) const override {
    const size_t m = this->frame().mover();
    const auto route =
        slideInCell(slice(), cell, {from[3 * m], from[3 * m + 1]}, {to[3 * m], to[3 * m + 1]});
    if (!route) return std::nullopt;
    std::vector<Config> out;
    for (const Vec2 p : *route)
      out.push_back(this->frame().moved(from, {p.x, p.y, from[3 * m + 2]}));
    return out;
  }
  unsigned fixes() const override { return this->kTheta; }
  Pose fixedAt() const override { return {0, 0, slice().theta()}; }
  void sketch(RecordManifold& out, bool geometry) const override {
    Manifold::sketch(out, geometry);
    out.theta = slice().theta();
    for (size_t c = 0; c < cellCount(); ++c) {
      for (const Ring& r : slice().cell(c)) out.vertices += r.size();
      if (geometry) out.regions.push_back(slice().cell(c));
    }
  }
};

template <class Frame>
class LineOf final : public StoredView<FramedManifold<Frame>, Line> {
 public:
  static constexpr const ManifoldFamily& kFamily = Frame::kLineFamily;
  using StoredView<FramedManifold<Frame>, Line>::StoredView;
  const Line& line() const { return this->item(); }

  const ManifoldFamily& family() const override { return kFamily; }
  size_t cellCount() const override { return line().arcs().size(); }
  long locate(const Config& q) const override {
    return line().arcContaining(q[3 * this->frame().mover() + 2]);
  }
  /// Rotation in place inside the arc (on a full circle, the short way), in the frame's steps.
  std::optional<std::vector<Config>> motion(size_t cell, const Config& from,
                                            const Config& to) const override {
    const size_t m = this->frame().mover();
    const double theta = from[3 * m + 2];
    const double turn = line().arcs()[cell].turn(theta, to[3 * m + 2]);
    const int steps = Frame::turnSteps(turn);
    std::vector<Config> out;
    for (int i = 1; i <= steps; ++i)
      out.push_back(
          this->frame().moved(from, {from[3 * m], from[3 * m + 1], theta + turn * i / steps}));
    return out;
  }
  unsigned fixes() const override { return this->kX | this->kY; }
  Pose fixedAt() const override { return {line().point().x, line().point().y, 0}; }
  void sketch(RecordManifold& out, bool geometry) const override {
    Manifold::sketch(out, geometry);
    sketchArcs(line(), out, geometry);
  }
};

}  // namespace mms
