#pragma once
// MMS for one rigid polygonal robot that translates and rotates (3-D C-space): horizontal
// slices (fixed angle, exact free space of the reference point) and vertical lines (fixed
// position, free arcs of angles) as manifold samples; their free-space cells are the nodes of
// the connectivity graph, joined where a line's point lies in a slice cell and the slice's
// angle lies in the line's arc. Anytime: while start and goal are not connected, the numbers
// of slices and lines double; within a round they are interleaved, and the search runs as soon
// as start and goal connect. Multi-query: the roadmap stays for further queries.
//
// Salzman, Hemmer, Raveh, Halperin: "Motion planning via manifold samples", ESA 2011 /
// Algorithmica 2013; Salzman, Hemmer, Halperin: "On the power of manifold samples in exploring
// configuration spaces and the dimensionality of narrow passages", Section I-B and appendix.
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "check/PathChecker.h"
#include "mms/Planner.h"
#include "mms/Termination.h"
#include "planner/Subspace.h"
#include "util/Random.h"

namespace mms {

struct OneRobotSettings {
  uint64_t seed = 1;
  size_t nTheta = 16;          // n_theta: slices in the first round (the paper's name)
  size_t nLines = 1024;        // n_l: lines in the first round (a line costs ~10 us, a slice ~1 ms)
  double freeLineShare = 0.5;  // share of line points drawn inside slice FSCs, the rest uniform
  // Of those, the share drawn near a vertex of a cell (a placement touching two obstacle
  // features). Turning a bend needs a line where the robot can turn, a small region at the
  // corridor's corner: on the bends' tuning seeds (1-10, three planner seeds each) the median
  // time fell from 39 to 16 ms, on the corridor corner from 43 to 10 ms; the doors, one-robot open
  // clutter, bar-slot, bug trap and maze were unchanged within noise.
  double cornerLineShare = 0.5;
  PointLocation pointLocation = PointLocation::Auto;
  /// From the second round on, pivot lines (manifolds/Pivot.h): the robot turning about the
  /// centre of its pocket placed at the centre of each obstacle that fits there (a part it
  /// can swallow and turn about). Not in the first round, which solves every tight family but
  /// the swallow (docs/benchmarks.md) and so pays nothing.
  bool pivotLines = true;
  /// From the first round, spin places: pivot lines turning the robot about the centre of its
  /// smallest enclosing circle held at each local maximum of the clearance (climbed to from a
  /// 4 x 4 grid over the bounds) where the robot can turn all the way round, and slices at
  /// the start's and the goal's angles once two slices of the sequence have not connected them.
  /// A robot that must arrive and leave at given angles turns there the short way (the keyhole:
  /// its path on 5 of some 72 manifolds, not hundreds).
  bool spinPlaces = true;
  /// Threads that build slices (each round's slices in batches of this many). The result does
  /// not depend on it: slices are added to the roadmap in angle order.
  unsigned threads = 1;
  /// Give up after this many rounds of the roadmap's life (0: only the time limit stops it). A
  /// budget in rounds, unlike one in seconds, gives the same answer for the seed on any machine.
  size_t maxRounds = 0;
  /// Keeps what a record of the planning needs beyond the manifolds' time stamps: when each
  /// joined the start's and the goal's component (a pass over the nodes per search).
  bool record = false;
};

/// Angles n at a time: n evenly spaced with a random shift, then the midpoints between them,
/// and so on, so that every prefix covers the circle evenly.
class AngleSequence {
 public:
  AngleSequence(size_t n, double shift) : n_(std::max<size_t>(1, n)), shift_(shift) {}
  double next();
  /// The next n angles.
  std::vector<double> take(size_t n);
  /// A rigid robot's first angle set: its start angle, its goal angle if it differs, then the
  /// next n of the sequence. A slice at the start or goal angle contains the whole passage of
  /// positions around the start or goal, where tight problems are often tightest (a part seated
  /// in its slot, the square inside the Pacman's mouth).
  std::vector<double> startGoalThen(const Robot& robot, size_t n);

