#include "planner/HeldRobotPlanner.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "path/Motion.h"
#include "planner/NoPath.h"
#include "planner/Rounds.h"
#include "util/Deferred.h"
#include "util/Parallel.h"

namespace mms {

namespace {
std::vector<double> heldKey(size_t moving, const std::vector<std::pair<size_t, Pose>>& held) {
  std::vector<double> key{double(moving)};
  for (const auto& [robot, p] : held) key.insert(key.end(), {double(robot), p.x, p.y, p.theta});
  return key;
}
}  // namespace

// Robot r gets nTheta + r angles: with coprime set sizes n and n + 1, two robots' relative
// angles (what decides whether one fits into the other, the square into the Pacman's mouth)
// are spaced 2 pi / (n (n + 1)) instead of 2 pi / n, at no extra cost.
HeldRobotPlanner::HeldRobotPlanner(const Scene& scene, const HeldRobotSettings& settings,
                                   HeldRobotStats& stats)
    : scene_(scene),
      settings_(settings),
      checker_(scene_),
      contactScene_(withContactShapes(scene_, checker_)),
      rng_(settings.seed),
      k_(scene.robots.size()),
      base_(k_),
      common_(stats),
      sequenceAngles_(k_, 0),
      cells_(k_),
      reached_(k_) {
  for (size_t r = 0; r < k_; ++r) {
    translates_.push_back(scene_.robots[r].motion == Motion::Translate);
    worlds_.push_back(std::make_unique<SliceWorld>(contactScene_, r));
    lineWorlds_.push_back(std::make_unique<LineWorld>(contactScene_, r));
    angles_.push_back(
        std::make_unique<AngleSequence>(settings_.nTheta + r, rng_.uniform(0, 2 * M_PI)));
  }
}

HeldRobotPlanner::~HeldRobotPlanner() = default;

// A translating robot's one angle, a rigid robot's start and goal angles then its first
// nTheta + r; built while solving so that their cost, up to seconds among many obstacles,
// counts against the time limit.
void HeldRobotPlanner::buildBaseSlices(const Termination& stop) {
  for (size_t r = 0; r < k_ && !stop(); ++r) {
    if (!base_[r].empty()) continue;
    if (translates_[r]) {
      const TimeCharge charge(common_.baseSliceSeconds);
      base_[r].emplace_back(*worlds_[r],
                            exact::rationalAngleNear(scene_.robots[r].start.theta, 30));
    } else {
      sequenceAngles_[r] = settings_.nTheta + r;
      addAngles(r, angles_[r]->startGoalThen(scene_.robots[r], sequenceAngles_[r]), stop);
    }
  }
}

// Base slices built settings_.threads at a time and appended in angle order, then the same
// slice in every subspace where the robot moves: a subspace's slice k is always the overlay of
// base slice k.
void HeldRobotPlanner::addAngles(size_t robot, const std::vector<double>& thetas,
                                 const Termination& stop) {
  const size_t firstNode = roadmap_.nodeCount(), firstAngle = base_[robot].size();
  if (stop()) return;
  buildSlices(*worlds_[robot], thetas, settings_.threads, PointLocation::Auto,
              common_.baseSliceSeconds, [&](Slice&& s) { base_[robot].push_back(std::move(s)); });
  std::vector<Subspace*> moving;
  for (auto& sub : subspaces_)
    if (sub->moving() == robot) moving.push_back(sub.get());
  if (!moving.empty())
    addOverlays((base_[robot].size() - firstAngle) * moving.size(),
                [&](size_t i) -> std::pair<Subspace*, const Slice*> {
                  const size_t n = base_[robot].size() - firstAngle, m = moving.size();
                  if (overlaysBySubspace_)
                    return {moving[i / n], &base_[robot][firstAngle + i % n]};
                  return {moving[i % m], &base_[robot][firstAngle + i / m]};
                });
  anglesAdded(robot, firstAngle, stop);
  collectCells(firstNode);
}

// Built settings_.threads at a time and added in index order, so the roadmap does not depend
// on the thread count. A build the time limit cut short ends it (Stopped): the ones before
// it stay.
void HeldRobotPlanner::addOverlays(
    size_t count, const std::function<std::pair<Subspace*, const Slice*>(size_t)>& item) {
  const size_t batch = std::max<size_t>(1, 4 * size_t(settings_.threads));
  for (size_t done = 0; done < count;) {
    checkpoint();
    const size_t n = std::min(batch, count - done);
    std::vector<std::optional<Slice>> built(n);
    std::vector<std::exception_ptr> errors;
    {
      const TimeCharge charge(common_.manifolds.sliceSeconds);
      errors = parallelFor(n, settings_.threads, [&](size_t i) {
        const auto [sub, base] = item(done + i);
        built[i].emplace(sub->overlay(*base));
      });
    }
    for (size_t i = 0; i < n; ++i) {
      if (errors[i]) rethrowDeferring(errors[i], built);
      item(done + i).first->addOverlay(std::move(*built[i]));
    }
    done += n;
  }
}

size_t HeldRobotPlanner::addSubspace(size_t moving,
                                     const std::vector<std::pair<size_t, Pose>>& held,
                                     const Termination& stop,
                                     const std::function<void(Subspace&)>& join) {
  const size_t firstNode = roadmap_.nodeCount();
  subspaces_.push_back(std::make_unique<Subspace>(uint32_t(subspaces_.size()), contactScene_,
                                                  checker_, moving, held, roadmap_,
                                                  common_.manifolds));
  byHeld_[heldKey(moving, held)] = subspaces_.size() - 1;
  ++common_.subspaces;
  Subspace& sub = *subspaces_.back();
  addOverlays(base_[moving].size(), [&](size_t i) -> std::pair<Subspace*, const Slice*> {
    return {&sub, &base_[moving][i]};
  });
  if (!translates_[moving]) {
    const Robot& r = scene_.robots[moving];
    sub.addLine({r.start.x, r.start.y});  // line 0
    sub.addLine({r.goal.x, r.goal.y});    // line 1
    addRandomLines(sub, settings_.nLines, stop);
  }
  if (join) {
    Stopwatch watch;
    join(sub);
    common_.crossSeconds += watch.seconds();
  }
  collectCells(firstNode);
  return subspaces_.size() - 1;
}

long HeldRobotPlanner::findSubspace(size_t moving,
                                    const std::vector<std::pair<size_t, Pose>>& held) const {
  const auto it = byHeld_.find(heldKey(moving, held));
  return it == byHeld_.end() ? -1 : long(it->second);
}

long HeldRobotPlanner::nodeFor(const Subspace& sub, const Placement& p, bool knownFree) const {
  if (p.angleIndex >= 0)
    return sub.sliceNodeAt(size_t(p.angleIndex), {p.pose.x, p.pose.y}, knownFree);
  return sub.lineNodeAt(size_t(p.line), p.pose.theta);
}

Placement HeldRobotPlanner::placementAt(size_t robot, size_t angleIndex, Vec2 p) const {
  const double theta =
      translates_[robot] ? scene_.robots[robot].start.theta : base_[robot][angleIndex].theta();
  return {{p.x, p.y, theta}, long(angleIndex), -1};
}

// A translating robot's start and goal lie in its one slice; a rigid robot's on lines 0
// (start) and 1 (goal) of every subspace where it moves.
Placement HeldRobotPlanner::endPlacement(size_t robot, bool start) const {
  const Robot& rb = scene_.robots[robot];
  if (translates_[robot]) return {start ? rb.start : rb.goal, 0, -1};
  return {start ? rb.start : rb.goal, -1, start ? 0 : 1};
}

bool HeldRobotPlanner::leavesRoomFor(size_t robot, const Pose& pose) {
  const MovedShape held = heldShape(contactScene_, robot, pose);
  const TimeCharge charge(common_.manifolds.sliceSeconds);
  for (size_t j = 0; j < k_; ++j) {
    if (j == robot) continue;
    ++common_.screenedPoses;
    if (!cutsNoPassage(base_[j].front(), held)) return false;
  }
  return true;
}

Vec2 HeldRobotPlanner::linePoint(size_t robot) {
  return subspaceLinePoint(base_[robot], scene_.bounds, rng_);
}

// Random lines in a subspace of a rigid robot; their narrow arcs wait in narrowPending_ for
// sliceNarrowArcsIfDisconnected.
void HeldRobotPlanner::addRandomLines(Subspace& sub, size_t count, const Termination& stop) {
  for (size_t i = 0; i < count && !stop(); ++i) sub.addLine(linePoint(sub.moving()));
  narrowPending_.push_back(sub.id());
}

// The subspaces holding a robot at its start or goal double their random lines each round, as
// the slices double their angles. Every path begins and ends in them, and no later hold can
// stand in for them as new ones stand in for any other subspace, so a rotation passage their
// first lines missed (the Pacman turned round the square held at the square's goal) would
// otherwise wait for the shared angles to become dense enough.
void HeldRobotPlanner::growRootLines(size_t count, const Termination& stop) {
  for (size_t k = 0; k < rootSubspaces_ && !stop(); ++k)
    if (!translates_[subspaces_[k]->moving()]) addRandomLines(*subspaces_[k], count, stop);
}

// Narrow arcs the held robots make (narrowArcMiddles): a slice at each middle, local to this
// subspace, opens the rotation passage the shared angles miss (the Pacman turned round so the
// square passes through its mouth); at most settings_.narrowSlices each time the subspace's
// new lines are scanned (once for most subspaces, every round for the root ones). Open scenes
// have no such arcs and pay nothing.
void HeldRobotPlanner::sliceNarrowArcs(Subspace& sub) {
  const size_t moving = sub.moving();
  std::vector<double> met;
  for (const Slice& s : base_[moving]) met.push_back(s.theta());
  for (const Slice& s : sub.localSlices()) met.push_back(s.theta());
  std::vector<exact::RationalAngle> middles;
  {
    // Most of this is the lines among the obstacles alone that narrowArcMiddles builds.
    const TimeCharge charge(common_.manifolds.lineSeconds);
    // Only the lines not scanned before: the root subspaces gain lines every round.
    narrowScanned_.resize(subspaces_.size());
    const std::span<const Line> lines(sub.lines());
    for (const double m : narrowArcMiddles(
             lines.subspan(std::exchange(narrowScanned_[sub.id()], lines.size())),
             *lineWorlds_[moving], [&](const Pose& q) { return checker_.robotFree(moving, q); },
             met, 2 * M_PI / double(base_[moving].size()), settings_.narrowSlices))
      middles.push_back(exact::rationalAngleNear(m, 30));
  }
  // Built on all threads (each a new base slice and its overlay), added in arc order.
  std::vector<std::optional<Slice>> built(middles.size());
  std::vector<std::exception_ptr> errors;
  {
    const TimeCharge charge(common_.manifolds.sliceSeconds);
    errors = parallelFor(middles.size(), settings_.threads, [&](size_t i) {
      auto base = std::make_shared<const Slice>(*worlds_[moving], middles[i]);
      try {
        built[i].emplace(sub.overlay(*base));
      } catch (const Stopped&) {
        freeLater(std::move(base));  // a whole base slice: not freed past the limit
        throw;
      }
    });
  }
  for (size_t i = 0; i < middles.size(); ++i) {
    if (errors[i]) rethrowDeferring(errors[i], built);
    sub.addLocalOverlay(std::move(*built[i]));
  }
}

// Narrow-arc slices wait until start and goal do not connect without them (each needs a base
// slice of its own, the Minkowski sums of every obstacle): on the random polygons the first
// search then runs before 10-17 of them are built. They only join cells and arcs inside their
// subspace (holds are drawn at shared angles), so building them later loses no meeting point.
void HeldRobotPlanner::sliceNarrowArcsIfDisconnected() {
  if (from_ >= 0 && roadmap_.graph().connected(size_t(from_), size_t(to_))) return;
  sliceNarrowArcsNow();
}

void HeldRobotPlanner::sliceNarrowArcsNow() {
  // Taken first: a subspace the time limit cuts short is not retried.
  for (const size_t k : std::exchange(narrowPending_, {})) sliceNarrowArcs(*subspaces_[k]);
}

bool HeldRobotPlanner::reached(size_t v) const {
  return from_ >= 0 && (roadmap_.graph().connected(v, size_t(from_)) ||
                        roadmap_.graph().connected(v, size_t(to_)));
}

void HeldRobotPlanner::collectCells(size_t firstNode) {
  for (size_t v = firstNode; v < roadmap_.nodeCount(); ++v) {
    const Roadmap::Entry& e = roadmap_.entryOf(v);
    if (&e.manifold->family() != &SliceManifold::kFamily) continue;
    if (Subspace::isLocal(e.index)) continue;  // holds are drawn at the shared angles only
    const Subspace& sub = *subspaces_[e.group];
    cells_[sub.moving()].push_back(v);
    cellAdded(v, sub, e.index);
    if (reached(v)) reached_[sub.moving()].push_back(v);
  }
}

// Cells join the start's or goal's component later too; cells of new subspaces are added as
// they come.
const std::vector<std::vector<size_t>>& HeldRobotPlanner::reachedCells() {
  if (roadmap_.nodeCount() > reachedScan_ + reachedScan_ / 4) {
    reachedScan_ = roadmap_.nodeCount();
    for (size_t r = 0; r < k_; ++r) {
      reached_[r].clear();
      for (const size_t v : cells_[r])
        if (reached(v)) reached_[r].push_back(v);
    }
  }
  return reached_;
}

void HeldRobotPlanner::updateTotals() {
  common_.graphNodes = roadmap_.nodeCount();
  common_.graphEdges = roadmap_.edgeCount();
  common_.totalSeconds = clock_.seconds();
}

PlanStatus HeldRobotPlanner::run(const Termination& stop, const std::function<void()>& report,
                                 std::vector<Config>& waypoints, PathCheckResult& certificate) {
  clock_ = Stopwatch();
  const StopScope scope(stop);
  roadmap_.startClock();
  roadmap_.trackReached(settings_.record);
  try {
    return runRoundsFrom(stop, report, waypoints, certificate);
  } catch (const Stopped&) {
    // The manifold under construction is dropped (see StopScope).
    waypoints.clear();
    certificate = {};
    return stop.cancelled() ? PlanStatus::Cancelled : PlanStatus::NotFound;
  }
}

PlanStatus HeldRobotPlanner::runRoundsFrom(const Termination& stop,
                                           const std::function<void()>& report,
                                           std::vector<Config>& waypoints,
                                           PathCheckResult& certificate) {
  buildBaseSlices(stop);
  if (stop()) return stop.cancelled() ? PlanStatus::Cancelled : PlanStatus::NotFound;
  // A translating robot whose start and goal its one slice puts apart may have no motion at all:
  // the proof (NoPath.h) then ends the search here instead of at the time limit.
  common_.noPath = noPathOfAny(scene_, checker_, [&](size_t r) {
    return translates_[r] && apartIn(base_[r].front(), scene_.robots[r]);
  });
  if (!common_.noPath.empty()) return PlanStatus::NotFound;
  if (!placeEnds(stop)) return PlanStatus::NotFound;
  rootSubspaces_ = subspaces_.size();
  rootLines_ = settings_.nLines;
  endsPlaced(stop);
  sliceNarrowArcsIfDisconnected();

  Stopwatch sinceReport;
  RoundHooks h;
  h.begin = [&] { beginStretch(); };
  h.growing = [&] { return growing(); };
  h.complete = [&] { return roundComplete(); };
  h.share = [&] { return roundShare(); };
  h.grow = [&] {
    growStep(stop);
    if (sinceReport.seconds() >= 1.0) {
      report();
      sinceReport = Stopwatch();
    }
  };
  h.motion = [&](const std::vector<size_t>& nodes) {
    return certifiedMotion(scene_, checker_, roadmap_, nodes);
  };
  h.refused = [&] { sliceNarrowArcsNow(); };
  h.report = report;
  h.next = [&] { return nextRound(stop); };
  RoundsOutcome o = runRounds(h, roadmap_, size_t(from_), size_t(to_), stop, common_);
  return recordOutcome(o, roadmap_, common_, waypoints, certificate);
}

// Before a new round: false to give up (maxRounds, or a proof that no path exists); else the
// policy's targets, the root subspaces' lines and the angle sets grow. A narrow passage may
// need the robots' angles closer than the current sets offer (the Pacman's mouth and the
// square), or an angle the obstacles alone allow (an L through a gap); while a set is small the
// policy's targets wait (anglesFirst).
bool HeldRobotPlanner::nextRound(const Termination& stop) {
  if (settings_.maxRounds && common_.rounds >= settings_.maxRounds) return false;
  // A second round without a path: before growing, whether any path exists (NoPath.h; with
  // maxRounds, a test setting, of 2 or less it never runs).
  if (common_.rounds == 2)
    common_.noPath = noPathOfAny(scene_, checker_, [&](size_t r) { return !translates_[r]; });
  if (!common_.noPath.empty()) return false;
  nextTargets(!anglesFirst(sequenceAngles_, translates_));
  growRootLines(rootLines_, stop);
  rootLines_ *= 2;
  for (size_t r = 0; r < k_; ++r)
    if (!translates_[r]) {
      const std::vector<double> thetas = angles_[r]->take(sequenceAngles_[r]);
      sequenceAngles_[r] *= 2;
      addAngles(r, thetas, stop);
    }
  roundGrown(stop);
  // Rounds that only add angles grow no holds, so nothing else would build these now.
  if (!stop()) sliceNarrowArcsIfDisconnected();
  return true;
}

}  // namespace mms
