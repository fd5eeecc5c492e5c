#pragma once
// Recursive MMS for two robots in the plane (6-D C-space), Section II of Salzman, Hemmer,
// Halperin, "On the power of manifold samples in exploring configuration spaces and the
// dimensionality of narrow passages".
//
// Fixing robot B at a free pose b leaves the 3-D subspace C^a x b, approximated by a one-robot
// MMS (slices and lines) with B as an obstacle; symmetrically for A. To make the approximations
// intersect, each robot gets one angle set for the whole run (Theta_a, Theta_b, each evenly
// spaced with its own random shift): every subspace in which A moves has a slice at each angle
// of Theta_a, and A is only ever fixed at angles of Theta_a. Then the subspaces a x C^b and
// C^a x b meet at (a, b): the cell of the a-slice containing a's position and the cell of the
// b-slice containing b's position are joined in the graph. The obstacles' Minkowski sums are
// computed once per angle; a subspace's slice only subtracts the held robot's sum (overlay).
// Start and goal enter as fixings plus lines at the moving robot's start and goal positions in
// every subspace; each rigid robot's angle set also starts with its start and goal angles (our
// addition: tight passages often lie around them). A robot that only translates has a single
// angle and needs no lines: its slices are its exact free space.
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "check/PathChecker.h"
#include "planner/CompoundSubspace.h"
#include "planner/FixingSamplers.h"
#include "planner/MmsPlanner.h"
#include "planner/Subspace.h"

namespace mms {

struct TwoRobotSettings {
  uint64_t seed = 1;
  // n_theta: angles of robot 0 (robot 1: one more) besides its start and goal angles, in all
  // its subspaces. A subspace costs an overlay per angle, and the rotations a tight passage
  // needs come from its lines and narrow-arc slices more than from the shared angles, which
  // double every round: on the tuning seeds 4 took 0.3-0.8 of the time 16 took. 2 was faster
  // still where the first round solves, but 2.5 times slower on the Viking helmet, whose
  // passage needs an angle neither the start's nor the goal's (docs/benchmarks.md).
  size_t nTheta = 4;
  // n_l: random lines of a new subspace. The four holding a robot at its start or goal add
  // n_l, 2 n_l, ... more in rounds 2, 3, ... (growRootLines).
  size_t nLines = 128;
  // n_f: fixings per robot in the first round. Every round after the first doubles n_theta (the
  // new angles are the midpoints), so passages that need the robots' angles aligned closely are
  // reached too, and, once each rigid robot has 16 angles, n_f (anglesFirst in Rounds.h).
  size_t nFixings = 8;
  // Share of a translating robot's fixings drawn from the free-space cells already reached
  // from the start or the goal (the rest uniform over the robot's free space among the obstacles).
  // Such a fixing always meets the subspace it came from, so the graph grows into passages where
  // the robots stay tightly coupled (interlocked parts) that uniform fixings would almost never
  // hit.
  double expandShare = 0.5;
  // Of those, the share grown as RRT-Connect chains (both robots pushed in turn towards a
  // random target: interlocked parts climbing out together); the rest are single fixings in
  // reached cells (the smaller of two drawn uniformly), half of them near cell vertices (a part
  // tucked into a corner). Measured on the assembly scenes: chains are needed for the first, and
  // slow the second down when they are the majority.
  double connectShare = 0.25;
  size_t connectSteps = 200;  // at most this many fixings per chain
  // Share of the other fixings drawn near a vertex of the robot's free space among the
  // obstacles (a robot tucked into a corner, out of the other's way); the rest uniform.
  double cornerShare = 0.5;
  // A corner fixing is the first of up to this many corner poses that cuts no passage of the
  // other robot at its start angle (one overlay each), else the last.
  size_t cornerCandidates = 16;
  // A new subspace is tested for meeting points against at most this many subspaces of the
  // other family: those whose held poses are nearest, plus a random sample of the rest.
  size_t crossNearest = 256, crossRandom = 256;
  // Slices at the middles of narrow free arcs of a subspace's lines that no shared angle meets
  // (local to the subspace), at most this many each time a subspace's new lines are scanned.
  size_t narrowSlices = 8;
  // When the robots are close at start and goal, compound subspaces in which the pair keeps
  // its start or goal relative pose and moves as one rigid body (CompoundSubspace.h): a
  // gripper turning with the part it holds needs many alternating small moves of one robot at
  // a time otherwise.
  bool coupled = true;
  // Give up after this many rounds (0: only the time limit stops it). A budget in rounds,
  // unlike one in seconds, gives the same answer for the same seed on any machine.
  size_t maxRounds = 0;
  // Threads that build overlays (a subspace's slices); the result does not depend on it.
  unsigned threads = 1;
};

struct TwoRobotStats {
  size_t rounds = 0, subspaces = 0, crossEdges = 0, graphNodes = 0, graphEdges = 0;
  size_t expandedFixings = 0;  // fixings drawn from cells reached from start or goal
  size_t screenedPoses = 0;    // corner poses screened by an overlay (leavesRoom), in "overlays"
  size_t pathCells = 0, rejectedPaths = 0;
  size_t pathManifolds = 0, pathSubspaces = 0;  // of those built: slices + lines, subspaces
  std::string noPath;  // why no path exists, when proved (PlanStatistics::noPath)
  std::array<size_t, 2> fixings{0, 0};
  SubspaceStats manifolds;  // slices, lines, cells, arcs over all one-robot subspaces
  SubspaceStats compound;   // the same over the compound subspaces (the pair as one body)
  double baseSliceSeconds = 0, crossSeconds = 0, searchSeconds = 0, motionSeconds = 0,
         certifySeconds = 0;
  double totalSeconds = 0;
};

struct TwoRobotResult {
  PlanStatus status = PlanStatus::NotFound;
  std::vector<Config> waypoints;  // both robots' (x, y, theta), certified when Found
  PathCheckResult certificate;
  TwoRobotStats stats;
};

class TwoRobotPlanner : private FixingHost {
 public:
  explicit TwoRobotPlanner(const Scene& scene, TwoRobotSettings settings = {});
  ~TwoRobotPlanner();

