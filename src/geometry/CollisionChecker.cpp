#include "geometry/CollisionChecker.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/BroadPhase.h"
#include "geometry/PolygonOps.h"
#include "geometry/Predicates.h"
#include "util/Number.h"

namespace mms {

std::string Contact::describe(const Scene& scene) const {
  switch (kind) {
    case Kind::None:
      return "nothing";
    case Kind::Bounds:
      return "the bounds";
    case Kind::Obstacle:
      return "obstacles[" + std::to_string(index) + "]";
    case Kind::Robot:
      return "robot '" + scene.robots[index].name + "'";
  }
  return "?";
}

ShrunkShape shrinkForContacts(const Ring& shape, double tolerance) {
  ShrinkResult r = shrinkRing(shape, tolerance);
  if (r.error) return {{}, r.error};
  auto tooSmall = [&](const std::string& why) {
    return ShrunkShape{{},
                       "a feature is smaller than the contact tolerance " +
                           formatNumber(tolerance) + " (" + why + ")"};
  };
  // Nearly parallel edges (e.g. a vertex off by 1e-320) put the shrunk vertex at infinity:
  // exact predicates must not see that.
  for (Vec2 v : r.ring)
    if (!std::isfinite(v.x) || !std::isfinite(v.y))
      return tooSmall("the shape shrunk by it degenerates");
  if (findSelfIntersection(r.ring)) return tooSmall("the shape shrunk by it is not simple");
  if (!isCounterClockwise(r.ring)) return tooSmall("the shape shrunk by it turns over");
  for (Vec2 v : r.ring)
    if (!insideRing(shape, v)) return tooSmall("the shape shrunk by it leaves the shape");
  return {std::move(r.ring), std::nullopt};
}

namespace {
std::atomic<uint64_t> nextShapesId{1};
}  // namespace

CollisionChecker::CollisionChecker(const Scene& scene)
    : bounds_(scene.bounds),
      tolerance_(scene.tolerance()),
      obstacles_(scene.obstacles),
      shapesId_(nextShapesId.fetch_add(1, std::memory_order_relaxed)) {
  for (size_t i = 0; i < obstacles_.size(); ++i) {
    const Disc* d = scene.obstacleDisc(i);
    obstacleDiscs_.push_back(d ? *d : Disc{});
    obstacleBoxes_.push_back(d ? discBox(*d) : boundingBox(obstacles_[i]));
  }
  for (const Robot& r : scene.robots) {
    if (r.disc > 0) {
      // Shrunk by the tolerance like a polygon; the inscribed ring is what NoPath's proofs
      // may assume the robot holds.
      const double shrunk = r.disc - tolerance_;
      if (!(shrunk > 0))
        throw std::invalid_argument("robot '" + r.name +
                                    "': its radius is not above the contact tolerance");
      discs_.push_back(shrunk);
      radii_.push_back(shrunk);
      holdsReference_.push_back(true);
      shapes_.push_back(discInscribed({{0, 0}, shrunk}, 2 * kDiscSides));
      continue;
    }
    ShrunkShape s = shrinkForContacts(r.shape, tolerance_);
    if (s.error) throw std::invalid_argument("robot '" + r.name + "': " + *s.error);
    discs_.push_back(0);
    radii_.push_back(mms::radius(s.ring));
    holdsReference_.push_back(insideRing(s.ring, {0, 0}));
    shapes_.push_back(std::move(s.ring));
  }
}

namespace {
// A placed robot or an obstacle: a ring or an exact disc, with its box.
struct Placed {
  const Ring* ring = nullptr;  // null for a disc
  Disc disc;
  Box box;
};

// Each robot's last placement, per thread (the checker is const and called from planner
// threads; the hot path must not allocate), for the checker whose shapes it holds.
struct PlacedRobot {
  Pose pose;
  bool valid = false;
  Ring ring;
  Placed placed;
  // The rotation of the last placement: robots that only translate keep their angle.
  double theta = std::numeric_limits<double>::quiet_NaN(), cos = 1, sin = 0;
};
struct PlacementCache {
  uint64_t shapes = 0;
  std::vector<PlacedRobot> robots;
};
// Two checkers, for planners that test a part of the scene and the whole in turn.
thread_local PlacementCache placements[2];
thread_local size_t lastPlacements = 0;

// Whether a disc's interior meets a closed polygon (touching discs are free: the robots were
// shrunk by the tolerance, so a disc contact is never closer than that to a real overlap).
bool discMeetsRing(const Disc& d, const Ring& ring) {
  return insideRing(ring, d.center) || distanceToEdges(ring, d.center) < d.radius;
}

// Whether two shapes whose boxes overlap meet.
bool shapesMeet(const Placed& a, const Placed& b) {
  if (a.ring && b.ring) return ringsIntersect(*a.ring, a.box, *b.ring, b.box);
  if (a.ring) return discMeetsRing(b.disc, *a.ring);
  if (b.ring) return discMeetsRing(a.disc, *b.ring);
  return norm(a.disc.center - b.disc.center) < a.disc.radius + b.disc.radius;
}

bool overlap(const Placed& a, const Placed& b) { return a.box.overlaps(b.box) && shapesMeet(a, b); }

// Distance between the two shapes, or `bound` when it is at least that.
double gap(const Placed& a, const Placed& b, double bound) {
  if (a.box.distance(b.box) >= bound) return bound;
  if (a.ring && b.ring) return ringDistance(*a.ring, a.box, *b.ring, b.box, bound);
  double d;
  if (a.ring || b.ring) {
    const Ring& ring = a.ring ? *a.ring : *b.ring;
    const Disc& disc = a.ring ? b.disc : a.disc;
    d = insideRing(ring, disc.center) ? 0 : distanceToEdges(ring, disc.center) - disc.radius;
  } else {
    d = norm(a.disc.center - b.disc.center) - a.disc.radius - b.disc.radius;
  }
  return std::min(bound, std::max(0.0, d));
}

// How far a disc of radius r about v (a point when r is 0) keeps inside the bounds, 0 when it
// does not.
double boundsGap(const Box& bounds, Vec2 v, double r) {
  const double d = std::min(std::min(v.x - bounds.xmin, bounds.xmax - v.x),
                            std::min(v.y - bounds.ymin, bounds.ymax - v.y)) -
                   r;
  return std::max(0.0, d);
}

Placed asPlaced(const Ring& ring, const Disc& disc, const Box& box) {
  return disc.radius > 0 ? Placed{nullptr, disc, box} : Placed{&ring, {}, box};
}

// The ring placed, and its box (`r.placed.box`), in one pass over the vertices.
void placeRing(const Ring& shape, const Pose& pose, PlacedRobot& r) {
  if (!(pose.theta == r.theta)) {
    const Transform rotation(pose);
    r.theta = pose.theta, r.cos = rotation.c, r.sin = rotation.s;
  }
  const Transform t(r.cos, r.sin, pose.x, pose.y);
  Ring& out = r.ring;
  Box& box = r.placed.box;
  out.resize(shape.size());
  box = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
         -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (size_t i = 0; i < shape.size(); ++i) {
    const Vec2 v = t(shape[i]);
    out[i] = v;
    box.xmin = std::min(box.xmin, v.x);
    box.ymin = std::min(box.ymin, v.y);
    box.xmax = std::max(box.xmax, v.x);
    box.ymax = std::max(box.ymax, v.y);
  }
}

// Robot `robot` of the checker with shapes `shapes` placed at `pose`: its last placement when
// the pose is the same (the reference stays valid until the next call for another checker).
const Placed& placeRobot(const CollisionChecker& checker, uint64_t shapes, size_t robot,
                         const Pose& pose) {
  PlacementCache* cache = &placements[lastPlacements];
  if (cache->shapes != shapes) {
    lastPlacements ^= 1;
    cache = &placements[lastPlacements];
    if (cache->shapes != shapes) {
      cache->shapes = shapes;
      cache->robots.resize(std::max(cache->robots.size(), checker.robotCount()));
      for (PlacedRobot& r : cache->robots) r.valid = false;
    }
  }
  PlacedRobot& r = cache->robots[robot];
  if (r.valid && r.pose.x == pose.x && r.pose.y == pose.y && r.pose.theta == pose.theta)
    return r.placed;
  r.pose = pose;
  r.valid = true;
  if (const double disc = checker.disc(robot); disc > 0) {
    const Disc d{{pose.x, pose.y}, disc};
    r.placed = {nullptr, d, discBox(d)};
  } else {
    r.placed.ring = &r.ring;
    placeRing(checker.shrunkShape(robot), pose, r);
  }
  return r.placed;
}

// Distance between the segment ab and a closed polygon (0 when they meet).
double segmentRingDistance(Vec2 a, Vec2 b, const Ring& ring, double bound) {
  if (insideRing(ring, a)) return 0;
  double d = bound;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size() && d > 0; j = i++)
    d = std::min(d, segmentSegmentDistance(a, b, ring[j], ring[i]));
  return d;
}
}  // namespace

