#pragma once
// What the continuous path checker says of a path: certified or not, where it fails and why,
// and what the motion measures. Every planner's result carries one.
#include <cstddef>
#include <string>

namespace mms {

struct PathCheckResult {
  bool ok = false;
  // When !ok: where and why. `segment` is the index of the segment's first waypoint.
  size_t segment = 0;
  double parameter = 0;  // along the segment, in [0, 1]
  std::string reason;
  // Statistics.
  double minClearance = 0;  // smallest clearance seen at a checked pose (0: touching)
  size_t evaluations = 0;   // clearance evaluations (poses checked)
  double translation = 0;   // summed over robots
  double rotation = 0;      // radians, summed over robots
  // As fleets are measured (CG:SHOP 2021's makespan and sum of distances), where measured
  // (measureFleet): at unit speed, a robot's points moving at most one unit per unit time, which
  // a segment's motion bounds by |dp| + radius * |dtheta|.
  double makespan = 0;       // until the last robot arrives, a segment as long as its slowest
  double makespanBound = 0;  // the longest robot's straight start-goal cost (the short turn)
  double distance = 0;       // the robots' costs summed
  double distanceBound = 0;  // their straight start-goal costs summed
  double movingAtOnce = 0;   // robots in motion, in the mean over the makespan
};

}  // namespace mms
