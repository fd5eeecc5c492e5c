#include "planner/FixingSamplers.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "manifolds/CellSampling.h"
#include "manifolds/OneRobot.h"

namespace mms {

// Only a translating robot's fixings grow from reached cells: its subspaces are one slice each
// and cheap. A rigid robot's subspace costs n_theta overlays and n_l lines, and on the Pacman
// at 0.9 growing its fixings this way made the planner ten times slower than uniform ones.
bool MixedFixings::grow(size_t robot, FixingHost& host, const Termination& stop) {
  if (host.translates(robot) && host.startNode() >= 0 && host.rng().uniform() < expandShare_) {
    if (!host.reachedCells(robot).empty()) {
      if (host.rng().uniform() < connectShare_ && chains_.grow(robot, host, stop)) return true;
      if (frontier_.grow(robot, host, stop)) return true;
    }
  }
  if (host.rng().uniform() < cornerShare_ && corners_.grow(robot, host, stop)) return true;
  return uniform_.grow(robot, host, stop);
}

bool CornerFixings::grow(size_t robot, FixingHost& host, const Termination& stop) {
  const std::vector<Slice>& base = host.baseSlices(robot);
  Random& rng = host.rng();
  std::optional<Fixing> last;
  size_t drawn = 0;
  for (int attempt = 0; attempt < 16 * int(candidates_) && drawn < candidates_; ++attempt) {
    const size_t k = rng.below(base.size());
    if (base[k].fscCount() == 0) continue;
    const auto p = samplePointNearVertex(base[k], rng.below(base[k].fscCount()), rng);
    if (!p) continue;
    last = host.fixingAt(robot, k, *p, -1);
    ++drawn;
    if (drawn == candidates_ || host.leavesRoom(*last)) break;
  }
  if (!last) return false;
  host.hold(*last, stop);
  return true;
}

bool UniformFixings::grow(size_t robot, FixingHost& host, const Termination& stop) {
  const Box& b = host.bounds();
  const std::vector<Slice>& base = host.baseSlices(robot);
  Random& rng = host.rng();
  for (int attempt = 0; attempt < 200; ++attempt) {
    const size_t k = rng.below(base.size());
    const Vec2 p = rng.uniformIn(b);
    if (base[k].locate(p) < 0) continue;
    host.hold(host.fixingAt(robot, k, p, -1), stop);
    return true;
  }
  return false;
}

// The smaller of two cells drawn uniformly, since a small cell is where the parts are tightly
// coupled (the pocket the wide M must be tucked into lies in a cell of the corridor, not in the
// open space around the parts). Half of the points are taken near the cell's vertices: a part
// tucked into a corner is a corner of the exact cell. Measured on the M parts, seeds 1-80,
// subspaces until solved (mean): cells weighted by 1 / (1 + degree) as EST weights tree nodes
// 858 (seeds 1-60; it starves the start and goal subspaces' cells, which meet every new
// subspace), uniform 586, the smaller of two 384, the smallest of four 445 (seeds 1-40).
bool FrontierFixings::grow(size_t robot, FixingHost& host, const Termination& stop) {
  const std::vector<size_t>& cells = host.reachedCells(robot);
  const Roadmap& roadmap = host.roadmap();
  Random& rng = host.rng();
  auto area = [&](size_t v) { return host.sliceOf(v).area(roadmap.cellOf(v)); };
  for (int attempt = 0; attempt < 16; ++attempt) {
    size_t v = cells[rng.below(cells.size())];
    if (const size_t w = cells[rng.below(cells.size())]; area(w) < area(v)) v = w;
    const size_t cell = roadmap.cellOf(v);
    const Slice& slice = host.sliceOf(v);
    const auto p = rng.uniform() < 0.5 ? samplePointNearVertex(slice, cell, rng)
                                       : samplePointInCell(slice, cell, rng, 16);
    if (!p) continue;
    const Fixing f = host.fixingIn(robot, v, *p);
    host.countExpanded();
    host.hold(f, stop);
    return true;
  }
  return false;
}

// From the reached cell nearest (by bounding box) to a random target, move the robot as far as
// its cell allows in the target's direction, hold it there and move the other robot the same
// way in the new subspace, and so on while they make headway. Two interlocked parts climb out
// of a shaft like this, each step by the full play. Returns whether it added any fixing.
bool ConnectChains::grow(size_t robot, FixingHost& host, const Termination& stop) {
  Random& rng = host.rng();
  const Roadmap& roadmap = host.roadmap();
  const size_t root = size_t(rng.uniform() < 0.5 ? host.startNode() : host.goalNode());
  const Box& b = host.bounds();
  const Vec2 q = rng.uniformIn(b);
  const Box target{q.x, q.y, q.x, q.y};
  long node = -1;
  double nearest = INFINITY;
  for (const size_t v : host.reachedCells(robot)) {
    const double d = host.cellBox(v).distance(target);
    if (d < nearest && roadmap.graph().connected(v, root)) node = long(v), nearest = d;
  }
  if (node < 0) return false;
  auto center = [&](size_t v) {
    const Box& c = host.cellBox(v);
    return Vec2{(c.xmin + c.xmax) / 2, (c.ymin + c.ymax) / 2};
  };
  const Vec2 direction = q - center(size_t(node));
  const double length = norm(direction);
  if (length == 0) return false;
  const Vec2 unit = (1 / length) * direction;
  const double minStep = 1e-4 * std::max(b.width(), b.height());
  size_t moving = robot, stalled = 0, added = 0;
  for (size_t step = 0; step < steps_ && !stop(); ++step) {
    const size_t v = size_t(node);
    const uint32_t group = roadmap.entryOf(v).group;  // a copy: the roadmap grows
    const Vec2 from = center(v);
    const auto p = pointTowards(host.sliceOf(v), roadmap.cellOf(v), from + direction, rng);
    if (!p) break;
    // Headway: how far this robot's new pose lies along the direction beyond the cell's centre.
    const double headway = dot(*p - from, unit);
    host.countExpanded();
    const size_t k = host.hold(host.fixingIn(moving, v, *p), stop);
    ++added;
    stalled = headway < minStep ? stalled + 1 : 0;
    if (stalled >= 2) break;
    // The other robot, held in subspace `group`, now moves in subspace k from its pose.
    // (A start or goal fixing of a rigid robot is on a line, not in a slice: the chain ends.)
    node = host.nodeWhereHeld(k, group);
    if (node < 0 || &roadmap.entryOf(size_t(node)).manifold->family() != &SliceManifold::kFamily)
      break;
    moving = 1 - moving;
  }
  return added > 0;
}

}  // namespace mms
