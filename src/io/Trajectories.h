#pragma once
// A path as timed trajectories, one per robot, for fleet software: at unit speed (a robot's
// points move at most one unit per unit time), each segment lasting as long as its slowest robot
// needs (|dp| + radius * |dtheta|, the makespan's measure, check/PathChecker.h's measureFleet).
#include <string>
#include <vector>

#include "mms/Scene.h"

namespace mms {

/// CSV: "robot,name,t,x,y,theta", then per robot (in scene order) its pose at t = 0, wherever
/// it starts, stops or changes its way, and at the end: between two rows it moves at one
/// velocity (or stands). Times and poses printed to round-trip a double.
std::string trajectoriesCsv(const Scene& scene, const std::vector<Config>& waypoints);

}  // namespace mms