namespace {
thread_local size_t tWork = 0;  // workOnThisThread()
}  // namespace

size_t CollisionChecker::workOnThisThread() { return tWork; }

Contact CollisionChecker::robotContact(size_t robot, const Pose& pose) const {
  ++tWork;
  const Placed& a = placeRobot(*this, shapesId_, robot, pose);
  // The bounds are convex, so the robot is inside them when its box is.
  if (!bounds_.contains(a.box)) return {Contact::Kind::Bounds, 0};
  for (size_t i = 0; i < obstacles_.size(); ++i)
    if (a.box.overlaps(obstacleBoxes_[i]) &&
        shapesMeet(a, asPlaced(obstacles_[i], obstacleDiscs_[i], obstacleBoxes_[i])))
      return {Contact::Kind::Obstacle, i};
  return {};
}

bool CollisionChecker::robotFree(size_t robot, const Pose& pose) const {
  return robotContact(robot, pose).kind == Contact::Kind::None;
}

bool CollisionChecker::referenceBlocked(size_t robot, const Pose& pose) const {
  if (!holdsReference_[robot]) return false;
  const Vec2 p{pose.x, pose.y};
  for (size_t i = 0; i < obstacles_.size(); ++i) {
    if (!obstacleBoxes_[i].contains(p)) continue;
    const Disc& d = obstacleDiscs_[i];
    if (d.radius > 0 ? norm(p - d.center) < d.radius : insideRing(obstacles_[i], p)) return true;
  }
  return false;
}

