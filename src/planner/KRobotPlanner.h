#pragma once
// MMS for k >= 3 robots: recursive MMS (Salzman, Hemmer, Halperin, Section II) with every robot
// but one held. A *tuple* places all k robots; in the subspace (i, tuple) robot i moves among the
// obstacles and the others, held where the tuple puts them: a 3-D C-space approximated by exact
// slices and lines, as one robot's. Two subspaces (i, t) and (j, t) of one tuple meet at t
// itself, so a tuple joins the subspaces of all its robots.
//
// With two robots, any fixing of one meets any fixing of the other (the pair of their poses);
// with three or more, two tuples share a subspace only where they agree on all robots but one,
// which independent random tuples never do. So tuples grow from cells already reached, as RRT
// and EST grow trees over exact cells: a point p in a reached cell of subspace (i, t) makes the
// tuple t' (t with robot i at p), reached too, and a subspace of t' for another robot carries
// the growth on. Start and goal are two such trees; they meet when a tuple agrees with the
// other side's on all robots but one. To make that happen, each new subspace is also tried
// greedily: if its robot can reach its pose on the other side (its goal, for a tuple reached
// from the start), it is put there and the next robot is tried in turn, until all are there
// (the tuple joins the other side's subspaces) or one cannot move. A robot that must make way
// (wait in a niche while the others pass) is what the random growth provides.
//
// Probabilistic completeness, informally: every reached cell keeps a positive chance of
// producing tuples anywhere in it, the angle sets double every round (as with two robots), and
// the lines of each subspace are uniform, so the reachable tuples' subspaces cover any
// robust path's neighbourhood with probability going to 1; each step is exact, and every path
// returned is certified.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "check/PathChecker.h"
#include "planner/MmsPlanner.h"
#include "planner/Subspace.h"

namespace mms {

struct KRobotSettings {
  uint64_t seed = 1;
  // Angles of robot r: nTheta + r besides its start and goal angles, in all subspaces where it
  // moves. Not as few as two robots' (TwoRobotSettings::nTheta): on three robots in a niche
  // corridor (seeds 1-10, one robot rigid or translating, 12 planner seeds) 4 and 8 took 0.45
  // and 0.6 of the median time, but 1.03 and 0.82 of the total: runs that needed more tuples
  // waited for the angles, up to 7.8 and 2.4 s where 16 took at most 0.8 s.
  size_t nTheta = 16;
  size_t nLines = 128;  // random lines per subspace
  size_t nTuples = 8;   // tuples grown in the first round; doubles every round, with the angles
  // Share of growth points drawn near a vertex of their cell (a robot tucked into a corner, out
  // of the others' way); the rest uniform in the cell.
  double cornerShare = 0.5;
  // A growth point is the first of up to this many (each in a cell drawn anew) at which its
  // robot cuts no passage of any other robot at its start angle (one overlay per robot), else
  // the last.
  size_t screenCandidates = 16;
  size_t maxRounds = 0;  // 0: only the time limit stops it
  unsigned threads = 1;  // accepted for the seam; overlays are built on one thread
};

struct KRobotStats {
  size_t rounds = 0, subspaces = 0, tuples = 0, greedyMoves = 0, crossEdges = 0;
  size_t screenedPoses = 0;  // growth points screened by an overlay, in "overlays"
  size_t graphNodes = 0, graphEdges = 0, pathCells = 0, rejectedPaths = 0;
  size_t pathManifolds = 0, pathSubspaces = 0;
  std::string noPath;  // why no path exists, when proved (PlanStatistics::noPath)
  SubspaceStats manifolds;
  double baseSliceSeconds = 0, crossSeconds = 0, searchSeconds = 0, motionSeconds = 0,
         certifySeconds = 0;
  double totalSeconds = 0;
};

struct KRobotResult {
  PlanStatus status = PlanStatus::NotFound;
  std::vector<Config> waypoints;  // all robots' (x, y, theta), certified when Found
  PathCheckResult certificate;
  KRobotStats stats;
};

class KRobotPlanner {
 public:
  explicit KRobotPlanner(const Scene& scene, KRobotSettings settings = {});
  ~KRobotPlanner();

  KRobotResult solve(const Termination& stop,
                     const std::function<void(const KRobotStats&)>& progress = {});

 private:
  /// Where a tuple puts one robot: a pose at an angle of its set (a slice of every subspace
  /// where it moves), or its start or goal pose (lines 0 and 1 of those subspaces).
  struct Anchor {
    Pose pose;
    long angle = -1;  // index into the robot's angle set, or -1
    long line = -1;   // 0 / 1: start / goal position, or -1
  };
  using Tuple = std::vector<Anchor>;

  KRobotResult solveRounds(const Termination& stop,
                           const std::function<void(const KRobotStats&)>& progress);
  void addAngles(size_t robot, const std::vector<double>& thetas, const Termination& stop);
  size_t subspaceFor(size_t moving, const Tuple& t, const Termination& stop);
  long existing(size_t moving, const Tuple& t) const;
  long nodeFor(const Subspace& sub, const Anchor& a) const;
  void join(const Tuple& t);
  void grow(const Termination& stop);
  void towardsOtherSide(Tuple t, bool fromStart, const Termination& stop);
  bool leavesRoom(size_t robot, const Pose& p);
  bool reached(size_t node) const;
  size_t movingAt(size_t node) const;  // the robot that moves in the node's subspace
  bool rescanReached();
  void collectCells(size_t firstNode);
  KRobotResult finish(KRobotResult r, PlanStatus status);

  Scene scene_;
  KRobotSettings settings_;
  CollisionChecker checker_;
  Scene contactScene_;  // robots shrunk as the checker sees them: manifolds are built for them
  Random rng_;
  size_t k_;
  std::vector<bool> translates_;
  std::vector<std::unique_ptr<SliceWorld>> worlds_;
  std::vector<std::unique_ptr<AngleSequence>> angles_;
  std::vector<size_t> sequenceAngles_;    // per robot: base slices from angles_ (after start, goal)
  std::vector<std::vector<Slice>> base_;  // per robot: its slice at each angle, obstacles only
  std::vector<std::unique_ptr<Subspace>> subspaces_;
  std::vector<Tuple> tuples_;  // tuples_[i]: the tuple subspaces_[i] was made for
  std::map<std::vector<double>, size_t> byHeld_;  // (moving, held poses) -> subspace
  Tuple start_, goal_;
  Roadmap roadmap_;
  std::vector<size_t> cells_;  // slice-cell nodes at shared angles
  // Per moving robot: those connected to the start or goal. Growth draws the robot first, so a
  // robot with few angles (one that translates has one) is not drawn in proportion to its cells.
  std::vector<std::vector<size_t>> reached_;
  size_t reachedScan_ = 0;
  size_t grown_ = 0;  // growth steps taken (a step may fail to draw a point)
  long from_ = -1, to_ = -1;
  KRobotStats stats_;
  Stopwatch clock_;
};

}  // namespace mms
