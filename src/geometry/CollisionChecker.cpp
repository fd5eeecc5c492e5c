#include "geometry/CollisionChecker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/BroadPhase.h"
#include "geometry/PolygonOps.h"
#include "geometry/Predicates.h"

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
                           std::to_string(tolerance) + " (" + why + ")"};
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

CollisionChecker::CollisionChecker(const Scene& scene)
    : bounds_(scene.bounds), tolerance_(scene.tolerance()), obstacles_(scene.obstacles) {
  for (const Ring& o : obstacles_) obstacleBoxes_.push_back(boundingBox(o));
  for (const Robot& r : scene.robots) {
    ShrunkShape s = shrinkForContacts(r.shape, tolerance_);
    if (s.error) throw std::invalid_argument("robot '" + r.name + "': " + *s.error);
    radii_.push_back(mms::radius(s.ring));
    shapes_.push_back(std::move(s.ring));
  }
}

namespace {
// Scratch buffers for placed shapes: the checker is const and called from planner threads,
// and the hot path must not allocate.
thread_local Ring placedA, placedB;
}  // namespace

Contact CollisionChecker::robotContact(size_t robot, const Pose& pose) const {
  transformRing(shapes_[robot], pose, placedA);
  const Box box = boundingBox(placedA);
  // The bounds are convex, so the robot is inside them when its vertices are.
  if (!bounds_.contains(box)) return {Contact::Kind::Bounds, 0};
  for (size_t i = 0; i < obstacles_.size(); ++i)
    if (box.overlaps(obstacleBoxes_[i]) &&
        ringsIntersect(placedA, box, obstacles_[i], obstacleBoxes_[i]))
      return {Contact::Kind::Obstacle, i};
  return {};
}

bool CollisionChecker::robotFree(size_t robot, const Pose& pose) const {
  return robotContact(robot, pose).kind == Contact::Kind::None;
}

bool CollisionChecker::robotsDisjoint(size_t a, const Pose& pa, size_t b, const Pose& pb) const {
  transformRing(shapes_[a], pa, placedA);
  transformRing(shapes_[b], pb, placedB);
  return !ringsIntersect(placedA, boundingBox(placedA), placedB, boundingBox(placedB));
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
  transformRing(shapes_[robot], pose, placedA);
  const Box box = boundingBox(placedA);
  Clearance c{bound, {Contact::Kind::Bounds, 0}};
  for (Vec2 v : placedA) {
    const double d = std::min(std::min(v.x - bounds_.xmin, bounds_.xmax - v.x),
                              std::min(v.y - bounds_.ymin, bounds_.ymax - v.y));
    c.distance = std::min(c.distance, std::max(0.0, d));
  }
  for (size_t i = 0; i < obstacles_.size() && c.distance > 0; ++i) {
    if (box.distance(obstacleBoxes_[i]) >= c.distance) continue;
    const double d = ringDistance(placedA, box, obstacles_[i], obstacleBoxes_[i], c.distance);
    if (d < c.distance) c = {d, {Contact::Kind::Obstacle, i}};
  }
  return c;
}

double CollisionChecker::robotsDistance(size_t a, const Pose& pa, size_t b, const Pose& pb,
                                        double bound) const {
  transformRing(shapes_[a], pa, placedA);
  transformRing(shapes_[b], pb, placedB);
  return ringDistance(placedA, boundingBox(placedA), placedB, boundingBox(placedB), bound);
}

}  // namespace mms