bool CollisionChecker::robotsDisjoint(size_t a, const Pose& pa, size_t b, const Pose& pb) const {
  ++tWork;
  return !overlap(placeRobot(*this, shapesId_, a, pa), placeRobot(*this, shapesId_, b, pb));
}

std::optional<std::pair<size_t, Contact>> CollisionChecker::firstContact(const Config& q) const {
  const size_t k = shapes_.size();
  for (size_t i = 0; i < k; ++i) {
    Contact c = robotContact(i, poseOf(q, i));
    if (c.kind != Contact::Kind::None) return std::pair(i, c);
  }
  if (k <= kAllPairsUpTo) {
    for (size_t i = 0; i < k; ++i)
      for (size_t j = i + 1; j < k; ++j)
        if (!robotsDisjoint(i, poseOf(q, i), j, poseOf(q, j)))
          return std::pair(i, Contact{Contact::Kind::Robot, j});
    return std::nullopt;
  }
  thread_local DiscSweep sweep;
  thread_local std::vector<Vec2> centres;
  centres.resize(k);
  for (size_t i = 0; i < k; ++i) centres[i] = {q[3 * i], q[3 * i + 1]};
  // Discs a tolerance apart or more hold shapes that cannot overlap.
  for (const auto& [i, j] :
       sweep.near(centres, radii_, tolerance_, [](size_t, size_t, double) { return true; }))
    if (!robotsDisjoint(i, poseOf(q, i), j, poseOf(q, j)))
      return std::pair(i, Contact{Contact::Kind::Robot, j});
  return std::nullopt;
}

