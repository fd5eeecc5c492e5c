#pragma once
// Robots moving at once: any multi-robot path executed as a fleet would, each move starting as
// soon as the moves it must wait for are done (Hönig et al.'s action dependency graphs,
// "MAPF-POST", carried to continuous motions).
//
// A path's segments are its actions: the robots a segment moves, along the segment. Action b
// waits for an earlier action a when they share a robot, or when the regions they sweep may
// meet: each robot's region is bounded by the capsule its reference point's segment sweeps,
// thickened by the robot's radius (exact for a disc that translates). Whatever the timing, two
// actions that overlap in time then sweep disjoint regions, and a robot that waits between two
// of its actions stands where both swept, so every action that could meet it runs before or
// after those two as in the path: the schedule is as free of collisions as the path was. The
// result is certified again all the same.
//
// Time is counted at unit speed: a robot's points move at most one unit per unit time, which a
// motion from pose a to pose b bounds by |dp| + radius * |dtheta| (poseCost; the makespan as
// measureFleet counts it).
#include <cstddef>
#include <vector>

#include "geometry/CollisionChecker.h"
#include "mms/Scene.h"

namespace mms {

struct ScheduleStats {
  size_t actions = 0, dependencies = 0;
  double makespanBefore = 0, makespanAfter = 0;
};

/// The path with every robot's motion unchanged and each action started as early as its
/// dependencies allow: waypoints at the times an action starts or ends, robots moving together
/// between them. A path of one robot, or whose actions all depend on each other, comes back as
/// it was (dropping nothing but its motionless segments).
std::vector<Config> concurrentSchedule(const Scene& scene, const CollisionChecker& checker,
                                       const std::vector<Config>& waypoints,
                                       ScheduleStats* stats = nullptr);

}  // namespace mms
