#pragma once
// The core of recursive MMS for two robots or more (Salzman, Hemmer, Halperin, Section II): all
// robots but one held, the moving one's 3-D subspace approximated by exact slices and lines.
//
// Each robot gets one angle set for the whole run, evenly spaced with its own random shift and
// starting with its start and goal angles: every subspace in which it moves has a slice at each
// of them, and it is only ever held at them (or at its start or goal pose), so subspaces that
// hold it meet those where it moves. The obstacles' Minkowski sums are computed once per angle
// (base slices); a subspace's slice subtracts only the held robots (an overlay). Rounds double
// the angle sets, the random lines of the subspaces holding the robots at their start and goal,
// and the growth targets; narrow free arcs the held robots make get slices of their own.
//
// Where held poses come from is the *hold policy*, the one thing the variants decide:
// TwoRobotPlanner draws fixings (FixingSamplers.h) and joins each new subspace to those of the
// other robot; KRobotPlanner grows tuples from reached cells and moves robots greedily to the
// other side.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "check/PathChecker.h"
#include "planner/OneRobotPlanner.h"
#include "planner/Subspace.h"

namespace mms {

struct HeldRobotSettings {
  uint64_t seed = 1;
  // Angles of robot r: nTheta + r besides its start and goal angles, in all its subspaces.
  size_t nTheta = 4;
  // Random lines of a new subspace; with growRootLines, those holding a robot at its start or
  // goal add nLines, 2 nLines, ... more in rounds 2, 3, ...
  size_t nLines = 128;
  bool growRootLines = true;
  // Slices at the middles of narrow free arcs of a subspace's lines that no shared angle meets
  // (local to the subspace), at most this many each time a subspace's new lines are scanned.
  size_t narrowSlices = 8;
  // Give up after this many rounds (0: only the time limit stops it). A budget in rounds,
  // unlike one in seconds, gives the same answer for the same seed on any machine.
  size_t maxRounds = 0;
  // Threads that build overlays (a subspace's slices); the result does not depend on it.
  unsigned threads = 1;
  // Tracks when manifolds join the start's and the goal's component (OneRobotSettings::record).
  bool record = false;
};

struct HeldRobotStats {
  size_t rounds = 0, subspaces = 0, crossEdges = 0, graphNodes = 0, graphEdges = 0;
  double roundShare = 0;     // of the last round's targets met (PlanStatistics::roundShare)
  size_t screenedPoses = 0;  // held poses screened by an overlay (leavesRoom), in "overlays"
  size_t pathCells = 0, rejectedPaths = 0;
  size_t pathManifolds = 0, pathSubspaces = 0;  // of those built: slices + lines, subspaces
  std::string noPath;       // why no path exists, when proved (PlanStatistics::noPath)
  SubspaceStats manifolds;  // slices, lines, cells, arcs over all one-robot subspaces
  double baseSliceSeconds = 0, crossSeconds = 0, searchSeconds = 0, motionSeconds = 0,
         certifySeconds = 0;
  double totalSeconds = 0;
};

template <class Stats>
struct HeldRobotResult {
  PlanStatus status = PlanStatus::NotFound;
  std::vector<Config> waypoints;  // all robots' (x, y, theta), certified when Found
  PathCheckResult certificate;
  Stats stats;
};

class HeldRobotPlanner {
 public:
  HeldRobotPlanner(const HeldRobotPlanner&) = delete;
  HeldRobotPlanner& operator=(const HeldRobotPlanner&) = delete;
  virtual ~HeldRobotPlanner();
  const Roadmap& roadmap() const { return roadmap_; }

 protected:
  /// `stats` is the variant's, constructed after this base: only used once solving.
  HeldRobotPlanner(const Scene& scene, const HeldRobotSettings& settings, HeldRobotStats& stats);

  /// The rounds: base slices, the policy's ends, then growth until a certified path, the
  /// limit or maxRounds. `report` is called about once a second and after each search.
  PlanStatus run(const Termination& stop, const std::function<void()>& report,
                 std::vector<Config>& waypoints, PathCheckResult& certificate);
  /// run() with the variant's statistics (`stats`, the ones given to the constructor) in its
  /// result and progress reports.
  template <class Stats>
  HeldRobotResult<Stats> solveReporting(const Termination& stop,
                                        const std::function<void(const Stats&)>& progress,
                                        Stats& stats) {
    HeldRobotResult<Stats> r;
    auto report = [&] {
      if (!progress) return;
      updateTotals();
      progress(stats);
    };
    r.status = run(stop, report, r.waypoints, r.certificate);
    updateTotals();
    r.stats = stats;
    return r;
  }
  /// The graph's size and the seconds so far in the statistics.
  void updateTotals();

