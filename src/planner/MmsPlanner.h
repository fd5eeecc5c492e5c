#pragma once
// MMS for one rigid polygonal robot that translates and rotates (3-D C-space): horizontal
// slices (fixed angle, exact free space of the reference point) and vertical lines (fixed
// position, free arcs of angles) as manifold samples; their free-space cells are the nodes of
// the connectivity graph, joined where a line's point lies in a slice cell and the slice's
// angle lies in the line's arc. Anytime: while start and goal are not connected, the numbers
// of slices and lines double. Multi-query: the roadmap stays for further queries.
//
// Salzman, Hemmer, Raveh, Halperin: "Motion planning via manifold samples", ESA 2011 /
// Algorithmica 2013; Salzman, Hemmer, Halperin: "On the power of manifold samples in exploring
// configuration spaces and the dimensionality of narrow passages", Section I-B and appendix.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "check/PathChecker.h"
#include "graph/ConnectivityGraph.h"
#include "manifolds/Line.h"
#include "manifolds/Slice.h"
#include "util/Random.h"
#include "util/Termination.h"

namespace mms {

struct MmsSettings {
  uint64_t seed = 1;
  size_t nTheta = 16;     // n_theta: slices in the first round (the paper's name)
  size_t nLines = 1024;   // n_l: lines in the first round (a line costs ~10 us, a slice ~1 ms)
  double freeLineShare = 0.5;  // share of line points drawn inside slice FSCs, the rest uniform
  size_t shortcutAttempts = 200;
  PointLocation pointLocation = PointLocation::Auto;
};

struct MmsStats {
  size_t rounds = 0, slices = 0, lines = 0, sliceCells = 0, lineArcs = 0;
  size_t graphNodes = 0, graphEdges = 0;
  size_t pathCells = 0;        // FSCs on the graph path
  size_t rejectedPaths = 0;    // candidate motions the checker refused
  double sliceSeconds = 0, lineSeconds = 0, connectSeconds = 0, searchSeconds = 0;
  double motionSeconds = 0, certifySeconds = 0, totalSeconds = 0;
  LineStats lineStats;
};

struct MmsResult {
  enum class Status { Found, NotFound, Cancelled } status = Status::NotFound;
  std::vector<Config> waypoints;  // the robot's (x, y, theta), certified when Found
  std::vector<ConnectivityGraph::Node> cells;  // the graph path: line arcs and slice cells
  PathCheckResult certificate;
  MmsStats stats;
};

class MmsPlanner {
 public:
  /// Plans for robot `robot` of `scene` among the obstacles (other robots are ignored).
  MmsPlanner(const Scene& scene, size_t robot, MmsSettings settings);
  ~MmsPlanner();

  /// Grows the roadmap until start and goal connect through a certified motion, or until
  /// `stop` says so. `progress`, when set, is called after each round.
  MmsResult solve(const Pose& start, const Pose& goal, const Termination& stop,
                  const std::function<void(const MmsStats&)>& progress = {});

  const MmsStats& stats() const { return stats_; }
  const std::vector<Slice>& slices() const { return slices_; }
  const std::vector<Line>& lines() const { return lines_; }

 private:
  double nextAngle();
  Vec2 nextLinePoint();
  void addSlice(double theta);
  size_t addLine(Vec2 p);
  std::vector<Config> motion(const std::vector<size_t>& nodes, const Pose& start, const Pose& goal);
  void shortcut(std::vector<Config>& w);
  MmsResult::Status solveTranslation(const Pose& start, const Pose& goal, MmsResult& result);

  Scene scene_;  // a one-robot copy: the planned robot only
  MmsSettings settings_;
  CollisionChecker checker_;
  SliceWorld sliceWorld_;
  LineWorld lineWorld_;
  Random rng_;
  double angleShift_;
  size_t angleCount_ = 0;

  std::vector<Slice> slices_;
  std::vector<Line> lines_;
  std::vector<std::vector<size_t>> sliceNodes_, lineNodes_;  // cell -> graph node
  ConnectivityGraph graph_;
  MmsStats stats_;
};

/// The scene reduced to robot `robot` alone (other robots dropped), for one-robot planning.
Scene singleRobotScene(const Scene& scene, size_t robot);

}  // namespace mms
