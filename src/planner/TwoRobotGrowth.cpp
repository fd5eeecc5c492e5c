// The two-robot planner's side of growth: the cells its fixing samplers draw from
// (FixingSamplers.h, the host's answers) and which subspaces a new one is joined to.
#include <algorithm>
#include <cmath>

#include "planner/TwoRobotPlanner.h"

namespace mms {

void TwoRobotPlanner::cellAdded(size_t node, const Subspace& sub, uint32_t slice) {
  if (cellBoxes_.size() <= node) cellBoxes_.resize(roadmap_.nodeCount());
  cellBoxes_[node] = boundingBox(sub.slices()[slice].cell(roadmap_.cellOf(node)).front());
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
  const size_t cap = hold_.crossNearest + hold_.crossRandom;
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
  const size_t n = std::min(hold_.crossNearest, all.size());
  std::nth_element(all.begin(), all.begin() + long(n), all.end(),
                   [&](size_t a, size_t c) { return distance(a) < distance(c); });
  for (size_t i = 0; i < n; ++i) take(all[i]);
  for (size_t i = 0; i < hold_.crossRandom; ++i) take(all[n + rng_.below(all.size() - n)]);
  return out;
}

}  // namespace mms