  // The hold policy.
  /// Builds the subspaces holding the robots at their start and goal and sets from_ and to_;
  /// false if start or goal lies in no cell.
  virtual bool placeEnds(const Termination& stop) = 0;
  /// After placeEnds, before the first round (the compounds for two robots, the greedy moves
  /// for k).
  virtual void endsPlaced(const Termination&) {}
  virtual void beginStretch() {}
  virtual bool growing() = 0;        // whether growth goes on in this stretch of the round
  virtual bool roundComplete() = 0;  // the round's targets are met
  virtual double roundShare() = 0;   // how much of them (0 to 1)
  virtual void growStep(const Termination& stop) = 0;
  /// The next round's targets; `fixingsGrow`: the angle sets are large enough (anglesFirst).
  virtual void nextTargets(bool fixingsGrow) = 0;
  /// After a round's new angles and root lines (the compounds' lines, for two robots).
  virtual void roundGrown(const Termination&) {}
  /// Angles from `firstAngle` on were added to `robot`'s base slices.
  virtual void anglesAdded(size_t /*robot*/, size_t /*firstAngle*/, const Termination&) {}
  /// A new slice-cell node at a shared angle (the two-robot policy keeps its bounding box).
  virtual void cellAdded(size_t /*node*/, const Subspace&, uint32_t /*slice*/) {}

  // What the policies build with.
  /// A new subspace in which `moving` moves and the others stay at `held`: an overlay per
  /// angle of its set, and (a rigid robot) lines at its start and goal positions (lines 0 and
  /// 1) and nLines random ones; then `join` (timed as "cross") links it to other subspaces
  /// before its cells are collected. Registered for findSubspace.
  size_t addSubspace(size_t moving, const std::vector<std::pair<size_t, Pose>>& held,
                     const Termination& stop, const std::function<void(Subspace&)>& join = {});
  /// The subspace in which `moving` moves and the others stay at `held`, or -1.
  long findSubspace(size_t moving, const std::vector<std::pair<size_t, Pose>>& held) const;
  long nodeFor(const Subspace& sub, const Placement& p, bool knownFree = false) const;
  /// A placement of `robot` at p at angle `angleIndex` of its set (a translating robot keeps its
  /// own angle).
  Placement placementAt(size_t robot, size_t angleIndex, Vec2 p) const;
  /// Robots held at their start (false: goal) poses.
  Placement endPlacement(size_t robot, bool start) const;
  /// Whether `robot` at `pose` leaves every other robot, at its start angle, no more free-space
  /// cells than the obstacles alone: it cuts none of their passages. One overlay per robot.
  bool leavesRoomFor(size_t robot, const Pose& pose);
  bool reached(size_t node) const;
  /// Per robot: slice-cell nodes at shared angles where it moves, connected to the start or
  /// goal; rescanned once the graph has grown by a quarter (amortised constant per node).
  const std::vector<std::vector<size_t>>& reachedCells();
  /// Narrow-arc slices for the subspaces waiting, unless start and goal already connect.
  void sliceNarrowArcsIfDisconnected();
  Vec2 linePoint(size_t robot);

  Scene scene_;
  HeldRobotSettings settings_;
  CollisionChecker checker_;
  Scene contactScene_;  // robots shrunk as the checker sees them: manifolds are built for them
  Random rng_;
  size_t k_;
  std::vector<char> translates_;
  std::vector<std::unique_ptr<SliceWorld>> worlds_;
  std::vector<std::unique_ptr<LineWorld>> lineWorlds_;  // per robot: the obstacles alone
  std::vector<std::vector<Slice>> base_;  // per robot: its slice at each angle, obstacles only
  std::vector<std::unique_ptr<Subspace>> subspaces_;
  Roadmap roadmap_;
  long from_ = -1, to_ = -1;  // start and goal nodes once known
  size_t rootSubspaces_ = 0;  // the first ones, holding robots at start and goal (placeEnds)
  HeldRobotStats& common_;
  Stopwatch clock_;
  // New angles' overlays are added subspace by subspace (else angle by angle). The order only
  // numbers the nodes, but that steers the random draws: the k-robot policy keeps the order it
  // was tuned with (angle by angle gave it longer tails on niche-three, docs/planner.md).
  bool overlaysBySubspace_ = false;

 private:
  void buildBaseSlices(const Termination& stop);
  void addAngles(size_t robot, const std::vector<double>& thetas, const Termination& stop);
  void addOverlays(size_t count,
                   const std::function<std::pair<Subspace*, const Slice*>(size_t)>& item);
  void addRandomLines(Subspace& sub, size_t count, const Termination& stop);
  void growRootLines(size_t count, const Termination& stop);
  void sliceNarrowArcs(Subspace& sub);
  void sliceNarrowArcsNow();
  void collectCells(size_t firstNode);
  PlanStatus runRoundsFrom(const Termination& stop, const std::function<void()>& report,
                           std::vector<Config>& waypoints, PathCheckResult& certificate);
  bool nextRound(const Termination& stop);

  std::vector<std::unique_ptr<AngleSequence>> angles_;
  std::vector<size_t> sequenceAngles_;  // per robot: base slices from angles_ (after start, goal)
  std::map<std::vector<double>, size_t> byHeld_;  // (moving, held poses) -> subspace
  std::vector<size_t> narrowPending_;         // subspaces whose narrow-arc slices are not built yet
  std::vector<size_t> narrowScanned_;         // per subspace: its lines scanned for narrow arcs
  std::vector<std::vector<size_t>> cells_;    // per robot: slice-cell nodes where it moves
  std::vector<std::vector<size_t>> reached_;  // those connected to the start or goal
  size_t reachedScan_ = 0;                    // graph size at the last full scan
  size_t rootLines_ = 0;                      // random lines the root subspaces add next round
};

}  // namespace mms