bool CollisionChecker::isFree(const Config& q) const { return !firstContact(q).has_value(); }

CollisionChecker::Clearance CollisionChecker::robotClearance(size_t robot, const Pose& pose,
                                                             double bound) const {
  ++tWork;
  const Placed& a = placeRobot(*this, shapesId_, robot, pose);
  Clearance c{bound, {Contact::Kind::Bounds, 0}};
  if (a.ring)
    for (Vec2 v : *a.ring) c.distance = std::min(c.distance, boundsGap(bounds_, v, 0));
  else
    c.distance = std::min(c.distance, boundsGap(bounds_, a.disc.center, a.disc.radius));
  for (size_t i = 0; i < obstacles_.size() && c.distance > 0; ++i) {
    // Boxes that far apart are gap's answer too, without its square root (the margin keeps
    // borderline boxes to gap's own test).
    if (a.box.distance2(obstacleBoxes_[i]) > c.distance * c.distance * (1 + 1e-9)) continue;
    const double d =
        gap(a, asPlaced(obstacles_[i], obstacleDiscs_[i], obstacleBoxes_[i]), c.distance);
    if (d < c.distance) c = {d, {Contact::Kind::Obstacle, i}};
  }
  return c;
}

double CollisionChecker::robotsDistance(size_t a, const Pose& pa, size_t b, const Pose& pb,
                                        double bound) const {
  ++tWork;
  return gap(placeRobot(*this, shapesId_, a, pa), placeRobot(*this, shapesId_, b, pb), bound);
}

CollisionChecker::Clearance CollisionChecker::sweptDiscClearance(size_t robot, Vec2 a, Vec2 b,
                                                                 double bound) const {
  ++tWork;
  const double r = discs_[robot];
  Clearance c{bound, {Contact::Kind::Bounds, 0}};
  // The bounds are convex: the stadium is inside them when both end discs are.
  for (Vec2 v : {a, b}) c.distance = std::min(c.distance, boundsGap(bounds_, v, r));
  const Box swept{std::min(a.x, b.x) - r, std::min(a.y, b.y) - r, std::max(a.x, b.x) + r,
                  std::max(a.y, b.y) + r};
  for (size_t i = 0; i < obstacles_.size() && c.distance > 0; ++i) {
    if (swept.distance(obstacleBoxes_[i]) >= c.distance) continue;
    const Disc& o = obstacleDiscs_[i];
    const double d = o.radius > 0 ? pointSegmentDistance(o.center, a, b) - o.radius - r
                                  : segmentRingDistance(a, b, obstacles_[i], c.distance + r) - r;
    if (d < c.distance) c = {std::max(0.0, d), {Contact::Kind::Obstacle, i}};
  }
  return c;
}

double CollisionChecker::sweptDiscDistance(size_t i, Vec2 ai, Vec2 bi, size_t j, Vec2 aj, Vec2 bj,
                                           const Pose& pj) const {
  ++tWork;
  if (discs_[j] > 0)
    return std::max(0.0, pointSegmentDistance({0, 0}, ai - aj, bi - bj) - discs_[i] - discs_[j]);
  const Placed& held = placeRobot(*this, shapesId_, j, pj);
  return std::max(
      0.0,
      segmentRingDistance(ai, bi, *held.ring, std::numeric_limits<double>::infinity()) - discs_[i]);
}

}  // namespace mms
