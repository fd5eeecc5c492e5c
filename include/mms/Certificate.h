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
};

}  // namespace mms
