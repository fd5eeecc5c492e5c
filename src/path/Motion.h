#pragma once
// From a path in the roadmap to waypoints of all robots, shortened and certified.
#include <optional>
#include <vector>

#include "check/PathChecker.h"
#include "graph/Roadmap.h"
#include "mms/Scene.h"
#include "util/Random.h"

namespace mms {

/// The motion along a path of cells: inside each cell, its manifold's motion from where the
/// path entered it to where the cell meets the next one (the meeting point of the two
/// manifolds, Manifold.h), and to `goal` in the last. Any family, no branch on which.
/// Returns nothing if a cell's motion cannot be found or two consecutive cells do not meet.
std::optional<std::vector<Config>> graphPathMotion(const Roadmap& roadmap,
                                                   const std::vector<size_t>& nodes,
                                                   const Config& start, const Config& goal);

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
                                const Roadmap& roadmap, const std::vector<size_t>& nodes,
                                Random& rng, const ShortcutSettings& shortcuts);

/// Random shortcuts: replaces the stretch between two waypoints by the straight motion when the
/// checker certifies it. Bounded by attempts, not time, so a seed fixes the result. With
/// `oneRobotAtATime`, only stretches in which a single robot moves are replaced, so the path
/// keeps moving one robot at a time.
void shortcutPath(const Scene& scene, const CollisionChecker& checker, Random& rng, size_t attempts,
                  std::vector<Config>& waypoints, bool oneRobotAtATime = false);

}  // namespace mms
