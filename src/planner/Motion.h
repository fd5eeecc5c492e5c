#pragma once
// From a path in the connectivity graph to waypoints of all robots.
#include <memory>
#include <optional>
#include <vector>

#include "check/PathChecker.h"
#include "mms/Scene.h"
#include "planner/Subspace.h"
#include "util/Random.h"

namespace mms {

/// Each node's moving robot goes from where it entered the node to where it leaves it:
/// rotating in place inside a line's arc (on a full circle the short way), or translating
/// inside a slice cell along a route through the cell's triangulation. Consecutive nodes of
/// one subspace meet at (line point, slice angle); where the path crosses to another subspace,
/// the robot that moved stops at the pose the next subspace holds it at, and the other robot
/// moves next. Returns nothing if a route inside a cell cannot be found.
std::optional<std::vector<Config>> graphPathMotion(
    const ConnectivityGraph& graph, const std::vector<std::unique_ptr<Subspace>>& subspaces,
    const std::vector<size_t>& nodes, const Config& start, const Config& goal);

/// A graph path turned into a reported motion: built, shortened by shortcuts, and certified by
/// the path checker against the scene's start and goal. `ok` only if all three succeeded.
struct CertifiedMotion {
  bool ok = false;
  std::vector<Config> waypoints;
  PathCheckResult certificate;
  double buildSeconds = 0, shortcutSeconds = 0, certifySeconds = 0;
};
struct ShortcutSettings {
  size_t attempts = 200;
  bool oneRobotAtATime = false;
};
CertifiedMotion certifiedMotion(const Scene& scene, const CollisionChecker& checker,
                                const ConnectivityGraph& graph,
                                const std::vector<std::unique_ptr<Subspace>>& subspaces,
                                const std::vector<size_t>& nodes, Random& rng,
                                const ShortcutSettings& shortcuts);

/// Random shortcuts: replaces the stretch between two waypoints by the straight motion when the
/// checker certifies it. Bounded by attempts, not time, so a seed fixes the result. With
/// `oneRobotAtATime`, only stretches in which a single robot moves are replaced, so the path
/// keeps moving one robot at a time.
void shortcutPath(const Scene& scene, const CollisionChecker& checker, Random& rng, size_t attempts,
                  std::vector<Config>& waypoints, bool oneRobotAtATime = false);

}  // namespace mms
