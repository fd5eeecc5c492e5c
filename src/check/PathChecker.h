#pragma once
// Certifies a path as a continuous motion, not only at sampled poses.
//
// Each segment between waypoints is split into pieces until each piece is proven free: at a
// piece's midpoint the clearance of every moving robot (to the bounds, the obstacles and the
// other robots) must exceed how far any of its points can move within half the piece,
// |dp| + radius * |dtheta|. Clearances are measured on the robots shrunk by the contact
// tolerance, so touching contacts are allowed and penetration beyond the tolerance is not.
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "geometry/CollisionChecker.h"
#include "mms/Certificate.h"
#include "mms/Scene.h"

namespace mms {

struct PathCheckSettings {
  /// Clearance evaluations allowed over the whole path; a path that slides along contacts
  /// for long stretches needs pieces as short as the tolerance and may run out of them.
  size_t maxEvaluations = 20'000'000;
  /// Whether the result's minClearance is the smallest clearance of every pose evaluated. Off,
  /// distances are computed only as far as certifying needs (a far obstacle costs a box test),
  /// and minClearance is only an upper bound of the path's clearance.
  bool measureClearance = true;
};

/// One robot's cost from pose a to pose b: |dp| + radius * |dtheta|, which bounds how far any of
/// its points moves (the certifier's bound, the optimiser's cost, and at unit speed the time the
/// motion takes). Inline: the optimiser's attempts take thousands.
inline double poseCost(const CollisionChecker& checker, size_t robot, const Pose& a,
                       const Pose& b) {
  // Not hypot, a call into libm: a cost needs no guard against overflow.
  const double dx = b.x - a.x, dy = b.y - a.y;
  return std::sqrt(dx * dx + dy * dy) + checker.radius(robot) * std::fabs(b.theta - a.theta);
}

/// The path's makespan, sum of distances, their lower bounds and the robots moving at once, into
/// `r` (PathCheckResult's fleet measures).
void measureFleet(const Scene& scene, const CollisionChecker& checker,
                  const std::vector<Config>& waypoints, PathCheckResult& r);

/// Checks that the path starts at the scene's start, ends at its goal, keeps translate-only
/// robots at their angle, and is free as a continuous motion.
PathCheckResult checkPath(const Scene& scene, const CollisionChecker& checker,
                          const std::vector<Config>& waypoints,
                          const PathCheckSettings& settings = {});

/// Only the continuous-motion part: every segment between consecutive waypoints is free.
PathCheckResult checkMotion(const Scene& scene, const CollisionChecker& checker,
                            const std::vector<Config>& waypoints,
                            const PathCheckSettings& settings = {});

/// Whether the straight motion from a to b is certified free: the test of checkMotion for one
/// segment, without its report, refusing at the first evaluation that fails.
/// `stillOnesFree`: the robots that stay put are known to be free of the obstacles and of each
/// other (a is a certified configuration), so only the moving ones are tested.
bool motionFree(const CollisionChecker& checker, const Config& a, const Config& b,
                bool stillOnesFree = false);

/// How far the straight motion from a to b is certified free, as a fraction of it: 1 when all
/// of it is; else a point of its certified beginning, as far as the certifier's pieces find,
/// at which every moving robot is at least the contact tolerance away from anything (so that
/// a motion from there can be certified too); 0 when there is none.
double certifiedPrefix(const CollisionChecker& checker, const Config& a, const Config& b);

}  // namespace mms
