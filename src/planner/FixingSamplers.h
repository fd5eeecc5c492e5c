#pragma once
// How the two-robot planner picks its fixings: the seam. A sampler holds a robot at new poses
// (each a new subspace) through the FixingHost, the planner's narrow face to it, and never
// touches the roadmap itself. The paper draws fixings uniformly from each robot's free space
// among the obstacles (UniformFixings); that finds passages wide in the held robot's plane,
// but not placements where the two robots must stay tightly coupled (interlocked parts, a part
// tucked into a corner so the other can pass), which are tiny in area. Fixings drawn from the
// exact free-space cells already reached from the start or the goal (FrontierFixings,
// ConnectChains) always meet the subspace they come from, so they grow the graph into such
// places, as EST and RRT grow trees. MixedFixings is the planner's policy over the three.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "graph/Roadmap.h"
#include "manifolds/Slice.h"
#include "mms/Termination.h"
#include "planner/Subspace.h"
#include "util/Random.h"

namespace mms {

/// A robot held at a pose: the subspace in which the other robot moves.
struct Fixing : Placement {
  size_t robot = 0;
  long parent = -1;  // the subspace whose cell it was drawn from, or -1
};

/// What a sampler may read of the two-robot planner, and the one thing it may do: hold.
class FixingHost {
 public:
  virtual Random& rng() = 0;
  virtual const Box& bounds() const = 0;
  virtual bool translates(size_t robot) const = 0;
  /// The robot's slices among the obstacles alone, one per angle of its set.
  virtual const std::vector<Slice>& baseSlices(size_t robot) const = 0;
  virtual const Roadmap& roadmap() const = 0;
  /// The start and goal nodes, once they are known (-1 before).
  virtual long startNode() const = 0;
  virtual long goalNode() const = 0;
  /// Slice-cell nodes (at shared angles) where `robot` moves and that are connected to the
  /// start or the goal; rescanned as the roadmap grows.
  virtual const std::vector<size_t>& reachedCells(size_t robot) = 0;
  virtual const Box& cellBox(size_t node) const = 0;
  /// The slice a slice-cell node lies in.
  virtual const Slice& sliceOf(size_t node) const = 0;
  /// A fixing of `robot` at p at angle `angle` of its set (a translating robot keeps its own
  /// angle), drawn from a cell of subspace `parent` (or -1).
  virtual Fixing fixingAt(size_t robot, size_t angle, Vec2 p, long parent) const = 0;
  /// The same at p in a slice-cell node's slice, drawn from that node's subspace.
  Fixing fixingIn(size_t robot, size_t node, Vec2 p) const {
    const Roadmap::Entry& e = roadmap().entryOf(node);
    return fixingAt(robot, e.index, p, long(e.group));
  }
  /// Adds the subspace holding f, joins it to the others; returns its index.
  virtual size_t hold(const Fixing& f, const Termination& stop) = 0;
  /// The node of subspace `k` whose cell holds the pose at which subspace `held` holds its
  /// robot (the robot that moved there stands still here), or -1.
  virtual long nodeWhereHeld(size_t k, size_t held) const = 0;
  /// Whether the other robot, at the first angle of its set (its start angle), has no more
  /// free-space cells with f held than among the obstacles alone: f cuts none of its passages
  /// (a robot waiting in a niche, not across the corridor). One overlay: far cheaper than the
  /// subspace f would make.
  virtual bool leavesRoom(const Fixing& f) = 0;
  /// Counts a fixing drawn from reached cells (statistics).
  virtual void countExpanded() = 0;

 protected:
  ~FixingHost() = default;
};

class FixingSampler {
 public:
  virtual ~FixingSampler() = default;
  /// Holds `robot` at one or more new poses; false if it found none to hold.
  virtual bool grow(size_t robot, FixingHost& host, const Termination& stop) = 0;
};

/// The paper's: a free pose of the robot among the obstacles at one of its angles, uniform over
/// the slice.
class UniformFixings final : public FixingSampler {
 public:
  bool grow(size_t robot, FixingHost& host, const Termination& stop) override;
};

/// A free pose near a vertex of a cell of the robot's slice among the obstacles (slice and cell
/// uniform, then a vertex): a robot tucked into a corner, out of the other's way (waiting in a
/// niche, pressed into a pocket). Such poses are a sliver of the free space by area, so
/// UniformFixings almost never draws them. Of up to `candidates` such poses it holds the first
/// that leaves the other robot room (FixingHost::leavesRoom), else the last: most corners of a
/// corridor block it, the niche's do not.
class CornerFixings final : public FixingSampler {
 public:
  explicit CornerFixings(size_t candidates = 1) : candidates_(std::max<size_t>(1, candidates)) {}
  bool grow(size_t robot, FixingHost& host, const Termination& stop) override;

 private:
  size_t candidates_;
};

/// One fixing in a reached cell: the smaller of two drawn uniformly, half of the points near
/// the cell's vertices.
class FrontierFixings final : public FixingSampler {
 public:
  bool grow(size_t robot, FixingHost& host, const Termination& stop) override;
};

/// RRT-Connect over exact cells: both robots pushed in turn towards a random target, at most
/// `steps` fixings per chain.
class ConnectChains final : public FixingSampler {
 public:
  explicit ConnectChains(size_t steps) : steps_(steps) {}
  bool grow(size_t robot, FixingHost& host, const Termination& stop) override;

 private:
  size_t steps_;
};

/// The two-robot planner's policy: for a translating robot, once start and goal are known, a
/// share `expandShare` grows from reached cells (of those a share `connectShare` as chains, the
/// rest frontier fixings); everything else, and whatever they fail to grow, a share
/// `cornerShare` in corners, the rest uniform.
class MixedFixings final : public FixingSampler {
 public:
  MixedFixings(double expandShare, double connectShare, size_t connectSteps, double cornerShare,
               size_t cornerCandidates)
      : expandShare_(expandShare),
        connectShare_(connectShare),
        cornerShare_(cornerShare),
        corners_(cornerCandidates),
        chains_(connectSteps) {}
  bool grow(size_t robot, FixingHost& host, const Termination& stop) override;

 private:
  double expandShare_, connectShare_, cornerShare_;
  UniformFixings uniform_;
  CornerFixings corners_;
  FrontierFixings frontier_;
  ConnectChains chains_;
};

}  // namespace mms
