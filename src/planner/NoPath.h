#pragma once
// Proofs that a query has no motion at all, so that a planner ends at once with the reason
// (PlanStatistics::noPath) instead of searching until its time limit. Each proof looks at one
// robot among the obstacles alone: other robots only take room away, so a robot that cannot
// reach its goal alone cannot with them either. Sound, never complete: "" proves nothing.
#include <string>

#include "geometry/CollisionChecker.h"
#include "manifolds/Slice.h"
#include "mms/Scene.h"

namespace mms {

/// Why a translating robot cannot reach its goal, or "": when its start and goal lie in
/// different cells of `alone`, its slice among the obstacles alone. The slice is built for the
/// robot shrunk for contacts, whose free space holds the robot's own, so cells apart there are
/// apart for the robot too. A point in no cell (within a hair of a contact) proves nothing.
std::string goalCutOffAlone(const Slice& alone, const Robot& robot);

/// Why robot `robot` of `scene` cannot get from `start` to `goal` even alone, or "". A disc
/// inside the robot's shape as the checker tests it (shrunk by the contact tolerance) turns
/// with the robot but stays a disc: wherever the robot is free, so is a polygon inside that
/// disc at the disc's centre, whatever the robot's angle. So the disc's centre moves in the
/// polygon's exact free space (a slice of a translating robot) from where it is at the start
/// to where it is at the goal; when those lie in different cells, the robot has no motion.
/// Costs one slice among the obstacles. Catches a goal walled in or behind a gap narrower than
/// the robot's thickest part, not one behind a bend too tight for a long robot to turn.
std::string discCutOff(const Scene& scene, const CollisionChecker& checker, size_t robot,
                       const Pose& start, const Pose& goal);

}  // namespace mms
