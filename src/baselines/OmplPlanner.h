#pragma once
// OMPL's sampling-based planners on mms scenes, with mms's own collision checker as the state
// validity checker (one definition of free space for every planner) and OMPL's discrete motion
// validator at resolution `resolution`. Returned paths are only resolution-checked by OMPL;
// mms runs each through its continuous path checker, and a path that fails counts as a failure.
#include <functional>
#include <string>
#include <vector>

#include "check/PathChecker.h"
#include "mms/Planner.h"
#include "mms/Record.h"
#include "mms/Termination.h"

namespace mms {

struct OmplSettings {
  std::string planner = "rrtconnect";  // a name of the registry (src/registry/OmplPlanners.cpp)
  uint64_t seed = 1;
  /// Motion-check resolution as a fraction of the state space's extent (OMPL's
  /// setStateValidityCheckingResolution).
  double resolution = 0.002;
  double range = 0;  // RRT, RRT-Connect, KPIECE1, BKPIECE1, LazyPRM: 0 = OMPL's default
  /// The same planners' maximum motion length as a share of the state space's extent, where
  /// `range` is 0 (0: OMPL's 0.2). Among robots moving at once a long motion fails more often on
  /// the others: with certified motions and free samples, 0.1 made RRT-Connect 1.4x faster on
  /// two robots in open clutter, 1.2x among five discs swapping and 3x among ten in a room
  /// (median, tuning seeds); for one robot about the same or slower (bends 0.9x).
  double rangeShare = 0;
  unsigned neighbours = 0;    // PRM family: k nearest neighbours; 0 = OMPL's default
  double segmentFactor = 10;  // U-OB-PRM: segment length l = factor x resolution x extent
  bool simplify = false;      // OMPL's path simplifier on the returned path
  /// Motions checked by mms's continuous certifier (clearance against the motion's
  /// displacement bound) instead of OMPL's discrete checks at `resolution`.
  bool certifiedMotions = false;
  /// Each robot's uniform samples redrawn until it is clear of the obstacles (up to 100 draws):
  /// the tree planners grow towards free space.
  bool freeSamples = false;
  /// The share of samples in which each turning robot's angle is drawn between its start and
  /// goal angles (the short way) instead of from the whole circle: a tree whose states turn
  /// at random makes a path that turns back and forth wherever it goes, and taking that out
  /// is most of what the optimiser does after a sampler in open space.
  double leanAngles = 0;
  /// Leave OMPL's planner and states allocated (a command-line run about to exit): freeing
  /// a million states would overrun the time limit by seconds.
  bool keepUntilExit = false;
  /// Keeps the tree or roadmap, with when each state was reached, for a record of the planning.
  bool record = false;
};

struct OmplResult {
  PlanStatus status = PlanStatus::NotFound;  // Found, NotFound or Uncertified
  std::vector<Config> waypoints;             // certified when Found
  PathCheckResult certificate;               // why an OMPL path was refused, when Uncertified
  double seconds = 0;          // to a certified path (or to giving up): setup, solve, certify
  double setupSeconds = 0;     // the checker and OMPL's space and planner
  double solveSeconds = 0;     // OMPL's solve alone; the rest certifies
  double simplifySeconds = 0;  // OMPL's simplifier and its path's certification, after `seconds`
  size_t states = 0;           // vertices of the planner's graph or tree
  size_t edges = 0;            // its edges
  /// Checks of the termination condition: one per iteration of the planner's loop, so the
  /// same for the same seed whatever the load (the portfolio's budget for its sampler).
  size_t iterations = 0;
  /// Robot tests and distances made while solving (CollisionChecker::workOnThisThread).
  size_t checks = 0;
  RecordTree tree;           // with OmplSettings::record: the tree or roadmap, thinned
  RecordGrowth growth;       // and how many states it had by when
  double recordSeconds = 0;  // of `seconds`, reading it out
};

/// Called about once a second while OMPL's planner works (from one of its threads), with
/// the time so far and the size of its graph or tree.
using OmplProgress = std::function<void(const OmplResult& sofar)>;

/// Plans all robots of the scene jointly (SE(2) per rigid robot, R^2 per translating one).
/// Seeds OMPL's global RNG: call once per process for reproducible runs.
OmplResult planWithOmpl(const Scene& scene, const OmplSettings& settings, const Termination& stop,
                        const OmplProgress& progress = {});

}  // namespace mms
