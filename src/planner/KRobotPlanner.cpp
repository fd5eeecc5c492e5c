#include "planner/KRobotPlanner.h"

#include <algorithm>
#include <cmath>

#include "manifolds/CellSampling.h"

namespace mms {

namespace {
bool samePose(const Pose& a, const Pose& b) {
  return a.x == b.x && a.y == b.y && a.theta == b.theta;
}
}  // namespace

KRobotPlanner::KRobotPlanner(const Scene& scene, KRobotSettings settings)
    : HeldRobotPlanner(scene, settings, stats_), hold_(settings), target_(settings.nTuples) {
  overlaysBySubspace_ = true;
}

KRobotPlanner::~KRobotPlanner() = default;

KRobotResult KRobotPlanner::solve(const Termination& stop,
                                  const std::function<void(const KRobotStats&)>& progress) {
  return solveReporting(stop, progress, stats_);
}

// Where t holds every robot but `moving`.
std::vector<std::pair<size_t, Pose>> KRobotPlanner::heldBy(size_t moving, const Tuple& t) const {
  std::vector<std::pair<size_t, Pose>> held;
  for (size_t r = 0; r < k_; ++r)
    if (r != moving) held.emplace_back(r, t[r].pose);
  return held;
}

long KRobotPlanner::existing(size_t moving, const Tuple& t) const {
  return findSubspace(moving, heldBy(moving, t));
}

// The subspace in which `moving` moves and the others stay where t puts them, built if new.
size_t KRobotPlanner::subspaceFor(size_t moving, const Tuple& t, const Termination& stop) {
  const std::vector<std::pair<size_t, Pose>> held = heldBy(moving, t);
  if (const long e = findSubspace(moving, held); e >= 0) return size_t(e);
  tuples_.push_back(t);
  return addSubspace(moving, held, stop);
}

// The subspaces of t's robots meet at t: each robot's cell there is joined to the first's.
void KRobotPlanner::join(const Tuple& t) {
  Stopwatch watch;
  long first = -1;
  for (size_t r = 0; r < k_; ++r) {
    const long e = existing(r, t);
    if (e < 0) continue;
    const long node = nodeFor(*subspaces_[size_t(e)], t[r]);
    if (node < 0) continue;
    if (first < 0) {
      first = node;
    } else {
      roadmap_.addEdge(size_t(first), size_t(node));
      ++stats_.crossEdges;
    }
  }
  stats_.crossSeconds += watch.seconds();
}

// The start and goal tuples, each joining the subspaces of all its robots.
bool KRobotPlanner::placeEnds(const Termination& stop) {
  for (size_t r = 0; r < k_; ++r) {
    start_.push_back(endPlacement(r, true));
    goal_.push_back(endPlacement(r, false));
  }
  for (const Tuple* t : {&start_, &goal_}) {
    for (size_t r = 0; r < k_; ++r) subspaceFor(r, *t, stop);
    join(*t);
  }
  from_ = nodeFor(*subspaces_[0], start_[0]);
  to_ = nodeFor(*subspaces_[size_t(existing(0, goal_))], goal_[0]);
  return from_ >= 0 && to_ >= 0;
}

// Scenes where the robots can go one after the other are solved here.
void KRobotPlanner::endsPlaced(const Termination& stop) {
  towardsOtherSide(start_, true, stop);
  towardsOtherSide(goal_, false, stop);
}

// From tuple t, each robot not yet at its pose on the other side (its goal, for a tuple reached
// from the start) is tried in turn, in random order: if its subspace of t (built if new)
// connects its pose to that one, it goes there, and the robots left are tried again from the
// new tuple; until all are there (the other side's own tuple: its subspaces exist) or none can.
void KRobotPlanner::towardsOtherSide(Tuple t, bool fromStart, const Termination& stop) {
  const Tuple& target = fromStart ? goal_ : start_;
  while (!stop()) {
    std::vector<size_t> left;
    for (size_t r = 0; r < k_; ++r)
      if (!samePose(t[r].pose, target[r].pose)) left.push_back(r);
    if (left.empty()) return;
    for (size_t n = left.size(); n > 1; --n) std::swap(left[n - 1], left[rng_.below(n)]);
    bool moved = false;
    for (const size_t r : left) {
      const Subspace& sub = *subspaces_[subspaceFor(r, t, stop)];
      join(t);
      const long here = nodeFor(sub, t[r]), there = nodeFor(sub, target[r]);
      if (here < 0 || there < 0 || !roadmap_.graph().connected(size_t(here), size_t(there)))
        continue;
      t[r] = target[r];
      ++stats_.greedyMoves;
      moved = true;
      join(t);
      break;
    }
    if (!moved) return;
  }
}

// A point of a reached cell (near a vertex, or anywhere in it) where the cell's robot stays in
// the new tuple: of up to `screenCandidates` (each in a cell drawn anew) the first that leaves
// the others room, else the last. Returns (the cell's subspace, the robot's placement).
std::optional<std::pair<size_t, Placement>> KRobotPlanner::growthPoint() {
  const std::vector<std::vector<size_t>>& reached = reachedCells();
  // A robot is drawn by its reached cells per angle, as if all had as many angles: with cells
  // drawn alike, one that translates (one slice a subspace, against a rigid one's 18 or more)
  // was seldom drawn, and the niche it had to wait in was found after seconds, not ms.
  std::vector<double> weight(k_);
  double total = 0;
  for (size_t r = 0; r < k_; ++r)
    total += weight[r] = double(reached[r].size()) / double(base_[r].size());
  std::optional<std::pair<size_t, Placement>> last;
  for (size_t c = 0; c < hold_.screenCandidates; ++c) {
    double u = rng_.uniform(0, total);
    size_t robot = 0;
    while (robot + 1 < k_ && (reached[robot].empty() || u >= weight[robot])) u -= weight[robot++];
    const std::vector<size_t>& cells = reached[robot];
    if (cells.empty()) continue;
    const size_t v = cells[rng_.below(cells.size())];
    const Roadmap::Entry& e = roadmap_.entryOf(v);
    const size_t group = e.group, angle = e.index, cell = roadmap_.cellOf(v);
    const size_t i = subspaces_[group]->moving();
    const Slice& slice = subspaces_[group]->slices()[angle];
    const auto p = rng_.uniform() < hold_.cornerShare ? samplePointNearVertex(slice, cell, rng_)
                                                      : samplePointInCell(slice, cell, rng_, 16);
    if (!p) continue;
    last = {group, placementAt(i, angle, *p)};
    if (c + 1 < hold_.screenCandidates && leavesRoomFor(i, last->second.pose)) break;
  }
  return last;
}

// A tuple grown from a reached cell: the cell's robot stays at a growth point, and another
// robot, chosen at random, moves in the new tuple's subspace.
void KRobotPlanner::growStep(const Termination& stop) {
  if (anyReached()) {
    ++grown_;
    if (const auto point = growthPoint()) {
      const auto& [group, placement] = *point;
      const size_t i = subspaces_[group]->moving();
      Tuple t = tuples_[group];
      t[i] = placement;
      ++stats_.tuples;
      const long at = nodeFor(*subspaces_[group], placement);
      const bool fromStart = at >= 0 && roadmap_.graph().connected(size_t(at), size_t(from_));
      size_t j = rng_.below(k_ - 1);
      if (j >= i) ++j;
      subspaceFor(j, t, stop);
      join(t);
      towardsOtherSide(std::move(t), fromStart, stop);
    }
  }
  sliceNarrowArcsIfDisconnected();
}

bool KRobotPlanner::anyReached() {
  for (const auto& cells : reachedCells())
    if (!cells.empty()) return true;
  return false;
}

bool KRobotPlanner::growing() { return grown_ < grownAtRoundStart_ + target_ && anyReached(); }

void KRobotPlanner::nextTargets(bool fixingsGrow) {
  grownAtRoundStart_ = grown_;
  if (fixingsGrow) target_ *= 2;
}

}  // namespace mms
