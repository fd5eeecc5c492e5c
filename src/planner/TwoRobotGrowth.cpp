// How the two-robot planner picks its fixings. The paper draws them uniformly from each
// robot's free space among the obstacles; that finds passages wide in the held robot's plane,
// but not placements where the two robots must stay tightly coupled (interlocked parts, a part
// tucked into a corner so the other can pass), which are tiny in area. Fixings drawn from the
// exact free-space cells already reached from the start or the goal always meet the subspace
// they come from, so they grow the graph into such places, as EST and RRT grow trees.
#include <algorithm>
#include <cmath>

#include "manifolds/CellSampling.h"
#include "planner/TwoRobotPlanner.h"

namespace mms {

void TwoRobotPlanner::collectCells(size_t firstNode) {
  cellBoxes_.resize(graph_.nodeCount());
  for (size_t v = firstNode; v < graph_.nodeCount(); ++v) {
    const auto& n = graph_.node(v);
    if (n.kind != ConnectivityGraph::Kind::SliceCell) continue;
    if (n.manifold & Subspace::kLocal) continue;  // fixings are drawn at the shared angles only
    const Subspace& sub = *subspaces_[n.subspace];
    cells_[sub.moving()].push_back(v);
    cellBoxes_[v] = boundingBox(sub.slices()[n.manifold].cell(n.cell).front());
    if (reached(v)) reached_[sub.moving()].push_back(v);
  }
}

// A fixing of `robot` at p in slice `manifold` (of base_ and of every subspace where it moves);
// a translating robot keeps its own angle.
TwoRobotPlanner::Fixing TwoRobotPlanner::fixingAt(size_t robot, const Slice& slice, size_t manifold,
                                                  Vec2 p, long parent) const {
  const double theta = translates_[robot] ? scene_.robots[robot].start.theta : slice.theta();
  return {robot, {p.x, p.y, theta}, long(manifold), -1, parent};
}

bool TwoRobotPlanner::reached(size_t v) const {
  return from_ >= 0 && (graph_.connected(v, size_t(from_)) || graph_.connected(v, size_t(to_)));
}

// Only a translating robot's fixings grow from reached cells: its subspaces are one slice each
// and cheap. A rigid robot's subspace costs n_theta overlays and n_l lines, and on the Pacman
// at 0.9 growing its fixings this way made the planner ten times slower than uniform ones.
bool TwoRobotPlanner::grow(size_t robot, const Termination& stop) {
  if (translates_[robot] && from_ >= 0 && rng_.uniform() < settings_.expandShare) {
    // Cells join the start's or goal's component later too: rescan once the graph has grown
    // by a quarter (amortised constant per node); cells of new subspaces are added as they
    // come.
    if (graph_.nodeCount() > reachedScan_ + reachedScan_ / 4) {
      reachedScan_ = graph_.nodeCount();
      for (size_t r = 0; r < 2; ++r) {
        reached_[r].clear();
        for (const size_t v : cells_[r])
          if (reached(v)) reached_[r].push_back(v);
      }
    }
    if (!reached_[robot].empty()) {
      if (rng_.uniform() < settings_.connectShare && connectTowards(robot, stop)) return true;
      Fixing f;
      if (frontierFixing(robot, f)) {
        addSubspace(f, stop);
        return true;
      }
    }
  }
  Fixing f;
  if (!uniformFixing(robot, f)) return false;
  addSubspace(f, stop);
  return true;
}

// A free pose of `robot` among the obstacles at one of its angles, uniform over the slice.
bool TwoRobotPlanner::uniformFixing(size_t robot, Fixing& out) {
  const Box& b = scene_.bounds;
  for (int attempt = 0; attempt < 200; ++attempt) {
    const size_t k = rng_.below(base_[robot].size());
    const Vec2 p{rng_.uniform(b.xmin, b.xmax), rng_.uniform(b.ymin, b.ymax)};
    if (base_[robot][k].locate(p) < 0) continue;
    out = fixingAt(robot, base_[robot][k], k, p, -1);
    return true;
  }
  return false;
}

// A fixing in a reached cell: the smaller of two drawn uniformly, since a small cell is where
// the parts are tightly coupled (the pocket the wide M must be tucked into lies in a cell of
// the corridor, not in the open space around the parts). Half of the points are taken near the
// cell's vertices: a part tucked into a corner is a corner of the exact cell. Measured on the M
// parts, seeds 1-80, subspaces until solved (mean): cells weighted by 1 / (1 + degree) as EST
// weights tree nodes 858 (seeds 1-60; it starves the start and goal subspaces' cells, which
// meet every new subspace), uniform 586, the smaller of two 384, the smallest of four 445 (seeds
// 1-40).
bool TwoRobotPlanner::frontierFixing(size_t robot, Fixing& out) {
  const auto& cells = reached_[robot];
  auto sliceOf = [&](const ConnectivityGraph::Node& n) -> const Slice& {
    return subspaces_[n.subspace]->slice(n.manifold);
  };
  auto area = [&](size_t v) { return sliceOf(graph_.node(v)).area(graph_.node(v).cell); };
  for (int attempt = 0; attempt < 16; ++attempt) {
    size_t v = cells[rng_.below(cells.size())];
    if (const size_t w = cells[rng_.below(cells.size())]; area(w) < area(v)) v = w;
    const auto& n = graph_.node(v);
    const Slice& slice = sliceOf(n);
    const auto p = rng_.uniform() < 0.5 ? samplePointNearVertex(slice, n.cell, rng_)
                                        : samplePointInCell(slice, n.cell, rng_, 16);
    if (!p) continue;
    out = fixingAt(robot, slice, n.manifold, *p, long(n.subspace));
    ++stats_.expandedFixings;
    return true;
  }
  return false;
}

// RRT-Connect over exact cells: from the reached cell nearest (by bounding box) to a random
// target, move the robot as far as its cell allows in the target's direction, hold it there
// and move the other robot the same way in the new subspace, and so on while they make
// headway. Two interlocked parts climb out of a shaft like this, each step by the full play.
// Returns whether it added any fixing.
bool TwoRobotPlanner::connectTowards(size_t robot, const Termination& stop) {
  const size_t root = size_t(rng_.uniform() < 0.5 ? from_ : to_);
  const Box& b = scene_.bounds;
  const Vec2 q{rng_.uniform(b.xmin, b.xmax), rng_.uniform(b.ymin, b.ymax)};
  const Box target{q.x, q.y, q.x, q.y};
  long node = -1;
  double nearest = INFINITY;
  for (const size_t v : reached_[robot]) {
    const double d = cellBoxes_[v].distance(target);
    if (d < nearest && graph_.connected(v, root)) node = long(v), nearest = d;
  }
  if (node < 0) return false;
  auto center = [&](size_t v) {
    const Box& c = cellBoxes_[v];
    return Vec2{(c.xmin + c.xmax) / 2, (c.ymin + c.ymax) / 2};
  };
  const Vec2 direction = q - center(size_t(node));
  const double length = norm(direction);
  if (length == 0) return false;
  const Vec2 unit = (1 / length) * direction;
  const double minStep = 1e-4 * std::max(b.width(), b.height());
  size_t moving = robot, stalled = 0, added = 0;
  for (size_t step = 0; step < settings_.connectSteps && !stop(); ++step) {
    const ConnectivityGraph::Node n = graph_.node(size_t(node));  // a copy: the graph grows
    const Slice& slice = subspaces_[n.subspace]->slices()[n.manifold];
    const Vec2 from = center(size_t(node));
    const auto p = pointTowards(slice, n.cell, from + direction, rng_);
    if (!p) break;
    // Headway: how far this robot's new pose lies along the direction beyond the cell's centre.
    const double headway = dot(*p - from, unit);
    ++stats_.expandedFixings;
    const size_t k = addSubspace(fixingAt(moving, slice, n.manifold, *p, long(n.subspace)), stop);
    ++added;
    stalled = headway < minStep ? stalled + 1 : 0;
    if (stalled >= 2) break;
    // The other robot, held in subspace n.subspace, now moves in subspace k from its pose.
    // (A start or goal fixing of a rigid robot is on a line, not in a slice: the chain ends.)
    node = nodeFor(*subspaces_[k], fixings_[n.subspace], true);
    if (node < 0 || graph_.node(size_t(node)).kind != ConnectivityGraph::Kind::SliceCell) break;
    moving = 1 - moving;
  }
  return added > 0;
}

// The subspaces of the other family a new one (holding `held`) is tested against: all while
// they are few; then the start and goal subspaces, the one `held` was drawn from, those whose
// held poses are nearest (where the robots interact and the pair may be blocked) and a random
// sample of the rest (far apart pairs are almost always free: a few of them connect as well as
// all). Testing all would cost a collision check and point locations per pair, quadratic in
// the fixings.
std::vector<size_t> TwoRobotPlanner::crossCandidates(const Fixing& held) {
  std::vector<size_t> all;
  for (size_t j = 0; j + 1 < subspaces_.size(); ++j)
    if (subspaces_[j]->moving() == held.robot) all.push_back(j);
  const size_t cap = settings_.crossNearest + settings_.crossRandom;
  if (all.size() <= cap) return all;
  std::vector<char> taken(subspaces_.size(), 0);
  std::vector<size_t> out;
  auto take = [&](size_t j) {
    if (!taken[j] && subspaces_[j]->moving() == held.robot) out.push_back(j), taken[j] = 1;
  };
  for (size_t j = 0; j < 4; ++j) take(j);  // start and goal fixings
  if (held.parent >= 0) take(size_t(held.parent));
  auto distance = [&](size_t j) {
    return std::hypot(fixings_[j].pose.x - held.pose.x, fixings_[j].pose.y - held.pose.y);
  };
  const size_t n = std::min(settings_.crossNearest, all.size());
  std::nth_element(all.begin(), all.begin() + long(n), all.end(),
                   [&](size_t a, size_t c) { return distance(a) < distance(c); });
  for (size_t i = 0; i < n; ++i) take(all[i]);
  for (size_t i = 0; i < settings_.crossRandom; ++i) take(all[n + rng_.below(all.size() - n)]);
  return out;
}

}  // namespace mms
