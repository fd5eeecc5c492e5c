#pragma once
// One robot moves while the obstacles and any robots held at fixed poses stay: a 3-D C-space
// approximated by slices (fixed angle) and lines (fixed position) whose free-space cells are
// nodes of a shared roadmap. The one-robot planner uses one subspace; the two-robot
// planner (recursive MMS, Section II of the paper) one per fixing of either robot.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "graph/Roadmap.h"
#include "manifolds/Line.h"
#include "manifolds/OneRobot.h"
#include "manifolds/Slice.h"
#include "mms/Termination.h"
#include "util/Random.h"

namespace mms {

/// Where a robot is held: a pose at an angle of its set (a slice of every subspace where it
/// moves), or its start or goal pose (lines 0 and 1 of those subspaces).
struct Placement {
  Pose pose;
  long angleIndex = -1;  // into the robot's angle set, or -1
  long line = -1;        // 0 / 1: start / goal position, or -1
};

struct SubspaceStats {
  size_t slices = 0, lines = 0, sliceCells = 0, lineArcs = 0;
  size_t localSlices = 0;  // of the slices: those at angles of one subspace alone
  double sliceSeconds = 0, lineSeconds = 0, connectSeconds = 0;
  LineStats lineStats;
};

/// `scene` with every robot's shape shrunk by half the contact tolerance. Manifolds are built
/// for these shapes, so a placement in contact (an assembled part resting on its neighbour)
/// lies inside a free-space cell instead of on its boundary, while every placement in a cell
/// keeps half the tolerance of clearance as the checker sees it (it shrinks by the whole), so
/// motions inside cells stay certifiable.
Scene withContactShapes(const Scene& scene, const CollisionChecker& checker);

/// Slices of `world` at `thetas`, built `threads` at a time and passed to `add` in the order of
/// `thetas`, so what is built does not depend on the thread count. A build that throws (Stopped
/// at the time limit) ends it: the slices before it have been added. Adds the seconds spent
/// building to `seconds`, also when it ends so.
void buildSlices(const SliceWorld& world, const std::vector<double>& thetas, unsigned threads,
                 PointLocation strategy, double& seconds, const std::function<void(Slice&&)>& add);

/// A slice-family manifold added to the roadmap as `index` in `group` and woven into side 1 of
/// `weave` (its lines on side 0: a line's arc is found by one binary search, a slice's cell by
/// point location, so the line first). What a subspace of one robot and one of a compound both
/// do to add a slice. Returns its roadmap id.
inline uint32_t addJoinedSlice(Roadmap& roadmap, SubspaceStats& stats,
                               std::unique_ptr<Manifold> slice, uint32_t group, uint32_t index,
                               uint32_t weave) {
  const size_t cells = slice->cellCount();
  const uint32_t id = roadmap.add(std::move(slice), group, index);
  ++stats.slices;
  stats.sliceCells += cells;
  const TimeCharge connect(stats.connectSeconds);
  roadmap.weave(weave, 1, id);
  return id;
}

/// A line at p (free arcs decided by `free`) appended to `lines`, added to the roadmap as
/// `make(index)` in `group`, and woven into side 0 of `weave` (the slices on side 1). What a
/// subspace of one robot and one of a compound both do to add a line. Returns its roadmap id.
template <class Make>
uint32_t addJoinedLine(Roadmap& roadmap, SubspaceStats& stats, std::vector<Line>& lines,
                       const LineWorld& world, const PoseTest& free, Vec2 p, uint32_t group,
                       const Make& make, uint32_t weave) {
  {
    const TimeCharge charge(stats.lineSeconds);
    lines.emplace_back(world, free, p, &stats.lineStats);
  }
  const size_t l = lines.size() - 1;
  const uint32_t id = roadmap.add(make(l), group, uint32_t(l));
  ++stats.lines;
  stats.lineArcs += lines[l].arcs().size();
  const TimeCharge connect(stats.connectSeconds);
  roadmap.weave(weave, 0, id);
  return id;
}

/// Robot `robot` of `scene` held at `pose`, as an overlay subtracts it.
MovedShape heldShape(const Scene& scene, size_t robot, const Pose& pose);

/// Whether `held` leaves the moving robot of `base` (its slice among the obstacles alone) no
/// more free-space cells than the obstacles do: it cuts none of its passages (a robot waiting in
/// a niche, not across the corridor). One overlay: far cheaper than a subspace.
bool cutsNoPassage(const Slice& base, const MovedShape& held);

/// Where a subspace of a robot with base slices `base` puts a random line: half of the points
/// where the robot fits at some angle of its set (a free point of a random base slice, 20 tries),
/// the rest uniform in `bounds`.
Vec2 subspaceLinePoint(const std::vector<Slice>& base, const Box& bounds, Random& rng);

/// Middles of free arcs of `lines` (a subspace's, with a robot held) that are narrower than
/// `spacing` and contain none of the angles `met` nor an earlier middle: rotation passages the
/// shared angles miss. Only arcs the held robot makes narrow count: where the same line among
/// the obstacles alone (`alone`, free per `amongObstacles`) has an arc narrower than `spacing`
/// and less than twice as wide, the arc is the obstacles' own, the same in every subspace, and
/// the shared angles, which double every round, reach it at most a round later; a local slice
/// in each subspace would pay for it again and again (in a corridor, most short arcs are the
/// walls'). An arc the held robot makes more than twice as narrow still counts. At most `limit`
/// middles, in line and arc order.
std::vector<double> narrowArcMiddles(std::span<const Line> lines, const LineWorld& alone,
                                     const PoseTest& amongObstacles, std::vector<double> met,
                                     double spacing, size_t limit);

class Subspace {
 public:
  /// Robot `moving` of `scene` moves; each (robot, pose) in `held` stays put as an obstacle.
  Subspace(const Subspace&) = delete;  // its manifolds point at its frame and vectors
  Subspace& operator=(const Subspace&) = delete;
  Subspace(uint32_t id, const Scene& scene, const CollisionChecker& checker, size_t moving,
           std::vector<std::pair<size_t, Pose>> held, Roadmap& roadmap, SubspaceStats& stats);

