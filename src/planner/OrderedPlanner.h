#pragma once
// MMS for many robots: robots moved one at a time, in an order, each through its own exact
// free space while the others stay where they are; the k-robot MMS takes over for robots that
// block each other.
//
// A robot that moves alone among robots that stand still is one robot among obstacles: its
// free space at its angle is one exact slice (the paper's fixed-angle manifold) of the
// obstacles and of the robots that stand. A move tries, cheapest first: the straight motion;
// the route through its cell of the obstacles' slice (one per shape and angle,
// manifolds/CellRoute.h); the route through an exact slice of a region round that route alone,
// with the obstacles and standing robots reaching into it, the region grown until it joins
// start and goal. A rigid robot that must turn (or cannot translate there) gets a few rounds
// of the one-robot MMS among the obstacles and the standing robots. Each is certified with the
// others held before it is taken, and the whole path again at the end.
//
// Order: passes over the robots not yet at their goal, those furthest along the robots' common
// direction of travel first (a grid going to another grid empties from its front), until a
// pass moves nobody. The robots left then block each other (or their goals are walled in by
// robots already there). Robots of one shape that translate are shuffled on a pebble graph
// (planner/PebbleMotion.h): placements that step aside, one robot moving at a time. Else the
// k-robot MMS plans the robots left together, the robots at their goals held as obstacles, and
// failing that all robots from where they stand. This is the revolving-areas
// order of Agarwal, Geft, Halperin and Taylor (2022) without its step-aside moves: where a
// robot must make way, the k-robot MMS finds the way. Probabilistic completeness is the
// k-robot MMS's, run last over all robots from a configuration the ordered moves reached along
// certified motions (docs/planner.md).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "check/PathChecker.h"
#include "geometry/CollisionChecker.h"
#include "mms/Planner.h"
#include "mms/Scene.h"
#include "mms/Termination.h"
#include "planner/HeldRobotPlanner.h"
#include "planner/PebbleMotion.h"

namespace mms {

struct OrderedSettings {
  uint64_t seed = 1;  // for the k-robot MMS of robots that block each other
  unsigned threads = 1;
  /// The first region round the obstacles' route reaches this many moving-robot diameters past
  /// it (doubled while its slice does not join start and goal).
  double regionDiameters = 3;
  PebbleSettings pebbles;
};

struct OrderedStats {
  size_t passes = 0, moves = 0, straightMoves = 0, routeMoves = 0, regionMoves = 0, turnMoves = 0;
  size_t regionSlices = 0, baseSlices = 0, jointRobots = 0;  // jointRobots: left to the k-robot MMS
  PebbleStats pebbles;                                       // the shuffle, when it ran
  double baseSliceSeconds = 0, routeSeconds = 0, regionSeconds = 0, turnSeconds = 0,
         pebbleSeconds = 0, jointSeconds = 0, certifySeconds = 0, totalSeconds = 0;
  std::string noPath;
};

using OrderedResult = HeldRobotResult<OrderedStats>;

class OrderedPlanner {
 public:
  explicit OrderedPlanner(const Scene& scene, OrderedSettings settings = {});
  ~OrderedPlanner();
  OrderedPlanner(const OrderedPlanner&) = delete;
  OrderedPlanner& operator=(const OrderedPlanner&) = delete;

  OrderedResult solve(const Termination& stop,
                      const std::function<void(const OrderedStats&)>& progress = {});

 private:
  struct ShapeSlice;
  std::vector<size_t> order() const;
  bool moveAlone(size_t robot, const Termination& stop);
  bool translateAlone(size_t robot, const Termination& stop);
  bool turnAlone(size_t robot, const Termination& stop);
  Scene heldScene(const std::vector<size_t>& robots) const;
  Config withMoved(const std::vector<size_t>& robots, const Config& sub) const;
  /// A sub-planner's settings with this planner's seed and threads.
  template <class Settings>
  Settings seeded(Settings s) const {
    s.seed = settings_.seed;
    s.threads = settings_.threads;
    return s;
  }
  bool take(size_t robot, const std::vector<Vec2>& route);
  ShapeSlice& sliceOf(size_t robot);
  Scene regionScene(size_t robot, const Box& region) const;
  bool shuffle(const Termination& stop);
  bool planJointly(std::vector<size_t> robots, bool othersAsObstacles, const Termination& stop);

  Scene scene_;
  OrderedSettings settings_;
  CollisionChecker checker_;
  OrderedStats stats_;
  Config q_;                   // where every robot stands now
  std::vector<Config> path_;   // from the start to q_
  std::vector<bool> atGoal_;   // per robot
  std::vector<long> shapeOf_;  // per robot: its ShapeSlice, -1 until needed
  std::vector<std::unique_ptr<ShapeSlice>> slices_;
  std::vector<Box> obstacleBoxes_;
};

}  // namespace mms
