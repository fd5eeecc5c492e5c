#pragma once
// From a path in the roadmap to waypoints of all robots, shortened and certified.
#include <optional>
#include <vector>

#include "check/PathChecker.h"
#include "graph/Roadmap.h"
#include "mms/Scene.h"

namespace mms {

/// The motion along a path of cells: inside each cell, its manifold's motion from where the
/// path entered it to where the cell meets the next one (the meeting point of the two
/// manifolds, Manifold.h), and to `goal` in the last. Any family, no branch on which.
/// Returns nothing if a cell's motion cannot be found or two consecutive cells do not meet.
std::optional<std::vector<Config>> graphPathMotion(const Roadmap& roadmap,
                                                   const std::vector<size_t>& nodes,
                                                   const Config& start, const Config& goal);

/// A graph path turned into a reported motion: built, and certified by the path checker against
/// the scene's start and goal. `ok` only if both succeeded. It is not shortened here: the path
/// optimiser (Optimize.h) shortens every planner's first path after the time to it, and
/// shortcuts taken before that cost a third of a several-robot plan's time to its path (4-5
/// discs swapping places) and changed the optimised path's length by less than 2 %.
struct CertifiedMotion {
  bool ok = false;
  std::vector<Config> waypoints;
  PathCheckResult certificate;
  double buildSeconds = 0, certifySeconds = 0;
};
CertifiedMotion certifiedMotion(const Scene& scene, const CollisionChecker& checker,
                                const Roadmap& roadmap, const std::vector<size_t>& nodes);

}  // namespace mms
