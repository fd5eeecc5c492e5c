#include "planner/TwoRobotPlanner.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>

#include "geometry/PolygonOps.h"
#include "path/Motion.h"
#include "planner/NoPath.h"
#include "planner/Rounds.h"
#include "util/Deferred.h"
#include "util/Parallel.h"

namespace mms {

// Robot 1 gets one angle more than robot 0: with coprime set sizes n and n + 1, the robots'
// relative angles (what decides whether one fits into the other, the square into the Pacman's
// mouth) are spaced 2 pi / (n (n + 1)) instead of 2 pi / n, at no extra cost.
size_t TwoRobotPlanner::angleCount(size_t robot) const { return settings_.nTheta + robot; }

TwoRobotPlanner::TwoRobotPlanner(const Scene& scene, TwoRobotSettings settings)
    : scene_(scene),
      settings_(settings),
      checker_(scene_),
      contactScene_(withContactShapes(scene_, checker_)),
      rng_(settings.seed),
      sampler_(std::make_unique<MixedFixings>(settings.expandShare, settings.connectShare,
                                              settings.connectSteps, settings.cornerShare,
                                              settings.cornerCandidates)) {
  for (size_t r = 0; r < 2; ++r) {
    translates_[r] = scene_.robots[r].motion == Motion::Translate;
    worlds_[r] = std::make_unique<SliceWorld>(contactScene_, r);
    lineWorlds_[r] = std::make_unique<LineWorld>(contactScene_, r);
    angles_[r] = std::make_unique<AngleSequence>(angleCount(r), rng_.uniform(0, 2 * M_PI));
  }
}

// The robots' base slices (a translating robot's one angle, a rigid robot's first n_theta),
// built in solve() so that their cost, up to seconds among many obstacles, counts against its
// time limit.
void TwoRobotPlanner::buildBaseSlices(const Termination& stop) {
  for (size_t r = 0; r < 2 && !stop(); ++r) {
    if (!base_[r].empty()) continue;
    if (translates_[r]) {
      const TimeCharge charge(stats_.baseSliceSeconds);
      base_[r].emplace_back(*worlds_[r],
                            exact::rationalAngleNear(scene_.robots[r].start.theta, 30));
    } else {
      sequenceAngles_[r] = angleCount(r);
      addAngles(r, angles_[r]->startGoalThen(scene_.robots[r], angleCount(r)), stop);
    }
  }
}

// More angles for a rigid robot: the next ones of its evenly spread sequence (the midpoints of
// the current set), each a new base slice and a new slice in every subspace where it moves.
// Base slices are built settings_.threads at a time and appended in angle order; a subspace's
// slice k is always the overlay of base slice k.
void TwoRobotPlanner::addAngles(size_t robot, const std::vector<double>& thetas,
                                const Termination& stop) {
  const size_t firstNode = roadmap_.nodeCount(), firstAngle = base_[robot].size();
  if (stop()) return;
  buildSlices(*worlds_[robot], thetas, settings_.threads, PointLocation::Auto,
              stats_.baseSliceSeconds, [&](Slice&& s) { base_[robot].push_back(std::move(s)); });
  std::vector<Subspace*> moving;
  for (auto& sub : subspaces_)
    if (sub->moving() == robot) moving.push_back(sub.get());
  if (!moving.empty())
    addOverlays((base_[robot].size() - firstAngle) * moving.size(),
                [&](size_t i) -> std::pair<Subspace*, const Slice*> {
                  return {moving[i % moving.size()], &base_[robot][firstAngle + i / moving.size()]};
                });
  for (auto& c : compounds_)
    if (robot == c->frame().carrier)
      for (size_t k = firstAngle; k < base_[robot].size() && !stop(); ++k)
        c->addSlice(base_[robot][k], *worlds_[c->frame().attached]);
  collectCells(firstNode);
}

TwoRobotPlanner::~TwoRobotPlanner() = default;

namespace {
bool sameRelativePose(const CompoundFrame& f, const CompoundFrame& g) {
  return std::hypot(f.offset.x - g.offset.x, f.offset.y - g.offset.y) <=
             1e-9 * (1 + std::hypot(f.offset.x, f.offset.y)) &&
         std::abs(std::remainder(f.dtheta - g.dtheta, 2 * M_PI)) <= 1e-9;
}
}  // namespace

// A pair that starts and ends close together (a part held in a gripper, a robot pushing
// another) moves as one rigid body: one compound subspace per relative pose of its start and
// goal (one if they agree). Each has lines at robot 0's start and goal positions; they meet the
// start and goal arcs at the start and goal configurations themselves. Where the relative
// poses differ, robot 1 changes its hold in the subspaces holding robot 0 at its start or goal:
// a line there at robot 1's position in the other relative pose meets the other compound. Pairs
// apart at either end build none: they pay nothing.
void TwoRobotPlanner::addCompound(const Termination& stop) {
  if (!settings_.coupled || translates_[0] || translates_[1]) return;
  const Robot &a = scene_.robots[0], &b = scene_.robots[1];
  const double reach = 0.25 * std::min(radius(a.shape), radius(b.shape));
  if (checker_.robotsDistance(0, a.start, 1, b.start) > reach ||
      checker_.robotsDistance(0, a.goal, 1, b.goal) > reach)
    return;
  std::vector<CompoundFrame> frames{CompoundFrame::between(a.start, b.start)};
  if (const CompoundFrame g = CompoundFrame::between(a.goal, b.goal);
      !sameRelativePose(frames[0], g))
    frames.push_back(g);
  for (const CompoundFrame& f : frames) {
    if (stop()) return;
    compounds_.push_back(
        std::make_unique<CompoundSubspace>(uint32_t((1u << 30) + compounds_.size()), contactScene_,
                                           checker_, f, roadmap_, stats_.compound));
    CompoundSubspace& c = *compounds_.back();
    for (const Slice& base : base_[0]) c.addSlice(base, *worlds_[1]);
    // Subspaces 0 and 2 hold robot 0 at its start and goal; 1 and 3 robot 1.
    for (const auto& [carrier, held, end] :
         {std::tuple{a.start, size_t(0), from_}, std::tuple{a.goal, size_t(2), to_}}) {
      const uint32_t line = c.addLine({carrier.x, carrier.y});
      roadmap_.join(line, roadmap_.graph().node(size_t(end)).manifold);
      const Pose other = f.attachedPose(carrier);
      const Pose own = held == 0 ? b.start : b.goal;
      if (std::hypot(other.x - own.x, other.y - own.y) >
          1e-9 * (1 + std::abs(own.x) + std::abs(own.y))) {
        const size_t l = subspaces_[held]->addLine({other.x, other.y});
        roadmap_.join(subspaces_[held]->lineId(l), line);
      }
    }
    addCompoundLines(c, settings_.nLines, stop);
  }
}

// Half the compound's lines in its slices' cells drawn uniformly among the cells (the compound
// turns where its cells are small: a chamber just larger than the pair), half as a subspace's.
void TwoRobotPlanner::addCompoundLines(CompoundSubspace& c, size_t count, const Termination& stop) {
  for (size_t i = 0; i < count && !stop(); ++i) {
    std::optional<Vec2> p;
    if (rng_.uniform() < 0.5) p = c.pointInCell(rng_);
    c.addLine(p ? *p : linePoint(c.frame().carrier));
  }
}

// Overlays (a base slice minus the held robot) for `count` (subspace, base) pairs, built
// settings_.threads at a time and added in index order, so the roadmap does not depend on the
// thread count. A build the time limit cut short ends it (Stopped): the ones before it stay.
void TwoRobotPlanner::addOverlays(
    size_t count, const std::function<std::pair<Subspace*, const Slice*>(size_t)>& item) {
  const size_t batch = std::max<size_t>(1, 4 * size_t(settings_.threads));
  for (size_t done = 0; done < count;) {
    checkpoint();
    const size_t n = std::min(batch, count - done);
    std::vector<std::optional<Slice>> built(n);
    std::vector<std::exception_ptr> errors;
    {
      const TimeCharge charge(stats_.manifolds.sliceSeconds);
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

// Narrow arcs the held robot makes (narrowArcMiddles): a slice at each middle, local to this
// subspace, opens the rotation passage the shared angles miss (the Pacman turned round so the
// square passes through its mouth); at most settings_.narrowSlices each time the subspace's
// new lines are scanned (once for most subspaces, every round for the start and goal ones).
// Open scenes have no such arcs and pay nothing.
void TwoRobotPlanner::sliceNarrowArcs(Subspace& sub) {
  const size_t moving = sub.moving();
  std::vector<double> met;
  for (const Slice& s : base_[moving]) met.push_back(s.theta());
  for (const Slice& s : sub.localSlices()) met.push_back(s.theta());
  std::vector<exact::RationalAngle> middles;
  {
    // Most of this is the lines among the obstacles alone that narrowArcMiddles builds.
    const TimeCharge charge(stats_.manifolds.lineSeconds);
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
    const TimeCharge charge(stats_.manifolds.sliceSeconds);
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
// subspace (fixings are drawn at shared angles), so building them later loses no meeting point.
void TwoRobotPlanner::sliceNarrowArcsIfDisconnected() {
  if (from_ >= 0 && roadmap_.graph().connected(size_t(from_), size_t(to_))) return;
  sliceNarrowArcsNow();
}

void TwoRobotPlanner::sliceNarrowArcsNow() {
  // Taken first: a subspace the time limit cuts short is not retried.
  for (const size_t k : std::exchange(narrowPending_, {})) sliceNarrowArcs(*subspaces_[k]);
}

Vec2 TwoRobotPlanner::linePoint(size_t robot) {
  return subspaceLinePoint(base_[robot], scene_.bounds, rng_);
}

long TwoRobotPlanner::nodeFor(const Subspace& sub, const Fixing& f, bool knownFree) const {
  if (f.angle >= 0) return sub.sliceNodeAt(size_t(f.angle), {f.pose.x, f.pose.y}, knownFree);
  return sub.lineNodeAt(size_t(f.specialLine), f.pose.theta);
}

size_t TwoRobotPlanner::addSubspace(const Fixing& held, const Termination& stop) {
  const size_t moving = 1 - held.robot;
  const size_t firstNode = roadmap_.nodeCount();
  subspaces_.push_back(std::make_unique<Subspace>(
      uint32_t(subspaces_.size()), contactScene_, checker_, moving,
      std::vector<std::pair<size_t, Pose>>{{held.robot, held.pose}}, roadmap_, stats_.manifolds));
  fixings_.push_back(held);
  ++stats_.subspaces;
  ++stats_.fixings[held.robot];
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
  // Meet subspaces of the other family at the pair of their held poses.
  Stopwatch watch;
  for (const size_t j : crossCandidates(held)) {
    // Both fixings are free among the obstacles; the pair meets where the robots are disjoint.
    if (!checker_.robotsDisjoint(held.robot, held.pose, fixings_[j].robot, fixings_[j].pose))
      continue;
    const long here = nodeFor(sub, fixings_[j], true);
    if (here < 0) continue;
    const long there = nodeFor(*subspaces_[j], held, true);
    if (there < 0) continue;
    roadmap_.addEdge(size_t(here), size_t(there));
    ++stats_.crossEdges;
  }
  stats_.crossSeconds += watch.seconds();
  collectCells(firstNode);
  return subspaces_.size() - 1;
}

// The four subspaces holding a robot at its start or goal double their random lines each
// round, as the slices double their angles. Every path begins and ends in them, and no later
// fixing can stand in for them as new fixings stand in for any other subspace, so a rotation
// passage their first lines missed (the Pacman turned round the square held at the square's
// goal until the square can leave its mouth) would otherwise wait for the shared angles to
// become dense enough.
void TwoRobotPlanner::growRootLines(size_t count, const Termination& stop) {
  for (size_t k = 0; k < kRootSubspaces && !stop(); ++k)
    if (!translates_[subspaces_[k]->moving()]) addRandomLines(*subspaces_[k], count, stop);
}

// Random lines (subspaceLinePoint) in a subspace of a rigid robot; their narrow arcs wait in
// narrowPending_ for sliceNarrowArcsIfDisconnected.
void TwoRobotPlanner::addRandomLines(Subspace& sub, size_t count, const Termination& stop) {
  for (size_t i = 0; i < count && !stop(); ++i) sub.addLine(linePoint(sub.moving()));
  narrowPending_.push_back(sub.id());
}

bool TwoRobotPlanner::leavesRoom(const Fixing& f) {
  const TimeCharge charge(stats_.manifolds.sliceSeconds);
  ++stats_.screenedPoses;
  return cutsNoPassage(base_[1 - f.robot].front(), heldShape(contactScene_, f.robot, f.pose));
}

TwoRobotResult TwoRobotPlanner::finish(TwoRobotResult r, PlanStatus status) {
  return finishedRun(std::move(r), status, roadmap_, stats_, clock_);
}

TwoRobotResult TwoRobotPlanner::solve(const Termination& stop,
                                      const std::function<void(const TwoRobotStats&)>& progress) {
  clock_ = Stopwatch();
  const StopScope scope(stop);
  try {
    return solveRounds(stop, progress);
  } catch (const Stopped&) {
    // The manifold under construction is dropped (see StopScope).
    return finish(TwoRobotResult{},
                  stop.cancelled() ? PlanStatus::Cancelled : PlanStatus::NotFound);
  }
}

TwoRobotResult TwoRobotPlanner::solveRounds(
    const Termination& stop, const std::function<void(const TwoRobotStats&)>& progress) {
  TwoRobotResult result;
  buildBaseSlices(stop);
  if (stop())
    return finish(result, stop.cancelled() ? PlanStatus::Cancelled : PlanStatus::NotFound);
  // A translating robot whose start and goal its one slice puts apart may have no motion at all:
  // the proof (NoPath.h) then ends the search here instead of at the time limit.
  stats_.noPath = noPathOfAny(scene_, checker_, [&](size_t r) {
    return translates_[r] && apartIn(base_[r].front(), scene_.robots[r]);
  });
  if (!stats_.noPath.empty()) return finish(result, PlanStatus::NotFound);
  // Start and goal fixings: each robot held at its start and at its goal. A translating
  // robot's poses lie in its one slice; a rigid robot's on lines 0 (start) and 1 (goal).
  std::array<Fixing, 2> start, goal;
  for (size_t r = 0; r < 2; ++r) {
    const Robot& rb = scene_.robots[r];
    start[r] = {r, rb.start, translates_[r] ? 0L : -1L, translates_[r] ? -1L : 0L, -1};
    goal[r] = {r, rb.goal, translates_[r] ? 0L : -1L, translates_[r] ? -1L : 1L, -1};
  }
  for (const Fixing& f : {start[0], start[1], goal[0], goal[1]}) addSubspace(f, stop);
  // Robot 0 moves in the subspace holding robot 1 at its start (index 1) / goal (index 3).
  const long from = nodeFor(*subspaces_[1], start[0]), to = nodeFor(*subspaces_[3], goal[0]);
  if (from < 0 || to < 0) return finish(result, PlanStatus::NotFound);
  from_ = from;
  to_ = to;
  addCompound(stop);
  sliceNarrowArcsIfDisconnected();

  size_t target = settings_.nFixings, rootLines = settings_.nLines;
  Stopwatch sinceReport;
  // The robots take turns, so both families grow before start and goal connect.
  std::array<bool, 2> exhausted{false, false};
  auto wants = [&](size_t r) { return !exhausted[r] && stats_.fixings[r] < target + 2; };
  RoundHooks h;
  h.begin = [&] { exhausted = {false, false}; };
  h.growing = [&] { return wants(0) || wants(1); };
  h.complete = [&] { return stats_.fixings[0] >= target + 2 && stats_.fixings[1] >= target + 2; };
  h.grow = [&] {
    for (size_t r = 0; r < 2 && !stop(); ++r) {
      if (!wants(r)) continue;
      if (!sampler_->grow(r, *this, stop)) exhausted[r] = true;
      sliceNarrowArcsIfDisconnected();
      if (progress && sinceReport.seconds() >= 1.0) {
        progress(finish(result, PlanStatus::NotFound).stats);
        sinceReport = Stopwatch();
      }
    }
  };
  h.motion = [&](const std::vector<size_t>& nodes) {
    return certifiedMotion(scene_, checker_, roadmap_, nodes);
  };
  h.refused = [&] { sliceNarrowArcsNow(); };
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
    // Grow the angle sets: a narrow passage may need the two robots' angles closer than the
    // current sets offer (the Pacman's mouth and the square), or an angle the obstacles alone
    // allow (an L through a gap). While a set is small the fixings wait (anglesFirst).
    if (!anglesFirst(sequenceAngles_, translates_)) target *= 2;
    growRootLines(rootLines, stop);
    rootLines *= 2;
    for (size_t r = 0; r < 2; ++r)
      if (!translates_[r]) {
        const std::vector<double> thetas = angles_[r]->take(sequenceAngles_[r]);
        sequenceAngles_[r] *= 2;
        addAngles(r, thetas, stop);
      }
    for (auto& c : compounds_) addCompoundLines(*c, c->lineCount(), stop);
    // Rounds that only add angles grow no fixings, so nothing else would build these now.
    if (!stop()) sliceNarrowArcsIfDisconnected();
    return true;
  };
  RoundsOutcome o = runRounds(h, roadmap_, size_t(from), size_t(to), stop, stats_);
  const PlanStatus status =
      recordOutcome(o, roadmap_, stats_, result.waypoints, result.certificate);
  return finish(result, status);
}

}  // namespace mms