  TwoRobotResult solve(const Termination& stop,
                       const std::function<void(const TwoRobotStats&)>& progress = {});

 private:
  // Growth (TwoRobotGrowth.cpp): what the fixing sampler sees, and the subspaces fixings hold.
  TwoRobotResult solveRounds(const Termination& stop,
                             const std::function<void(const TwoRobotStats&)>& progress);
  void buildBaseSlices(const Termination& stop);
  void addOverlays(size_t count,
                   const std::function<std::pair<Subspace*, const Slice*>(size_t)>& item);
  // FixingHost
  Random& rng() override { return rng_; }
  const Box& bounds() const override { return scene_.bounds; }
  bool translates(size_t robot) const override { return translates_[robot]; }
  const std::vector<Slice>& baseSlices(size_t robot) const override { return base_[robot]; }
  const Roadmap& roadmap() const override { return roadmap_; }
  long startNode() const override { return from_; }
  long goalNode() const override { return to_; }
  const std::vector<size_t>& reachedCells(size_t robot) override;
  const Box& cellBox(size_t node) const override { return cellBoxes_[node]; }
  const Slice& sliceOf(size_t node) const override;
  Fixing fixingAt(size_t robot, size_t angle, Vec2 p, long parent) const override;
  size_t hold(const Fixing& f, const Termination& stop) override { return addSubspace(f, stop); }
  long nodeWhereHeld(size_t k, size_t held) const override;
  bool leavesRoom(const Fixing& f) override;
  void countExpanded() override { ++stats_.expandedFixings; }

  void collectCells(size_t firstNode);
  bool reached(size_t node) const;
  std::vector<size_t> crossCandidates(const Fixing& held);
  size_t addSubspace(const Fixing& held, const Termination& stop);
  long nodeFor(const Subspace& sub, const Fixing& f, bool knownFree = false) const;
  Vec2 linePoint(size_t robot);
  void growRootLines(size_t count, const Termination& stop);
  void addRandomLines(Subspace& sub, size_t count, const Termination& stop);
  void sliceNarrowArcs(Subspace& sub);
  void sliceNarrowArcsIfDisconnected();
  void sliceNarrowArcsNow();
  size_t angleCount(size_t robot) const;
  void addAngles(size_t robot, const std::vector<double>& thetas, const Termination& stop);
  void addCompound(const Termination& stop);
  void addCompoundLines(CompoundSubspace& c, size_t count, const Termination& stop);
  TwoRobotResult finish(TwoRobotResult r, PlanStatus status);

  Scene scene_;
  TwoRobotSettings settings_;
  CollisionChecker checker_;
  Scene contactScene_;  // robots shrunk as the checker sees them: manifolds are built for them
  Random rng_;
  std::unique_ptr<FixingSampler> sampler_;
  std::array<bool, 2> translates_;
  std::array<std::unique_ptr<SliceWorld>, 2> worlds_;
  std::array<std::unique_ptr<LineWorld>, 2> lineWorlds_;  // per robot: the obstacles alone
  std::array<std::unique_ptr<AngleSequence>, 2> angles_;
  std::array<size_t, 2> sequenceAngles_{0, 0};  // base slices from angles_ (after start, goal)
  std::array<std::vector<Slice>, 2>
      base_;                     // per robot: its slice at each of its angles, obstacles only
  std::vector<Fixing> fixings_;  // fixings_[i] is held in subspaces_[i]
  // The first subspaces hold each robot at its start and at its goal (solveRounds).
  static constexpr size_t kRootSubspaces = 4;
  std::vector<std::unique_ptr<Subspace>> subspaces_;
  std::vector<size_t> narrowPending_;  // subspaces whose narrow-arc slices are not built yet
  std::vector<size_t> narrowScanned_;  // per subspace: its lines scanned for narrow arcs
  std::vector<std::unique_ptr<CompoundSubspace>> compounds_;  // the pair as one body, if close
  Roadmap roadmap_;
  std::array<std::vector<size_t>, 2> cells_;    // per robot: slice-cell nodes where it moves
  std::array<std::vector<size_t>, 2> reached_;  // those connected to the start or goal
  size_t reachedScan_ = 0;                      // graph size at the last full scan
  std::vector<Box> cellBoxes_;                  // per slice-cell node: its bounding box
  long from_ = -1, to_ = -1;                    // start and goal nodes once known
  TwoRobotStats stats_;
  Stopwatch clock_;
};

}  // namespace mms
