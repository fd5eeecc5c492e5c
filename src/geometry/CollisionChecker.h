#pragma once
// The collision checker every planner shares (MMS's path certification and the OMPL
// baselines alike), so that all of them plan against one definition of free space.
//
// Free: the robot lies inside the bounds and its interior is disjoint from every obstacle's
// and every other robot's interior. Touching is free within the scene tolerance delta: each
// robot is tested as its shape shrunk inwards by delta (mitred offset), so contacts up to
// depth delta count as touching, and exact contacts (as MMS produces them) are never
// reported as collisions however the doubles round.
//
// Disc robots and disc obstacles are tested as the discs they are, not their polygonal
// stand-ins: a disc robot is shrunk by delta as well, and a disc contact is found by its
// centre's distance (a floating-point test is exact enough here: delta is the margin).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "mms/Scene.h"

namespace mms {

/// What a placement hits (or, for clearance, what is nearest).
struct Contact {
  enum class Kind { None, Bounds, Obstacle, Robot } kind = Kind::None;
  size_t index = 0;  // obstacle index or other robot's index
  std::string describe(const Scene& scene) const;
};

/// Shrinks a robot shape by the contact tolerance; error text when its features are too
/// small for that (the shrunk ring would not be simple or not inside the shape).
struct ShrunkShape {
  Ring ring;
  std::optional<std::string> error;
};
ShrunkShape shrinkForContacts(const Ring& shape, double tolerance);

class CollisionChecker {
 public:
  /// The scene must have been validated (robot shapes shrink without error).
  explicit CollisionChecker(const Scene& scene);

  /// Robot `robot` at `pose` against the bounds and the obstacles (other robots ignored).
  bool robotFree(size_t robot, const Pose& pose) const;
  /// A test that costs a point's, before robotFree where most poses are blocked (a sampler's
  /// redrawn samples in a tight scene): true when the robot's reference point, which its
  /// shrunk shape holds, lies in an obstacle, so that the robot meets it. False says nothing
  /// (always so for a robot whose reference point lies outside its shape).
  bool referenceBlocked(size_t robot, const Pose& pose) const;
  /// Robots a and b at their poses do not overlap.
  bool robotsDisjoint(size_t a, const Pose& pa, size_t b, const Pose& pb) const;
  /// Every robot free and no two robots overlap.
  bool isFree(const Config& q) const;

  /// The first thing a robot hits, for messages (Kind::None when free).
  Contact robotContact(size_t robot, const Pose& pose) const;
  /// First contact of any robot in q: the robot's index and what it hits.
  std::optional<std::pair<size_t, Contact>> firstContact(const Config& q) const;

  struct Clearance {
    double distance = 0;  // of the shrunk shape; 0 when it touches or overlaps
    Contact nearest;
  };
  /// Distance from the (shrunk) robot to the bounds and the obstacles.
  /// With a bound: the bound when nothing is nearer (`nearest` then names the bounds).
  Clearance robotClearance(size_t robot, const Pose& pose,
                           double bound = std::numeric_limits<double>::infinity()) const;
  /// Distance between two (shrunk) robots, or `bound` when it is at least that (far robots
  /// then cost a box test per edge instead of a test per pair of edges).
  double robotsDistance(size_t a, const Pose& pa, size_t b, const Pose& pb,
                        double bound = std::numeric_limits<double>::infinity()) const;

  /// A disc robot translating from a to b sweeps a stadium: its distance (shrunk, as for
  /// clearances) to the bounds and the obstacles over the whole motion, exactly, or `bound`
  /// when it is at least that.
  Clearance sweptDiscClearance(size_t robot, Vec2 a, Vec2 b,
                               double bound = std::numeric_limits<double>::infinity()) const;
  /// Disc robot i translating from ai to bi and robot j from aj to bj (a disc, or a polygon that
  /// stands still at pj): the least distance between them over the motion, exactly (for two
  /// discs, the distance of their relative motion's segment from the origin).
  double sweptDiscDistance(size_t i, Vec2 ai, Vec2 bi, size_t j, Vec2 aj, Vec2 bj,
                           const Pose& pj) const;

  /// Robot tests and distances (one robot against the bounds and obstacles, or one pair of
  /// robots) that any checker made on the calling thread: work counted where time would depend
  /// on the machine's load, so that budgets measured in it keep a seed's results the same.
  static size_t workOnThisThread();

  double tolerance() const { return tolerance_; }
  /// Up to this many robots every pair is tested; beyond, only pairs a sweep over the robots'
  /// discs finds near (geometry/BroadPhase.h). Either way the same pairs collide.
  static constexpr size_t kAllPairsUpTo = 16;
  /// Radius of robot's disc shrunk by the tolerance; 0 for a polygon robot.
  double disc(size_t robot) const { return discs_[robot]; }
  /// Largest distance of a shape point from its frame origin: a rotation by dtheta moves no
  /// point of the robot further than radius * |dtheta|.
  double radius(size_t robot) const { return radii_[robot]; }
  /// The shrunk polygon; for a disc robot a polygon inscribed in its shrunk disc (what a proof
  /// that no path exists may take it to hold).
  const Ring& shrunkShape(size_t robot) const { return shapes_[robot]; }
  size_t robotCount() const { return shapes_.size(); }

 private:
  Box bounds_;
  double tolerance_;
  std::vector<Ring> obstacles_;
  std::vector<Disc> obstacleDiscs_;  // radius 0 for polygons
  std::vector<Box> obstacleBoxes_;
  std::vector<Ring> shapes_;
  std::vector<double> radii_;
  std::vector<double> discs_;
  std::vector<bool> holdsReference_;  // whether the shrunk shape holds its frame's origin
  // Names this checker's shapes for the per-thread cache of placed robots (one per robot, its
  // last pose): an evaluation tests each robot against the obstacles and then in every pair,
  // and held robots keep their pose from one evaluation to the next.
  uint64_t shapesId_;
};

}  // namespace mms
