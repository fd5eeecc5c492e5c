#pragma once
// Proofs that a query has no motion at all, so that a planner ends with the reason
// (PlanStatistics::noPath) instead of searching until its time limit. Each proof looks at one
// robot among the obstacles alone: other robots only take room away, so a robot that cannot
// reach its goal alone cannot with them either. Sound, never complete: "" proves nothing.
//
// Both build the exact free space of a probe, a polygon that lies strictly inside the robot as
// the collision checker tests it (shrunk by the contact tolerance) wherever the robot is free,
// and place it by translation only: if the probe's start and goal lie in different cells of
// that free space, the robot has no motion. The probe keeps a margin to the checker's shape, so
// a free robot leaves it clear of every obstacle with room to spare for the rounding of its
// vertices and of the slice's rational angle.
#include <functional>
#include <string>

#include "geometry/CollisionChecker.h"
#include "manifolds/Slice.h"
#include "mms/Scene.h"

namespace mms {

/// Why robot `robot` of `scene` cannot get from `start` to `goal` even alone, or "". Costs one
/// slice among the obstacles.
/// - A translating robot: the probe is the robot shrunk by twice the tolerance, at its angle.
///   (The planners' own slices are built for the robot shrunk by half the tolerance, a larger
///   shape than the checker's: cells apart there need not be apart for the checker.)
/// - A rigid robot: a disc inside the checker's shape turns with the robot but stays a disc, so
///   the probe is a 16-gon inside nine tenths of it, at the disc's centre, whatever the robot's
///   angle. Catches a goal walled in or behind a gap narrower than the robot's thickest part,
///   not one behind a bend too tight for a long robot to turn.
std::string noPathAlone(const Scene& scene, const CollisionChecker& checker, size_t robot,
                        const Pose& start, const Pose& goal);

/// The proof (noPathAlone, from the scene's start to its goal) of the first robot for which
/// `asks` holds and whose proof holds, or "".
std::string noPathOfAny(const Scene& scene, const CollisionChecker& checker,
                        const std::function<bool(size_t robot)>& asks);

/// Whether a translating robot's planner slice `alone` (its one angle, among the obstacles
/// alone) puts its start and goal in different cells. It proves nothing, but where they share
/// a cell noPathAlone would find nothing either (its probe is smaller than the slice's robot),
/// so a planner asks for the proof only when this holds.
bool apartIn(const Slice& alone, const Robot& robot);

}  // namespace mms
