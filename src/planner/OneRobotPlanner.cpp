#include "planner/OneRobotPlanner.h"

#include <cmath>
#include <limits>

#include "geometry/PolygonOps.h"
#include "geometry/SpinPlace.h"
#include "manifolds/CellRoute.h"
#include "manifolds/CellSampling.h"
#include "manifolds/Pivot.h"
#include "path/Motion.h"
#include "planner/NoPath.h"
#include "planner/Rounds.h"
#include "util/Parallel.h"

namespace mms {

Scene singleRobotScene(const Scene& scene, size_t robot) {
  Scene s = scene;
  s.robots = {scene.robots[robot]};
  return s;
}

std::vector<double> AngleSequence::take(size_t n) {
  std::vector<double> out(n);
  for (double& t : out) t = next();
  return out;
}

std::vector<double> AngleSequence::startGoalThen(const Robot& robot, size_t n) {
  std::vector<double> out{robot.start.theta};
  if (std::fabs(std::remainder(robot.goal.theta - robot.start.theta, 2 * M_PI)) > 1e-9)
    out.push_back(robot.goal.theta);
  for (size_t i = 0; i < n; ++i) out.push_back(next());
  return out;
}

double AngleSequence::next() {
  const size_t k = count_++;
  double fraction;
  if (k < n_) {
    fraction = double(k) / n_;
  } else {
    size_t level = 1, start = n_;  // level L holds n * 2^(L-1) angles
    while (k >= start + (n_ << (level - 1))) start += n_ << (level - 1), ++level;
    fraction = double(2 * (k - start) + 1) / double(n_ << level);
  }
  return std::remainder(shift_ + 2 * M_PI * fraction, 2 * M_PI);
}

OneRobotPlanner::OneRobotPlanner(const Scene& scene, size_t robot, OneRobotSettings settings)
    : scene_(singleRobotScene(scene, robot)),
      settings_(settings),
      checker_(scene_),
      contactScene_(withContactShapes(scene_, checker_)),
      sliceWorld_(contactScene_, 0),
      rng_(settings.seed),
      angles_(settings.nTheta, rng_.uniform(0, 2 * M_PI)) {
  subspaces_.push_back(std::make_unique<Subspace>(0, contactScene_, checker_, 0,
                                                  std::vector<std::pair<size_t, Pose>>{}, roadmap_,
                                                  stats_.manifolds));
}

OneRobotPlanner::~OneRobotPlanner() = default;

Vec2 OneRobotPlanner::nextLinePoint() {
  const Box& b = scene_.bounds;
  // Part of the points where some slice has room for the robot: lines there can connect.
  if (!slices().empty() && rng_.uniform() < settings_.freeLineShare) {
    // Near a vertex of a cell: a placement touching two features (a corridor's corner), where
    // a robot turning a bend must be and uniform points rarely fall.
    if (rng_.uniform() < settings_.cornerLineShare) {
      const Slice& s = slices()[rng_.below(slices().size())];
      if (s.fscCount() > 0)
        if (const auto p = samplePointNearVertex(s, rng_.below(s.fscCount()), rng_)) return *p;
    }
    for (int attempt = 0; attempt < 20; ++attempt) {
      const Slice& s = slices()[rng_.below(slices().size())];
      const Vec2 p = rng_.uniformIn(b);
      if (s.locate(p) >= 0) return p;
    }
  }
  return rng_.uniformIn(b);
}

void OneRobotPlanner::addPivotLines(const Pose& start, const Pose& goal) {
  pivotsAdded_ = true;
  if (!settings_.pivotLines) return;
  const std::optional<Disc> pocket = pocketDisc(contactScene_.robots[0].shape);
  if (!pocket) return;
  const LineWorld world = pivotWorld(contactScene_, pocket->center);
  std::vector<Vec2> parts;
  for (const Ring& o : contactScene_.obstacles)
    if (const Disc part = smallestCircle(o); part.radius <= pocket->radius)
      parts.push_back(part.center);
  if (parts.empty()) return;
  // A turn about a part begins and ends where the robot comes and goes: the slices at the
  // start's and the goal's angles reach it there, where a robot that cannot turn in its
  // corridor meets no slice of the sequence for rounds.
  addEndSlices(start, goal);
  for (const Vec2 at : parts) addPivotLine(world, pocket->center, at);
}

void OneRobotPlanner::addPivotLine(const LineWorld& world, Vec2 pivot, Vec2 at) {
  std::unique_ptr<PivotLineManifold> line;
  {
    const TimeCharge charge(stats_.manifolds.lineSeconds);
    line = std::make_unique<PivotLineManifold>(
        world, [&](const Pose& q) { return subspace().free(q); }, pivot, at,
        &stats_.manifolds.lineStats);
  }
  ++stats_.manifolds.lines;
  stats_.manifolds.lineArcs += line->cellCount();
  subspace().addWovenLine(std::move(line), uint32_t(stats_.pivotLines++));
}

void OneRobotPlanner::addEndSlices(const Pose& start, const Pose& goal) {
  if (endSlicesAdded_) return;
  endSlicesAdded_ = true;
  addSlice(start.theta);
  addSlice(goal.theta);
  extraSlices_ += 2;
}

// Where the robot can turn all the way round: local maxima of the distance to the walls at
// least its smallest circle's radius, climbed to from a grid over the bounds (once per roadmap).
std::vector<Vec2> OneRobotPlanner::spinPlaces(double radius) const {
  constexpr int kGrid = 4;
  const Box& b = contactScene_.bounds;
  const double w = (b.xmax - b.xmin) / kGrid, h = (b.ymax - b.ymin) / kGrid;
  std::vector<Vec2> places;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      checkpoint();  // among thousands of obstacles each climb takes a while
      const Vec2 from{b.xmin + (i + 0.5) * w, b.ymin + (j + 0.5) * h};
      const Vec2 at = clearestNear(contactScene_, from, 0.25 * std::min(w, h),
                                   std::numeric_limits<double>::infinity());
      if (wallDistance(contactScene_, at) < radius) continue;
      bool taken = false;
      for (const Ring& o : contactScene_.obstacles) taken = taken || insideRing(o, at);
      for (const Vec2 p : places) taken = taken || std::hypot(p.x - at.x, p.y - at.y) < radius / 4;
      if (!taken) places.push_back(at);
    }
  return places;
}