  uint32_t id() const { return frame_.id; }
  size_t moving() const { return frame_.moving; }
  const std::vector<std::pair<size_t, Pose>>& held() const { return frame_.held; }
  const std::vector<Slice>& slices() const { return slices_; }
  /// Slices at angles of this subspace alone (not shared with the others).
  const std::vector<Slice>& localSlices() const { return localSlices_; }
  /// A slice's roadmap entry `index`: its place among slices(), or among localSlices() with
  /// the top bit set, so that one number names either kind.
  static uint32_t localIndex(size_t k) { return kLocalBit | uint32_t(k); }
  static bool isLocal(uint32_t index) { return (index & kLocalBit) != 0; }
  static uint32_t positionOf(uint32_t index) { return index & ~kLocalBit; }
  /// The slice a roadmap entry's `index` names.
  const Slice& slice(uint32_t index) const {
    return isLocal(index) ? localSlices_[positionOf(index)] : slices_[index];
  }
  const std::vector<Line>& lines() const { return lines_; }

  /// The slice `base` (the obstacles alone) with the held robots subtracted. Builds only, so
  /// several threads may build overlays of one subspace at once.
  Slice overlay(const Slice& base) const;
  /// Adds a slice built by overlay(), connecting it to the lines already here. Returns its
  /// index.
  size_t addOverlay(Slice slice);
  size_t addSlice(const Slice& base);  // overlay(base), timed, then added
  /// Adds a slice built by overlay() as a local slice, connecting it to the lines here.
  void addLocalOverlay(Slice slice);
  /// Adds a line at p, connecting it to the slices already here. Returns its index.
  size_t addLine(Vec2 p);
  /// The roadmap id of line l.
  uint32_t lineId(size_t l) const { return lineIds_[l]; }
  /// Adds a manifold of another family that meets this subspace's slices as its lines do (a
  /// pivot line), woven with them; `index` is the planner's number for it. Returns its id.
  uint32_t addWovenLine(std::unique_ptr<Manifold> line, uint32_t index);

  /// Graph node of the cell of slice k containing p, or -1 (also when slice k was never built).
  /// `knownFree`: the collision checker found p free here, so a slice of one cell needs no
  /// point location.
  long sliceNodeAt(size_t k, Vec2 p, bool knownFree = false) const;
  /// Graph node of the arc of line l containing theta, or -1.
  long lineNodeAt(size_t l, double theta) const;

  /// Whether the moving robot is free at q here (obstacles, bounds, held robots).
  bool free(const Pose& q) const;

 private:
  uint32_t addSliceManifold(const std::vector<Slice>& store, uint32_t index);
  static constexpr uint32_t kLocalBit = 1u << 31;

  HeldFrame frame_;
  const CollisionChecker& checker_;
  std::shared_ptr<const std::vector<MovedShape>> heldShapes_;  // shared by its overlays
  std::vector<Ring> heldRings_;                                // the same in doubles, for lines
  LineWorld lineWorld_;
  Roadmap& roadmap_;
  SubspaceStats& stats_;
  std::vector<Slice> slices_;
  std::vector<Line> lines_;
  std::vector<Slice> localSlices_;
  std::vector<uint32_t> sliceIds_, lineIds_;  // roadmap ids of the manifolds
  uint32_t weave_;                            // its lines and (local) slices, all joined
};

}  // namespace mms
