#include "planner/KRobotPlanner.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "manifolds/CellSampling.h"
#include "path/Motion.h"
#include "planner/NoPath.h"
#include "planner/Rounds.h"

namespace mms {

namespace {
bool samePose(const Pose& a, const Pose& b) {
  return a.x == b.x && a.y == b.y && a.theta == b.theta;
}
}  // namespace

KRobotPlanner::KRobotPlanner(const Scene& scene, KRobotSettings settings)
    : scene_(scene),
      settings_(settings),
      checker_(scene_),
      contactScene_(withContactShapes(scene_, checker_)),
      rng_(settings.seed),
      k_(scene.robots.size()),
      sequenceAngles_(k_, 0),
      base_(k_),
      reached_(k_) {
  for (size_t r = 0; r < k_; ++r) {
    translates_.push_back(scene_.robots[r].motion == Motion::Translate);
    worlds_.push_back(std::make_unique<SliceWorld>(contactScene_, r));
    angles_.push_back(
        std::make_unique<AngleSequence>(settings_.nTheta + r, rng_.uniform(0, 2 * M_PI)));
  }
}

KRobotPlanner::~KRobotPlanner() = default;

// New angles of a rigid robot: base slices, then the same slice in every subspace where it
// moves, so a subspace's slice k is always the overlay of base slice k.
void KRobotPlanner::addAngles(size_t robot, const std::vector<double>& thetas,
                              const Termination& stop) {
  const size_t firstNode = roadmap_.nodeCount(), firstAngle = base_[robot].size();
  if (stop()) return;
  buildSlices(*worlds_[robot], thetas, 1, PointLocation::Auto, stats_.baseSliceSeconds,
              [&](Slice&& s) { base_[robot].push_back(std::move(s)); });
  for (auto& sub : subspaces_)
    if (sub->moving() == robot)
      for (size_t k = firstAngle; k < base_[robot].size(); ++k) sub->addSlice(base_[robot][k]);
  collectCells(firstNode);
}

long KRobotPlanner::existing(size_t moving, const Tuple& t) const {
  std::vector<double> key{double(moving)};
  for (size_t r = 0; r < k_; ++r)
    if (r != moving) key.insert(key.end(), {t[r].pose.x, t[r].pose.y, t[r].pose.theta});
  const auto it = byHeld_.find(key);
  return it == byHeld_.end() ? -1 : long(it->second);
}

// The subspace in which `moving` moves and the others stay where t puts them, built if new.
size_t KRobotPlanner::subspaceFor(size_t moving, const Tuple& t, const Termination& stop) {
  if (const long e = existing(moving, t); e >= 0) return size_t(e);
  const size_t firstNode = roadmap_.nodeCount();
  std::vector<std::pair<size_t, Pose>> held;
  std::vector<double> key{double(moving)};
  for (size_t r = 0; r < k_; ++r)
    if (r != moving) {
      held.emplace_back(r, t[r].pose);
      key.insert(key.end(), {t[r].pose.x, t[r].pose.y, t[r].pose.theta});
    }
  subspaces_.push_back(std::make_unique<Subspace>(uint32_t(subspaces_.size()), contactScene_,
                                                  checker_, moving, std::move(held), roadmap_,
                                                  stats_.manifolds));
  tuples_.push_back(t);
  const size_t index = subspaces_.size() - 1;
  byHeld_[key] = index;
  ++stats_.subspaces;
  Subspace& sub = *subspaces_.back();
  for (const Slice& base : base_[moving]) sub.addSlice(base);
  if (!translates_[moving]) {
    const Robot& r = scene_.robots[moving];
    sub.addLine({r.start.x, r.start.y});  // line 0
    sub.addLine({r.goal.x, r.goal.y});    // line 1
    for (size_t i = 0; i < settings_.nLines && !stop(); ++i)
      sub.addLine(subspaceLinePoint(base_[moving], scene_.bounds, rng_));
  }
  collectCells(firstNode);
  return index;
}

long KRobotPlanner::nodeFor(const Subspace& sub, const Anchor& a) const {
  if (a.angle >= 0) return sub.sliceNodeAt(size_t(a.angle), {a.pose.x, a.pose.y});
  return sub.lineNodeAt(size_t(a.line), a.pose.theta);
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

// Whether robot `robot` at p leaves every other robot, at its start angle, no more free-space
// cells than the obstacles alone do: it cuts none of their passages (waits in a niche, not
// across the corridor). One overlay per other robot: far cheaper than a subspace.
bool KRobotPlanner::leavesRoom(size_t robot, const Pose& p) {
  const MovedShape held = heldShape(contactScene_, robot, p);
  const TimeCharge charge(stats_.manifolds.sliceSeconds);
  for (size_t j = 0; j < k_; ++j) {
    if (j == robot) continue;
    ++stats_.screenedPoses;
    if (!cutsNoPassage(base_[j].front(), held)) return false;
  }
  return true;
}

// A tuple grown from a reached cell: a point of the cell (near a vertex, or anywhere in it) is
// where the cell's robot stays in the new tuple, and another robot, chosen at random, moves in
// the new tuple's subspace. Of up to `screenCandidates` such points (each in a cell drawn anew)
// the first that leaves the others room is taken, else the last.
void KRobotPlanner::grow(const Termination& stop) {
  if (!rescanReached()) return;
  // A robot is drawn by its reached cells per angle, as if all had as many angles: with cells
  // drawn alike, one that translates (one slice a subspace, against a rigid one's 18 or more)
  // was seldom drawn, and the niche it had to wait in was found after seconds, not ms.
  std::vector<double> weight(k_);
  double total = 0;
  for (size_t r = 0; r < k_; ++r)
    total += weight[r] = double(reached_[r].size()) / double(base_[r].size());
  ++grown_;
  std::optional<std::pair<size_t, Anchor>> last;  // (subspace, the moved robot's anchor)
  for (size_t c = 0; c < settings_.screenCandidates; ++c) {
    double u = rng_.uniform(0, total);
    size_t robot = 0;
    while (robot + 1 < k_ && (reached_[robot].empty() || u >= weight[robot])) u -= weight[robot++];
    const std::vector<size_t>& cells = reached_[robot];
    if (cells.empty()) continue;
    const size_t v = cells[rng_.below(cells.size())];
    const Roadmap::Entry& e = roadmap_.entryOf(v);
    const size_t group = e.group, angle = e.index, cell = roadmap_.cellOf(v);
    const size_t i = subspaces_[group]->moving();
    const Slice& slice = subspaces_[group]->slices()[angle];
    const auto p = rng_.uniform() < settings_.cornerShare
                       ? samplePointNearVertex(slice, cell, rng_)
                       : samplePointInCell(slice, cell, rng_, 16);
    if (!p) continue;
    const double theta = translates_[i] ? scene_.robots[i].start.theta : base_[i][angle].theta();
    last = {group, Anchor{{p->x, p->y, theta}, long(angle), -1}};
    if (c + 1 < settings_.screenCandidates && leavesRoom(i, last->second.pose)) break;
  }
  if (!last) return;
  const auto& [group, anchor] = *last;
  const size_t i = subspaces_[group]->moving();
  Tuple t = tuples_[group];
  t[i] = anchor;
  ++stats_.tuples;
  const long at = nodeFor(*subspaces_[group], anchor);
  const bool fromStart = at >= 0 && roadmap_.graph().connected(size_t(at), size_t(from_));
  size_t j = rng_.below(k_ - 1);
  if (j >= i) ++j;
  subspaceFor(j, t, stop);
  join(t);
  towardsOtherSide(std::move(t), fromStart, stop);
}

size_t KRobotPlanner::movingAt(size_t v) const {
  return subspaces_[roadmap_.entryOf(v).group]->moving();
}

bool KRobotPlanner::reached(size_t v) const {
  return from_ >= 0 && (roadmap_.graph().connected(v, size_t(from_)) ||
                        roadmap_.graph().connected(v, size_t(to_)));
}

void KRobotPlanner::collectCells(size_t firstNode) {
  for (size_t v = firstNode; v < roadmap_.nodeCount(); ++v) {
    const Roadmap::Entry& e = roadmap_.entryOf(v);
    if (&e.manifold->family() != &SliceManifold::kFamily || (e.index & Subspace::kLocal)) continue;
    cells_.push_back(v);
    if (reached(v)) reached_[movingAt(v)].push_back(v);
  }
}

// Cells join the start's or goal's component later too: rescan once the graph has grown by a
// quarter (amortised constant per node). Returns whether any cell is reached.
bool KRobotPlanner::rescanReached() {
  if (roadmap_.nodeCount() > reachedScan_ + reachedScan_ / 4) {
    reachedScan_ = roadmap_.nodeCount();
    for (auto& cells : reached_) cells.clear();
    for (const size_t v : cells_)
      if (reached(v)) reached_[movingAt(v)].push_back(v);
  }
  for (const auto& cells : reached_)
    if (!cells.empty()) return true;
  return false;
}

KRobotResult KRobotPlanner::finish(KRobotResult r, PlanStatus status) {
  return finishedRun(std::move(r), status, roadmap_, stats_, clock_);
}

KRobotResult KRobotPlanner::solve(const Termination& stop,
                                  const std::function<void(const KRobotStats&)>& progress) {
  clock_ = Stopwatch();
  const StopScope scope(stop);
  try {
    return solveRounds(stop, progress);
  } catch (const Stopped&) {
    return finish(KRobotResult{}, stop.cancelled() ? PlanStatus::Cancelled : PlanStatus::NotFound);
  }
}

KRobotResult KRobotPlanner::solveRounds(const Termination& stop,
                                        const std::function<void(const KRobotStats&)>& progress) {
  KRobotResult result;
  // Base slices: a translating robot's one angle; a rigid robot's start and goal angles first,
  // then its evenly spread set.
  for (size_t r = 0; r < k_ && !stop(); ++r) {
    const Robot& rb = scene_.robots[r];
    if (translates_[r]) {
      const TimeCharge charge(stats_.baseSliceSeconds);
      base_[r].emplace_back(*worlds_[r], exact::rationalAngleNear(rb.start.theta, 30));
      continue;
    }
    sequenceAngles_[r] = settings_.nTheta + r;
    addAngles(r, angles_[r]->startGoalThen(rb, sequenceAngles_[r]), stop);
  }
  if (stop())
    return finish(result, stop.cancelled() ? PlanStatus::Cancelled : PlanStatus::NotFound);
  // A translating robot whose start and goal its one slice puts apart may have no motion at all:
  // the proof (NoPath.h) then ends the search here instead of at the time limit.
  stats_.noPath = noPathOfAny(scene_, checker_, [&](size_t r) {
    return translates_[r] && apartIn(base_[r].front(), scene_.robots[r]);
  });
  if (!stats_.noPath.empty()) return finish(result, PlanStatus::NotFound);
  for (size_t r = 0; r < k_; ++r) {
    const Robot& rb = scene_.robots[r];
    const long angle = translates_[r] ? 0 : -1;
    start_.push_back({rb.start, angle, translates_[r] ? -1L : 0L});
    goal_.push_back({rb.goal, angle, translates_[r] ? -1L : 1L});
  }
  for (const Tuple* t : {&start_, &goal_}) {
    for (size_t r = 0; r < k_; ++r) subspaceFor(r, *t, stop);
    join(*t);
  }
  from_ = nodeFor(*subspaces_[0], start_[0]);
  to_ = nodeFor(*subspaces_[size_t(existing(0, goal_))], goal_[0]);
  if (from_ < 0 || to_ < 0) return finish(result, PlanStatus::NotFound);
  reachedScan_ = 0;  // from_ and to_ are known now: the next call rescans
  // Scenes where the robots can go one after the other are solved here.
  towardsOtherSide(start_, true, stop);
  towardsOtherSide(goal_, false, stop);

  size_t target = settings_.nTuples;
  Stopwatch sinceReport;
  size_t grownAtRoundStart = 0;
  RoundHooks h;
  h.begin = [&] {};
  h.growing = [&] { return grown_ < grownAtRoundStart + target && rescanReached(); };
  h.complete = [&] { return grown_ >= grownAtRoundStart + target; };
  h.grow = [&] {
    grow(stop);
    if (progress && sinceReport.seconds() >= 1.0) {
      progress(finish(result, PlanStatus::NotFound).stats);
      sinceReport = Stopwatch();
    }
  };
  h.motion = [&](const std::vector<size_t>& nodes) {
    return certifiedMotion(scene_, checker_, roadmap_, nodes);
  };
  h.report = [&] {
    if (progress) progress(finish(result, PlanStatus::NotFound).stats);
  };
  h.next = [&] {
    if (settings_.maxRounds && stats_.rounds >= settings_.maxRounds) return false;
    // A second round without a path: before growing, whether any path exists (NoPath.h; with
    // maxRounds, a test setting, of 2 or less it never runs).
    if (stats_.rounds == 2)
      stats_.noPath = noPathOfAny(scene_, checker_, [&](size_t r) { return !translates_[r]; });
    if (!stats_.noPath.empty()) return false;
    grownAtRoundStart = grown_;
    if (!anglesFirst(sequenceAngles_, translates_)) target *= 2;
    for (size_t r = 0; r < k_; ++r)
      if (!translates_[r]) {
        const std::vector<double> thetas = angles_[r]->take(sequenceAngles_[r]);
        sequenceAngles_[r] *= 2;
        addAngles(r, thetas, stop);
      }
    return true;
  };
  RoundsOutcome o = runRounds(h, roadmap_, size_t(from_), size_t(to_), stop, stats_);
  const PlanStatus status =
      recordOutcome(o, roadmap_, stats_, result.waypoints, result.certificate);
  return finish(result, status);
}

}  // namespace mms
