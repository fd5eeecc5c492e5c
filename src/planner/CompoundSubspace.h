#pragma once
// The 3-D subspace in which two robots keep one relative pose and move as a rigid compound,
// approximated as a one-robot subspace is: compound slices at the carrier's angles and
// compound lines (manifolds/Compound.h), joined in the shared roadmap.
#include <memory>
#include <vector>

#include "graph/Roadmap.h"
#include "manifolds/Compound.h"
#include "planner/Subspace.h"
#include "util/Random.h"

namespace mms {

class CompoundSubspace {
 public:
  /// Compound subspaces' roadmap groups start here, above any one-robot subspace's id.
  static constexpr uint32_t kFirstGroup = 1u << 30;
  CompoundSubspace(uint32_t group, const Scene& scene, const CollisionChecker& checker,
                   const CompoundFrame& frame, Roadmap& roadmap, SubspaceStats& stats);
  CompoundSubspace(const CompoundSubspace&) = delete;  // its manifolds point at its members
  CompoundSubspace& operator=(const CompoundSubspace&) = delete;

  const CompoundFrame& frame() const { return frame_; }
  /// A compound slice at the carrier's angle of `carrierBase` (the carrier among the
  /// obstacles), with the attached robot's slice built from `attachedWorld`; joined to the
  /// lines here.
  void addSlice(const Slice& carrierBase, const SliceWorld& attachedWorld);
  /// A compound line with the carrier's reference point at p, joined to the slices here.
  /// Returns its roadmap id.
  uint32_t addLine(Vec2 p);
  /// A point in a compound-slice cell drawn uniformly among the cells (not by area: the small
  /// cells are where the compound turns), or nothing.
  std::optional<Vec2> pointInCell(Random& rng) const;
  size_t lineCount() const { return lines_.size(); }
  /// Whether the pair is free at the carrier's pose q (both robots, and apart).
  bool free(const Pose& q) const;

 private:
  uint32_t group_;
  CompoundFrame frame_;
  const CollisionChecker& checker_;
  LineWorld lineWorld_;
  Roadmap& roadmap_;
  SubspaceStats& stats_;
  std::vector<Slice> slices_;
  std::vector<Line> lines_;
  uint32_t weave_;  // its lines and slices, all joined
};

}  // namespace mms
