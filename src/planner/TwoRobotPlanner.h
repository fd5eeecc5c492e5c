#pragma once
// Recursive MMS for two robots in the plane (6-D C-space), Section II of Salzman, Hemmer,
// Halperin, "On the power of manifold samples in exploring configuration spaces and the
// dimensionality of narrow passages".
//
// Fixing robot B at a free pose b leaves the 3-D subspace C^a x b, approximated by a one-robot
// MMS with B as an obstacle; symmetrically for A. The subspaces a x C^b and C^a x b meet at
// (a, b): the cell of the a-slice containing a's position and the cell of the b-slice containing
// b's position are joined in the graph (HeldRobotPlanner.h keeps the angle sets that make them
// meet). Start and goal enter as fixings at each robot's start and goal.
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "check/PathChecker.h"
#include "planner/CompoundSubspace.h"
#include "planner/FixingSamplers.h"
#include "planner/HeldRobotPlanner.h"

namespace mms {

struct TwoRobotSettings : HeldRobotSettings {
  // n_f: fixings per robot in the first round. Every round after the first doubles n_theta (the
  // new angles are the midpoints), so passages that need the robots' angles aligned closely are
  // reached too, and, once each rigid robot has 16 angles, n_f (anglesFirst in Rounds.h).
  size_t nFixings = 8;
  // Share of a translating robot's fixings drawn from the free-space cells already reached
  // from the start or the goal (the rest uniform over the robot's free space among the
  // obstacles). Such a fixing always meets the subspace it came from, so the graph grows into
  // passages where the robots stay tightly coupled (interlocked parts) that uniform fixings
  // would almost never hit.
  double expandShare = 0.5;
  // Of those, the share grown as RRT-Connect chains (both robots pushed in turn towards a
  // random target: interlocked parts climbing out together); the rest are single fixings in
  // reached cells (the smaller of two drawn uniformly), half of them near cell vertices (a part
  // tucked into a corner).
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
  // When the robots are close at start and goal, compound subspaces in which the pair keeps
  // its start or goal relative pose and moves as one rigid body (CompoundSubspace.h): a
  // gripper turning with the part it holds needs many alternating small moves of one robot at
  // a time otherwise.
  bool coupled = true;
};

struct TwoRobotStats : HeldRobotStats {
  size_t expandedFixings = 0;  // fixings drawn from cells reached from start or goal
  std::array<size_t, 2> fixings{0, 0};
  SubspaceStats compound;  // slices, lines, cells, arcs over the compound subspaces
};

using TwoRobotResult = HeldRobotResult<TwoRobotStats>;

/// The hold policy for two robots: fixings of either robot (FixingSamplers.h), each new
/// subspace joined to those of the other robot at the pair of their held poses.
class TwoRobotPlanner : public HeldRobotPlanner, private FixingHost {
 public:
  explicit TwoRobotPlanner(const Scene& scene, TwoRobotSettings settings = {});
  ~TwoRobotPlanner() override;

  TwoRobotResult solve(const Termination& stop,
                       const std::function<void(const TwoRobotStats&)>& progress = {});

 private:
  // The hold policy (HeldRobotPlanner)
  bool placeEnds(const Termination& stop) override;
  void endsPlaced(const Termination& stop) override { addCompound(stop); }
  void beginStretch() override { exhausted_ = {false, false}; }
  bool growing() override { return wants(0) || wants(1); }
  bool roundComplete() override;
  double roundShare() override;
  void growStep(const Termination& stop) override;
  void nextTargets(bool fixingsGrow) override;
  void roundGrown(const Termination& stop) override;
  void anglesAdded(size_t robot, size_t firstAngle, const Termination& stop) override;
  void cellAdded(size_t node, const Subspace& sub, uint32_t slice) override;
  bool wants(size_t robot) const;

  // FixingHost (TwoRobotGrowth.cpp): what the fixing sampler sees, and the subspaces it holds.
  Random& rng() override { return rng_; }
  const Box& bounds() const override { return scene_.bounds; }
  bool translates(size_t robot) const override { return translates_[robot]; }
  const std::vector<Slice>& baseSlices(size_t robot) const override { return base_[robot]; }
  const Roadmap& roadmap() const override { return roadmap_; }
  long startNode() const override { return from_; }
  long goalNode() const override { return to_; }
  const std::vector<size_t>& reachedCells(size_t robot) override {
    return HeldRobotPlanner::reachedCells()[robot];
  }
  const Box& cellBox(size_t node) const override { return cellBoxes_[node]; }
  const Slice& sliceOf(size_t node) const override;
  Fixing fixingAt(size_t robot, size_t angle, Vec2 p, long parent) const override {
    return {placementAt(robot, angle, p), robot, parent};
  }
  size_t hold(const Fixing& f, const Termination& stop) override { return addFixing(f, stop); }
  long nodeWhereHeld(size_t k, size_t held) const override;
  bool leavesRoom(const Fixing& f) override { return leavesRoomFor(f.robot, f.pose); }
  void countExpanded() override { ++stats_.expandedFixings; }

  size_t addFixing(const Fixing& held, const Termination& stop);
  std::vector<size_t> crossCandidates(const Fixing& held);
  void addCompound(const Termination& stop);
  void addCompoundLines(CompoundSubspace& c, size_t count, const Termination& stop);

  TwoRobotSettings hold_;
  TwoRobotStats stats_;
  std::unique_ptr<FixingSampler> sampler_;
  std::vector<Fixing> fixings_;  // fixings_[i] is held in subspaces_[i]
  // The first subspaces hold each robot at its start and at its goal (placeEnds).
  static constexpr size_t kRootSubspaces = 4;
  std::vector<std::unique_ptr<CompoundSubspace>> compounds_;  // the pair as one body, if close
  std::vector<Box> cellBoxes_;  // per slice-cell node: its bounding box
  size_t target_ = 0;           // fixings per robot this round, besides start and goal
  std::array<size_t, 2> fixingsAtRoundStart_{0, 0};
  std::array<bool, 2> exhausted_{false, false};  // the sampler found no fixing this stretch
};

}  // namespace mms
