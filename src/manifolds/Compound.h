#pragma once
// Coupled motion: two robots in a fixed relative pose move as one rigid compound (a gripper
// turning with the part it holds, a robot pushing another). Slices and lines of one robot with
// the other held still cannot contain such a motion; it needs many alternating small moves.
// A compound slice fixes the carrier's angle (both translate together; exact: the carrier's
// free space intersected with the attached robot's, moved, Slice.h); a compound line fixes the
// carrier's position (both turn about it; critical angles of the two shapes as one, Line.h).
// Each is exact and meets the one-robot families where a held robot stands where the compound
// puts it, so completeness and certification are untouched (the paper's argument applies to
// any family of manifolds whose cells are exact).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "manifolds/Line.h"
#include "manifolds/Manifold.h"
#include "manifolds/OneRobot.h"
#include "manifolds/Slice.h"
#include "manifolds/SliceLine.h"

namespace mms {

/// Which robot carries which, and in what relative pose.
struct CompoundFrame {
  size_t robots = 2;
  size_t carrier = 0, attached = 1;
  Vec2 offset;        // the attached robot's reference point in the carrier's frame
  double dtheta = 0;  // the attached robot's angle minus the carrier's
  /// Robot 1 at `attached` relative to robot 0 at `carrier`.
  static CompoundFrame between(const Pose& carrier, const Pose& attached);
  Pose attachedPose(const Pose& carrier) const;
  /// The carrier's pose that puts the attached robot at `attached`.
  Pose carrierFor(const Pose& attached) const;
  Config config(const Pose& carrier) const;
  /// `q` with the carrier at `carrier` and the attached robot where it puts it.
  Config moved(const Config& q, const Pose& carrier) const;
  size_t mover() const { return carrier; }
  void describe(RecordSubspace& out) const {
    out.moving = carrier;
    out.attached = long(attached);
  }
  /// The pair turns about the carrier's reference point in steps of at most kStep radians: the
  /// attached robot's straight moves between them stray from its circle by at most
  /// |offset| kStep^2 / 8 (1.3e-5 |offset|), far inside the play of any cell worth certifying.
  static constexpr double kStep = 0.01;
  static const ManifoldFamily kSliceFamily, kLineFamily;
  static int turnSteps(double turn) { return std::max(1, int(std::ceil(std::abs(turn) / kStep))); }
};

/// The rigid compound's shapes in the carrier's frame (for compound lines).
std::vector<Ring> compoundShapes(const Scene& scene, const CompoundFrame& frame);

/// The carrier's coordinates a compound manifold fixes: as a one-robot manifold's.
using CompoundManifold = FramedManifold<CompoundFrame>;

using CompoundSliceManifold = SliceOf<CompoundFrame>;
using CompoundLineManifold = LineOf<CompoundFrame>;

/// Rules: two compound manifolds of one frame meet as a slice and a line of one robot do; a
/// compound manifold and a one-robot manifold (the other robot held) meet where the held robot
/// stands where the compound would put it.
bool meetCompound(const Manifold& a, const Manifold& b, Config& at);
bool meetCompoundOneRobot(const Manifold& compound, const Manifold& oneRobot, Config& at);

}  // namespace mms
