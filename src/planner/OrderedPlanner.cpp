#include "planner/OrderedPlanner.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "geometry/Exact.h"
#include "geometry/PolygonOps.h"
#include "manifolds/CellRoute.h"
#include "manifolds/Slice.h"
#include "planner/KRobotPlanner.h"
#include "planner/OneRobotPlanner.h"
#include "planner/TwoRobotPlanner.h"

namespace mms {

namespace {

constexpr size_t kJointRoundsFirst = 4;
// Rounds of the one-robot MMS for a robot that turns on its way, while the others stand (more
// cost twice as much each, and the robots that need them are often blocked: on the warehouse's
// tuning seeds, 4 rounds made the two hard seeds slower, 7 s instead of 5-6 s with the
// k-robot MMS after 2).
constexpr size_t kTurnRounds = 2;

bool sameAngle(double a, double b) { return std::fabs(std::remainder(a - b, 2 * M_PI)) < 1e-12; }

// The route from a to b inside one cell of `slice`, if both lie in the same cell.
std::optional<std::vector<Vec2>> routeIn(const Slice& slice, Vec2 a, Vec2 b) {
  const int cell = slice.locate(a);
  if (cell < 0 || slice.locate(b) != cell) return std::nullopt;
  return routeInCell(
      slice.cell(size_t(cell)), [&](Vec2 p) { return slice.locate(p) == cell; }, a, b);
}

}  // namespace

// The obstacles' slice for one shape at one angle, shared by the robots that have both.
struct OrderedPlanner::ShapeSlice {
  ShapeSlice(const Scene& scene, size_t robot)
      : world(scene, robot),
        base(world, exact::rationalAngleNear(scene.robots[robot].start.theta, 30)) {}
  SliceWorld world;
  Slice base;
};

OrderedPlanner::OrderedPlanner(const Scene& scene, OrderedSettings settings)
    : scene_(scene), settings_(settings), checker_(scene) {
  for (const Ring& o : scene_.obstacles) obstacleBoxes_.push_back(boundingBox(o));
}

OrderedPlanner::~OrderedPlanner() = default;

// Robots furthest along the mean direction from starts to goals first: those in front of a
// crowd leave it first and reach the far side of the goals first.
std::vector<size_t> OrderedPlanner::order() const {
  const size_t k = scene_.robots.size();
  Vec2 d{0, 0};
  for (const Robot& r : scene_.robots) d = d + Vec2{r.goal.x - r.start.x, r.goal.y - r.start.y};
  std::vector<double> key(k, 0);
  if (norm(d) > 1e-9 * std::max(scene_.bounds.width(), scene_.bounds.height()))
    for (size_t i = 0; i < k; ++i) {
      const Robot& r = scene_.robots[i];
      key[i] = dot(Vec2{r.start.x + r.goal.x, r.start.y + r.goal.y}, d);
    }
  std::vector<size_t> out(k);
  std::iota(out.begin(), out.end(), 0);
  std::stable_sort(out.begin(), out.end(), [&](size_t a, size_t b) { return key[a] > key[b]; });
  return out;
}

// The region as a scene of its own: the obstacles and the standing robots that reach into it
// (as obstacles where they stand), and the moving robot.
Scene OrderedPlanner::regionScene(size_t robot, const Box& region) const {
  Scene local;
  local.bounds = region;
  for (size_t o = 0; o < scene_.obstacles.size(); ++o)
    if (obstacleBoxes_[o].overlaps(region)) local.obstacles.push_back(scene_.obstacles[o]);
  for (size_t j = 0; j < scene_.robots.size(); ++j) {
    const double rj = checker_.radius(j) + checker_.tolerance();
    const Box b{q_[3 * j] - rj, q_[3 * j + 1] - rj, q_[3 * j] + rj, q_[3 * j + 1] + rj};
    if (j != robot && b.overlaps(region))
      local.obstacles.push_back(placedRing(scene_.robots[j].shape, poseOf(q_, j)));
  }
  local.robots = {scene_.robots[robot]};
  return local;
}

OrderedPlanner::ShapeSlice& OrderedPlanner::sliceOf(size_t robot) {
  if (shapeOf_[robot] < 0) {
    const Robot& r = scene_.robots[robot];
    for (size_t other = 0; other < scene_.robots.size() && shapeOf_[robot] < 0; ++other)
      if (shapeOf_[other] >= 0 && scene_.robots[other].shape == r.shape &&
          scene_.robots[other].start.theta == r.start.theta)
        shapeOf_[robot] = shapeOf_[other];
    if (shapeOf_[robot] < 0) {
      const TimeCharge charge(stats_.baseSliceSeconds);
      slices_.push_back(std::make_unique<ShapeSlice>(scene_, robot));
      shapeOf_[robot] = long(slices_.size() - 1);
      ++stats_.baseSlices;
    }
  }
  return *slices_[size_t(shapeOf_[robot])];
}

// Takes the route for `robot` (the others where they stand) if every motion along it is
// certified.
bool OrderedPlanner::take(size_t robot, const std::vector<Vec2>& route) {
  const TimeCharge charge(stats_.certifySeconds);
  std::vector<Config> moves;
  Config at = q_;
  for (size_t k = 1; k < route.size(); ++k) {
    Config next = at;
    next[3 * robot] = route[k].x;
    next[3 * robot + 1] = route[k].y;
    // Where the others stand was certified with the moves before: only this robot is tested.
    if (!motionFree(checker_, at, next, /*stillOnesFree=*/true)) return false;
    moves.push_back(next);
    at = std::move(next);
  }
  path_.insert(path_.end(), moves.begin(), moves.end());
  q_ = at;
  return true;
}

// One robot from where it stands to its goal, the others held: the straight motion, the route
// in the obstacles' slice, the route in a slice of a region round it (grown as needed).
bool OrderedPlanner::moveAlone(size_t robot, const Termination& stop) {
  // A rigid robot that cannot translate there may turn its way there.
  return (sameAngle(q_[3 * robot + 2], scene_.robots[robot].goal.theta) &&
          translateAlone(robot, stop)) ||
         turnAlone(robot, stop);
}

bool OrderedPlanner::translateAlone(size_t robot, const Termination& stop) {
  const Robot& r = scene_.robots[robot];
  const Vec2 from{q_[3 * robot], q_[3 * robot + 1]}, to{r.goal.x, r.goal.y};
  if (take(robot, {from, to})) return ++stats_.straightMoves, true;
  ShapeSlice& s = sliceOf(robot);
  std::optional<std::vector<Vec2>> route;
  {
    const TimeCharge charge(stats_.routeSeconds);
    route = routeIn(s.base, from, to);
  }
  if (!route) return false;  // apart among the obstacles alone: no overlay joins them
  if (take(robot, *route)) return ++stats_.routeMoves, true;
  // The way is looked for in a region round the obstacles' route: a slice of that region alone,
  // among the obstacles and the robots standing in it, costs what the region holds whatever the
  // scene's size. A region whose cell does not join start and goal is grown, up to the bounds.
  const Box& all = scene_.bounds;
  double margin = settings_.regionDiameters * 2 * checker_.radius(robot);
  for (;; margin *= 2) {
    if (stop()) return false;
    Box region = boundingBox(*route);
    region = {std::max(all.xmin, region.xmin - margin), std::max(all.ymin, region.ymin - margin),
              std::min(all.xmax, region.xmax + margin), std::min(all.ymax, region.ymax + margin)};
    const bool whole = region.xmin == all.xmin && region.ymin == all.ymin &&
                       region.xmax == all.xmax && region.ymax == all.ymax;
    std::optional<std::vector<Vec2>> around;
    {
      const TimeCharge charge(stats_.regionSeconds);
      ++stats_.regionSlices;
      const Scene local = regionScene(robot, region);
      const SliceWorld world(local, 0);
      const Slice slice(world, exact::rationalAngleNear(r.start.theta, 30));
      around = routeIn(slice, from, to);
    }
    if (around && take(robot, *around)) return ++stats_.regionMoves, true;
    if (whole) break;
  }
  return false;
}

// Where every robot stands now, but `robots` placed as the sub-scene's configuration `sub`
// places them (its robot m is robots[m]).
Config OrderedPlanner::withMoved(const std::vector<size_t>& robots, const Config& sub) const {
  Config full = q_;
  for (size_t m = 0; m < robots.size(); ++m)
    for (size_t c = 0; c < 3; ++c) full[3 * robots[m] + c] = sub[3 * m + c];
  return full;
}

// The scene of `robots` from where they stand, the others obstacles where they stand (a disc an
// exact disc).
Scene OrderedPlanner::heldScene(const std::vector<size_t>& robots) const {
  Scene sub = scene_;
  sub.robots.clear();
  std::vector<bool> moving(scene_.robots.size(), false);
  for (size_t i : robots) {
    moving[i] = true;
    Robot r = scene_.robots[i];
    r.start = poseOf(q_, i);
    sub.robots.push_back(r);
  }
  for (size_t j = 0; j < scene_.robots.size(); ++j) {
    if (moving[j]) continue;
    const Robot& r = scene_.robots[j];
    if (r.disc > 0)
      sub.addObstacleDisc({{q_[3 * j], q_[3 * j + 1]}, r.disc});
    else
      sub.obstacles.push_back(placedRing(r.shape, poseOf(q_, j)));
  }
  return sub;
}

// A robot that turns on its way, the others held: one-robot MMS (slices and lines of its 3-D
// configuration space among the obstacles and the robots where they stand), a few rounds, so
// that a robot that cannot go yet leaves the time to the others.
bool OrderedPlanner::turnAlone(size_t robot, const Termination& stop) {
  if (scene_.robots[robot].motion != Motion::Rigid) return false;
  const TimeCharge charge(stats_.turnSeconds);
  const Scene sub = heldScene({robot});
  OneRobotSettings turn;
  turn.maxRounds = kTurnRounds;
  OneRobotPlanner p(sub, 0, seeded(turn));
  const OneRobotResult res = p.solve(sub.robots[0].start, sub.robots[0].goal, stop);
  if (res.status != PlanStatus::Found) return false;
  for (size_t k = 1; k < res.waypoints.size(); ++k)
    path_.push_back(withMoved({robot}, res.waypoints[k]));
  q_ = path_.back();
  ++stats_.turnMoves;
  return true;
}

// `robots` planned together by MMS from where they stand, the others held where they stand
// (as obstacles) or moving too.
bool OrderedPlanner::planJointly(std::vector<size_t> robots, bool othersAsObstacles,
                                 const Termination& stop) {
  // Among robots held as obstacles the robots left may have no way at all: a few rounds, then
  // all robots (whose MMS runs to the limit). A budget in rounds keeps the seed's result.
  const size_t rounds = othersAsObstacles ? kJointRoundsFirst : 0;
  const TimeCharge charge(stats_.jointSeconds);
  if (!othersAsObstacles) {
    robots.resize(scene_.robots.size());
    std::iota(robots.begin(), robots.end(), 0);
  }
  Scene sub = heldScene(robots);
  stats_.jointRobots = robots.size();
  std::vector<Config> w;
  PlanStatus status = PlanStatus::NotFound;
  // The recursive MMS for that many robots.
  auto heldHere = [&](auto s) {
    s.maxRounds = rounds;
    return seeded(s);
  };
  if (robots.size() == 1) {
    OneRobotPlanner p(sub, 0, seeded(OneRobotSettings{}));
    const OneRobotResult res = p.solve(sub.robots[0].start, sub.robots[0].goal, stop);
    status = res.status, w = res.waypoints;
  } else if (robots.size() == 2) {
    TwoRobotResult res = TwoRobotPlanner(sub, heldHere(TwoRobotSettings{})).solve(stop);
    status = res.status, w = std::move(res.waypoints);
  } else {
    KRobotResult res = KRobotPlanner(sub, heldHere(KRobotSettings{})).solve(stop);
    status = res.status, w = std::move(res.waypoints);
  }
  if (status != PlanStatus::Found) return false;
  for (const Config& sq : w) path_.push_back(withMoved(robots, sq));
  q_ = path_.back();
  for (size_t i : robots) atGoal_[i] = true;
  return true;
}

// Every robot from where it stands to its goal on the pebble graph, if it applies.
bool OrderedPlanner::shuffle(const Termination& stop) {
  if (!pebbleApplies(scene_, q_)) return false;
  const TimeCharge charge(stats_.pebbleSeconds);
  PebbleSettings pebbles = settings_.pebbles;
  pebbles.seed = settings_.seed;
  auto moves = pebbleMotion(scene_, checker_, q_, stop, stats_.pebbles, pebbles);
  if (!moves) return false;
  path_.insert(path_.end(), moves->begin() + 1, moves->end());
  q_ = path_.back();
  atGoal_.assign(atGoal_.size(), true);
  return true;
}

OrderedResult OrderedPlanner::solve(const Termination& outer,
                                    const std::function<void(const OrderedStats&)>& progress) {
  // The planners it runs in turn pass their rounds on to a watcher (the default planner's
  // allowance), not their growth within rounds, which is no share of this planner's work.
  const Termination stop = outer.withoutGrowthNotes();
  const Stopwatch clock;
  OrderedResult result;
  q_ = startConfig(scene_);
  path_ = {q_};
  atGoal_.assign(scene_.robots.size(), false);
  shapeOf_.assign(scene_.robots.size(), -1);
  const StopScope scope(stop);
  try {
    std::vector<size_t> left = order();
    for (bool moved = true; moved && !left.empty() && !stop();) {
      ++stats_.passes;
      moved = false;
      std::vector<size_t> still;
      for (size_t i : left) {
        if (!stop() && moveAlone(i, stop)) {
          atGoal_[i] = true, moved = true, ++stats_.moves;
        } else {
          still.push_back(i);
        }
      }
      left = std::move(still);
      stats_.totalSeconds = clock.seconds();
      if (progress) progress(stats_);
    }
    if (!left.empty() && !stop() && !shuffle(stop) && !stop() && !planJointly(left, true, stop) &&
        !stop())
      planJointly(left, false, stop);
  } catch (const Stopped&) {
  }
  stats_.totalSeconds = clock.seconds();
  const bool all = std::all_of(atGoal_.begin(), atGoal_.end(), [](bool b) { return b; });
  if (!all) {
    result.status = stop.cancelled() ? PlanStatus::Cancelled : PlanStatus::NotFound;
    result.stats = stats_;
    return result;
  }
  {
    const TimeCharge charge(stats_.certifySeconds);
    result.certificate = checkPath(scene_, checker_, path_);
  }
  result.status = result.certificate.ok ? PlanStatus::Found : PlanStatus::Uncertified;
  result.waypoints = std::move(path_);
  stats_.totalSeconds = clock.seconds();
  result.stats = stats_;
  return result;
}

}  // namespace mms
