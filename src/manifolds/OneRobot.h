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
#include "manifolds/SliceLine.h"

namespace mms {

/// Which robot moves and where the others are held.
struct HeldFrame {
  uint32_t id = 0;  // the subspace: manifolds of one frame share its held poses
  size_t robots = 1;
  size_t moving = 0;
  std::vector<std::pair<size_t, Pose>> held;
  const Pose* heldPose(size_t robot) const;
  size_t mover() const { return moving; }
  void describe(RecordSubspace& out) const {
    out.moving = moving;
    out.held = held;
  }
  /// q with the moving robot at p.
  Config moved(const Config& q, const Pose& p) const;
  /// A lone robot turning in place: one straight step is the exact motion.
  static int turnSteps(double) { return 1; }
  static const ManifoldFamily kSliceFamily, kLineFamily;
};

using OneRobotManifold = FramedManifold<HeldFrame>;

using SliceManifold = SliceOf<HeldFrame>;
using LineManifold = LineOf<HeldFrame>;

/// The meeting rule of any two one-robot manifolds: in one frame, the pose whose coordinates
/// the two fix together (a slice and a line; two slices or two lines share no single point);
/// across frames, each moving robot where the other frame holds it, if that lies on its own
/// manifold, with the robots held in both held alike.
bool meetOneRobot(const Manifold& a, const Manifold& b, Config& at);

}  // namespace mms