void OneRobotPlanner::addSpinPlaces() {
  spinsAdded_ = true;
  if (!settings_.spinPlaces) return;
  const Disc circle = smallestCircle(contactScene_.robots[0].shape);
  const std::vector<Vec2> places = spinPlaces(circle.radius);
  spinPlacesFound_ = !places.empty();
  if (places.empty()) return;
  const LineWorld world = pivotWorld(contactScene_, circle.center);
  for (const Vec2 at : places) addPivotLine(world, circle.center, at);
}

void OneRobotPlanner::addSlice(double theta) {
  std::optional<Slice> base;
  {
    const TimeCharge charge(stats_.manifolds.sliceSeconds);
    base.emplace(sliceWorld_, exact::rationalAngleNear(theta, 30), settings_.pointLocation);
  }
  subspace().addSlice(*base);  // nothing is held: shares the base's cells
}

// The slice at the next angle of the sequence. Slices are built settings_.threads at a time
// and kept until their turn, so the roadmap grows in the same order whatever the thread count.
void OneRobotPlanner::addNextSlice() {
  if (ahead_.empty()) {
    std::vector<double> thetas(std::max(1u, settings_.threads));
    for (double& t : thetas) t = angles_.next();
    buildSlices(sliceWorld_, thetas, settings_.threads, settings_.pointLocation,
                stats_.manifolds.sliceSeconds, [&](Slice&& s) { ahead_.push_back(std::move(s)); });
  }
  subspace().addSlice(ahead_.front());  // nothing is held: shares the base's cells
  ahead_.pop_front();
}

