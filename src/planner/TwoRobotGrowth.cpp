// The two-robot planner's side of growth: the cells its fixing samplers draw from
// (FixingSamplers.h, the host's answers) and which subspaces a new one is joined to.
#include <algorithm>
#include <cmath>

#include "planner/TwoRobotPlanner.h"

namespace mms {

void TwoRobotPlanner::collectCells(size_t firstNode) {
  cellBoxes_.resize(roadmap_.nodeCount());
  for (size_t v = firstNode; v < roadmap_.nodeCount(); ++v) {
    const Roadmap::Entry& e = roadmap_.entryOf(v);
    if (&e.manifold->family() != &SliceManifold::kFamily) continue;
    if (e.index & Subspace::kLocal) continue;  // fixings are drawn at the shared angles only
    const Subspace& sub = *subspaces_[e.group];
    cells_[sub.moving()].push_back(v);
    cellBoxes_[v] = boundingBox(sub.slices()[e.index].cell(roadmap_.cellOf(v)).front());
    if (reached(v)) reached_[sub.moving()].push_back(v);
  }
}

// A translating robot keeps its own angle.
Fixing TwoRobotPlanner::fixingAt(size_t robot, size_t angle, Vec2 p, long parent) const {
  const double theta =
      translates_[robot] ? scene_.robots[robot].start.theta : base_[robot][angle].theta();
  return {robot, {p.x, p.y, theta}, long(angle), -1, parent};
}

bool TwoRobotPlanner::reached(size_t v) const {
  return from_ >= 0 && (roadmap_.graph().connected(v, size_t(from_)) ||
                        roadmap_.graph().connected(v, size_t(to_)));
}

// Cells join the start's or goal's component later too: rescan once the graph has grown by a
// quarter (amortised constant per node); cells of new subspaces are added as they come.
const std::vector<size_t>& TwoRobotPlanner::reachedCells(size_t robot) {
  if (roadmap_.nodeCount() > reachedScan_ + reachedScan_ / 4) {
    reachedScan_ = roadmap_.nodeCount();
    for (size_t r = 0; r < 2; ++r) {
      reached_[r].clear();
      for (const size_t v : cells_[r])
        if (reached(v)) reached_[r].push_back(v);
    }
  }
  return reached_[robot];
}

const Slice& TwoRobotPlanner::sliceOf(size_t node) const {
  const Roadmap::Entry& e = roadmap_.entryOf(node);
  return subspaces_[e.group]->slice(e.index);
}

long TwoRobotPlanner::nodeWhereHeld(size_t k, size_t held) const {
  return nodeFor(*subspaces_[k], fixings_[held], true);
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
  for (size_t j = 0; j < kRootSubspaces; ++j) take(j);  // start and goal fixings
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