 private:
  size_t n_, count_ = 0;
  double shift_;
};

struct OneRobotStats {
  SubspaceStats manifolds;  // slices, lines, their cells and build times
  size_t pivotLines = 0;    // of the lines: those turning about a pivot
  size_t rounds = 0, graphNodes = 0, graphEdges = 0;
  double roundShare = 0;     // of the last round's targets met (PlanStatistics::roundShare)
  size_t pathCells = 0;      // FSCs on the graph path
  size_t pathManifolds = 0;  // the slices and lines they lie on (of slices + lines built)
  size_t rejectedPaths = 0;  // candidate motions the checker refused
  std::string noPath;        // why no path exists, when proved (PlanStatistics::noPath)
  double searchSeconds = 0, motionSeconds = 0, certifySeconds = 0, totalSeconds = 0;
};

struct OneRobotResult {
  PlanStatus status = PlanStatus::NotFound;    // Found, NotFound or Cancelled
  std::vector<Config> waypoints;               // the robot's (x, y, theta), certified when Found
  std::vector<ConnectivityGraph::Node> cells;  // the graph path: (roadmap manifold, cell)
  PathCheckResult certificate;
  OneRobotStats stats;
};

class OneRobotPlanner {
 public:
  /// Plans for robot `robot` of `scene` among the obstacles (other robots are ignored).
  OneRobotPlanner(const Scene& scene, size_t robot, OneRobotSettings settings);
  ~OneRobotPlanner();

  /// Grows the roadmap until start and goal connect through a certified motion, or until
  /// `stop` says so. `progress`, when set, is called after each round.
  OneRobotResult solve(const Pose& start, const Pose& goal, const Termination& stop,
                       const std::function<void(const OneRobotStats&)>& progress = {});

  const Roadmap& roadmap() const { return roadmap_; }
  const std::vector<Slice>& slices() const { return subspace().slices(); }
  const std::vector<Line>& lines() const { return subspace().lines(); }

 private:
  const Subspace& subspace() const { return *subspaces_.front(); }
  Subspace& subspace() { return *subspaces_.front(); }
  OneRobotResult solveRounds(const Pose& start, const Pose& goal, const Termination& stop,
                             const std::function<void(const OneRobotStats&)>& progress);
  Vec2 nextLinePoint();
  /// Pivot lines about the obstacles that fit the robot's pocket, once, with slices at the
  /// start's and the goal's angles if there are any.
  void addPivotLines(const Pose& start, const Pose& goal);
  void addPivotLine(const LineWorld& world, Vec2 pivot, Vec2 at);
  std::vector<Vec2> spinPlaces(double radius) const;
  void addSpinPlaces();
  void addEndSlices(const Pose& start, const Pose& goal);
  void addSlice(double theta);
  void addNextSlice();
  PlanStatus solveTranslation(const Pose& start, const Pose& goal, OneRobotResult& result);
  OneRobotResult finish(OneRobotResult result, PlanStatus status, double seconds);
  /// The statistics of the roadmap's whole life, this query's `seconds` counted.
  OneRobotStats statsSoFar(double seconds) const;

  Scene scene_;  // a one-robot copy: the planned robot only
  OneRobotSettings settings_;
  CollisionChecker checker_;
  Scene contactScene_;  // the robot shrunk as the checker sees it: manifolds are built for it
  SliceWorld sliceWorld_;
  Random rng_;
  AngleSequence angles_;
  bool pivotsAdded_ = false;
  bool spinsAdded_ = false;
  bool spinPlacesFound_ = false;  // some place where the robot can turn all the way round
  bool endSlicesAdded_ = false;   // for this query
  size_t extraSlices_ = 0;        // slices at queries' start and goal angles
  Roadmap roadmap_;
  std::vector<std::unique_ptr<Subspace>> subspaces_;  // exactly one: no robot is held
  // Slices of the next angles, built settings_.threads at a time ahead of their turn; they
  // join the roadmap one by one, so early stops do not depend on the thread count.
  std::deque<Slice> ahead_;
  OneRobotStats stats_;
};

/// The scene reduced to robot `robot` alone (other robots dropped), for one-robot planning.
Scene singleRobotScene(const Scene& scene, size_t robot);

}  // namespace mms
