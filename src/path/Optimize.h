#pragma once
// Certified path optimisation for any planner's path: every change is a new stretch of motion
// that the continuous path checker certifies before it is taken, so the result is as safe as
// the path it started from.
//
// Cost is the bound the certifier uses on how far a robot's points move: per robot and segment
// |dp| + radius * |dtheta|, summed. It falls with each step below:
//  - turn the short way: where a rigid robot turns more than half a circle in all over a
//    stretch (turns split across waypoints and fixed-angle moves count as one), the stretch
//    turning the other way round, its new turn put where the robot turned;
//  - shortcuts between two points anywhere on the path (not only waypoints), all robots at once;
//  - partial shortcuts (as OMPL's PathSimplifier): one robot's translation, or its rotation, or
//    both, straightened over a stretch while everything else keeps its timing. This is what
//    removes rotation a robot does not need when the passage needs only its translation;
//  - waypoints on a straight line through their neighbours are dropped.
// The objective "clearance" then moves waypoints away from contacts while the path stays
// certified and no segment's smallest clearance falls.
//
// Rounds of shortcuts end once two in a row stop paying. Bounded by attempts (a seed fixes the
// result) and by `stop` (the planner's time limit).
#include <cstddef>
#include <vector>

#include "geometry/CollisionChecker.h"
#include "mms/Scene.h"
#include "mms/Termination.h"
#include "util/Random.h"

namespace mms {

enum class PathObjective { Length, Clearance };

struct OptimizeSettings {
  PathObjective objective = PathObjective::Length;
  size_t attempts = 100;  // shortcut attempts, full and partial, per round
  size_t rounds = 16;
  /// Rounds end once two in a row each shorten the path by less than this share of its cost
  /// (or take nothing).
  double minGain = 0.0025;
  /// A candidate is certified only when it would shorten the path by this share of its cost:
  /// smaller steps cost a certification each and add up to little (on tuning scenes of ten
  /// families, 0.05 % halved the optimiser's time for paths 0.2 % longer).
  double minStep = 0.0005;
  size_t clearanceAttempts = 0;  // waypoint moves for the clearance objective (0: 50 per waypoint)
  /// The certifier's work over all candidates, in clearances of one robot (an evaluation of k
  /// robots counts k + k(k-1)/2: each robot, each pair), so that a seed fixes the result and k
  /// robots do not take k^2 times as long; and evaluations per candidate stretch: a stretch
  /// that needs more slides along contacts.
  size_t maxWork = 300'000, candidateEvaluations = 4000;
  /// What the rounds of shortcuts may spend, in robot tests and distances
  /// (CollisionChecker::workOnThisThread; their certification included); 0: no bound but the
  /// rounds' own. The turns made the short way are not bounded by it.
  size_t roundsWork = 0;
};

struct OptimizeStats {
  double costBefore = 0, costAfter = 0;
  size_t accepted = 0;     // changes taken
  size_t rounds = 0;       // rounds of shortcuts run
  size_t roundsWork = 0;   // robot tests and distances they made
  size_t checked = 0;      // candidate stretches given to the certifier
  size_t evaluations = 0;  // the certifier's evaluations for them (of all robots)
  size_t slices = 0;       // exact slices built to route a robot that turns the other way
  size_t gridRoutes = 0;   // routes for it found on a grid instead (path/GridRoute.h)
  double seconds = 0;
};

/// The cost above: sum over robots and segments of |dp| + radius * |dtheta|.
double pathCost(const CollisionChecker& checker, const std::vector<Config>& waypoints);

/// Optimises a certified path in place; the path stays certified (start and goal unchanged,
/// translate-only robots keep their angle).
OptimizeStats optimizePath(const Scene& scene, const CollisionChecker& checker, Random& rng,
                           const OptimizeSettings& settings, const Termination& stop,
                           std::vector<Config>& waypoints);

/// Rotation a path's robots need at least: per rigid robot, the short way from its start angle
/// to its goal angle (the certifier accepts the goal modulo a full turn).
double minimumRotation(const Scene& scene);

}  // namespace mms