OneRobotStats OneRobotPlanner::statsSoFar(double seconds) const {
  OneRobotStats s = stats_;
  s.graphNodes = roadmap_.nodeCount();
  s.graphEdges = roadmap_.edgeCount();
  s.totalSeconds += seconds;
  return s;
}

OneRobotResult OneRobotPlanner::finish(OneRobotResult result, PlanStatus status, double seconds) {
  stats_ = statsSoFar(seconds);
  result.status = status;
  result.stats = stats_;
  return result;
}

// A translate-only robot has a 2-D C-space: the one slice at its angle is its exact free
// space, so start and goal are connected iff they lie in the same cell. Complete, no sampling.
PlanStatus OneRobotPlanner::solveTranslation(const Pose& start, const Pose& goal,
                                             OneRobotResult& result) {
  if (slices().empty()) addSlice(start.theta);
  const Slice& s = slices().front();
  const int a = s.locate({start.x, start.y}), b = s.locate({goal.x, goal.y});
  if (a >= 0 && b >= 0 && a != b) stats_.noPath = noPathAlone(scene_, checker_, 0, start, goal);
  if (a < 0 || a != b) return PlanStatus::NotFound;
  const auto route = routeInCell(s.cell(a), [&](Vec2 p) { return s.locate(p) == a; },
                                 {start.x, start.y}, {goal.x, goal.y});
  if (!route) return PlanStatus::NotFound;
  std::vector<Config> w;
  for (Vec2 p : *route) w.push_back({p.x, p.y, start.theta});
  result.certificate = checkPath(scene_, checker_, w);
  if (!result.certificate.ok) {
    ++stats_.rejectedPaths;
    return PlanStatus::NotFound;
  }
  stats_.pathCells = stats_.pathManifolds = 1;
  result.waypoints = std::move(w);
  return PlanStatus::Found;
}

OneRobotResult OneRobotPlanner::solve(const Pose& start, const Pose& goal, const Termination& stop,
                                      const std::function<void(const OneRobotStats&)>& progress) {
  Stopwatch total;
  const StopScope scope(stop);
  roadmap_.startClock();
  roadmap_.trackReached(settings_.record);
  try {
    return solveRounds(start, goal, stop, progress);
  } catch (const Stopped&) {
    // The manifold under construction is dropped; the roadmap stays as it was before it.
    return finish(OneRobotResult{}, stop.cancelled() ? PlanStatus::Cancelled : PlanStatus::NotFound,
                  total.seconds());
  }
}

namespace {

// A round's targets of slices and lines, and where the round began: slices and lines grow in
// proportion, so the round's share of its targets met is the mean of theirs.
struct RoundTargets {
  size_t slices, lines, slicesFrom, linesFrom;
  double share(size_t builtSlices, size_t builtLines) const {
    auto part = [](size_t now, size_t from, size_t to) {
      return to <= from ? 1.0 : std::min(1.0, double(now - from) / double(to - from));
    };
    return (part(builtSlices, slicesFrom, slices) + part(builtLines, linesFrom, lines)) / 2;
  }
  // The next round: twice the targets, from what is built.
  void doubleFrom(size_t builtSlices, size_t builtLines) {
    slicesFrom = builtSlices, linesFrom = builtLines;
    slices *= 2, lines *= 2;
  }
};

}  // namespace

