#include "planner/CompoundSubspace.h"

#include "manifolds/CellSampling.h"
#include "mms/Termination.h"

namespace mms {

CompoundSubspace::CompoundSubspace(uint32_t group, const Scene& scene,
                                   const CollisionChecker& checker, const CompoundFrame& frame,
                                   Roadmap& roadmap, SubspaceStats& stats)
    : group_(group),
      frame_(frame),
      checker_(checker),
      lineWorld_(compoundShapes(scene, frame), scene.obstacles, scene.bounds),
      roadmap_(roadmap),
      stats_(stats),
      weave_(roadmap.addWeave()) {}

bool CompoundSubspace::free(const Pose& q) const {
  const Pose a = frame_.attachedPose(q);
  return checker_.robotFree(frame_.carrier, q) && checker_.robotFree(frame_.attached, a) &&
         checker_.robotsDisjoint(frame_.carrier, q, frame_.attached, a);
}

void CompoundSubspace::addSlice(const Slice& carrierBase, const SliceWorld& attachedWorld) {
  {
    const TimeCharge charge(stats_.sliceSeconds);
    const Slice attached(attachedWorld,
                         exact::rationalAngleNear(carrierBase.theta() + frame_.dtheta, 30));
    slices_.emplace_back(carrierBase, attached, frame_.offset);
  }
  const size_t k = slices_.size() - 1;
  addJoinedSlice(roadmap_, stats_, std::make_unique<CompoundSliceManifold>(frame_, slices_, k),
                 group_, uint32_t(k), weave_);
}

uint32_t CompoundSubspace::addLine(Vec2 p) {
  return addJoinedLine(
      roadmap_, stats_, lines_, lineWorld_, [this](const Pose& q) { return free(q); }, p, group_,
      [this](size_t l) { return std::make_unique<CompoundLineManifold>(frame_, lines_, l); },
      weave_);
}

std::optional<Vec2> CompoundSubspace::pointInCell(Random& rng) const {
  size_t cells = 0;
  for (const Slice& s : slices_) cells += s.fscCount();
  if (cells == 0) return std::nullopt;
  size_t pick = rng.below(cells);
  for (const Slice& s : slices_) {
    if (pick < s.fscCount()) return samplePointInCell(s, pick, rng, 16);
    pick -= s.fscCount();
  }
  return std::nullopt;
}

}  // namespace mms