OneRobotResult OneRobotPlanner::solveRounds(
    const Pose& start, const Pose& goal, const Termination& stop,
    const std::function<void(const OneRobotStats&)>& progress) {
  Stopwatch total;
  OneRobotResult result;
  stats_.noPath.clear();    // a proof about an earlier query of this roadmap
  endSlicesAdded_ = false;  // this query's start and goal angles get their own
  scene_.robots[0].start = start;
  scene_.robots[0].goal = goal;
  if (scene_.robots[0].motion == Motion::Translate) {
    const PlanStatus status = solveTranslation(start, goal, result);
    return finish(result, status, total.seconds());  // timed after the solve, which counts
  }
  // Start and goal enter through lines at their positions (a line holds every angle).
  Subspace& sub = subspace();
  const size_t startLine = sub.addLine({start.x, start.y}),
               goalLine = sub.addLine({goal.x, goal.y});
  const long from = sub.lineNodeAt(startLine, start.theta),
             to = sub.lineNodeAt(goalLine, goal.theta);
  if (from < 0 || to < 0) return finish(result, PlanStatus::NotFound, total.seconds());  // not free

  // The slices at the start's and goal's angles stand beside the sequence: counted in it they
  // would shift the interleaving, and a scene solved in round one would build other manifolds.
  auto sequenced = [&] { return slices().size() - extraSlices_; };
  RoundTargets target{std::max(sequenced(), settings_.nTheta),
                      std::max(lines().size(), settings_.nLines), sequenced(), lines().size()};
  Stopwatch sinceReport;
  auto report = [&](bool force) {
    if (!progress || (!force && sinceReport.seconds() < 1.0)) return;
    progress(statsSoFar(total.seconds()));
    sinceReport = Stopwatch();
  };
  // Slices and lines interleaved in the round's proportion, so that an early connection finds
  // few of either built (the angle sequence covers the circle evenly at every prefix). The
  // search runs as soon as start and goal connect: in open scenes a few dozen lines suffice.
  RoundHooks h;
  h.growing = [&] { return sequenced() < target.slices || lines().size() < target.lines; };
  h.complete = [&] { return !h.growing(); };
  h.share = [&] { return target.share(sequenced(), lines().size()); };
  h.grow = [&] {
    if (!spinsAdded_) addSpinPlaces();
    // After two slices of the sequence: where those connect start and goal (open scenes, many
    // imported ones), two more slices among hundreds of obstacles would double the time.
    if (spinPlacesFound_ && sequenced() >= 2) addEndSlices(start, goal);
    const bool slicesBehind = sequenced() * target.lines <= lines().size() * target.slices;
    if (sequenced() < target.slices && (slicesBehind || lines().size() >= target.lines))
      addNextSlice();
    else
      sub.addLine(nextLinePoint());
    if (stats_.rounds >= 2 && !pivotsAdded_) addPivotLines(start, goal);
    report(false);
  };
  h.motion = [&](const std::vector<size_t>& nodes) {
    return certifiedMotion(scene_, checker_, roadmap_, nodes);
  };
  h.report = [&] { report(true); };
  size_t roundsWithoutPath = 0;
  h.next = [&] {
    if (settings_.maxRounds && stats_.rounds >= settings_.maxRounds) return false;
    // A second round without a path: before doubling, whether any path exists (NoPath.h). After
    // the first, it would cost the runs that succeed in round two one more slice (4 % of them).
    if (++roundsWithoutPath == 2) {
      stats_.noPath = noPathAlone(scene_, checker_, 0, start, goal);
      if (!stats_.noPath.empty()) return false;
    }
    target.doubleFrom(sequenced(), lines().size());
    return true;
  };
  RoundsOutcome o = runRounds(h, roadmap_, size_t(from), size_t(to), stop, stats_);
  result.certificate = o.motion.certificate;
  if (o.end == RoundsOutcome::End::Found) {
    stats_.pathCells = o.nodes.size();
    stats_.pathManifolds = roadmap_.footprint(o.nodes).manifolds;
    for (size_t v : o.nodes) result.cells.push_back(roadmap_.graph().node(v));
    result.waypoints = std::move(o.motion.waypoints);
    return finish(result, PlanStatus::Found, total.seconds());
  }
  return finish(
      result, o.end == RoundsOutcome::End::Cancelled ? PlanStatus::Cancelled : PlanStatus::NotFound,
      total.seconds());
}

}  // namespace mms
