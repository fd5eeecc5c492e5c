#include "planner/NoPath.h"

#include <cmath>
#include <cstdio>

#include "geometry/Exact.h"
#include "geometry/PolygonOps.h"

namespace mms {

namespace {

// Whether `probe` (robot frame, translating at angle `theta`) has its positions `from` and `to`
// in different cells of its exact free space among the obstacles alone.
bool apartAlone(const Scene& scene, Ring probe, double theta, Vec2 from, Vec2 to) {
  Scene alone;
  alone.bounds = scene.bounds;
  // Disc obstacles as polygons inside them: the proof may only ever take less room than the
  // scene's obstacles do.
  alone.obstacles = scene.obstacles;
  for (size_t i = 0; i < alone.obstacles.size(); ++i)
    if (const Disc* d = scene.obstacleDisc(i)) alone.obstacles[i] = discInscribed(*d);
  alone.robots = {
      {"probe", std::move(probe), {from.x, from.y, theta}, {to.x, to.y, theta}, Motion::Translate}};
  const SliceWorld world(alone, 0);
  const Slice slice(world, exact::rationalAngleNear(theta, 30));
  const int a = slice.locate(from), b = slice.locate(to);
  return a >= 0 && b >= 0 && a != b;
}

// Whether `inner` lies inside `outer` with at least `margin` to spare (both in the robot frame).
bool insideWithMargin(const Ring& inner, const Ring& outer, double margin) {
  for (size_t i = 0, j = inner.size() - 1; i < inner.size(); j = i++) {
    if (!insideRing(outer, inner[i])) return false;
    for (size_t k = 0, l = outer.size() - 1; k < outer.size(); l = k++)
      if (pointSegmentDistance(inner[i], outer[l], outer[k]) < margin ||
          segmentsIntersect(inner[j], inner[i], outer[l], outer[k]))
        return false;
  }
  return true;
}

std::string translatingCutOff(const Scene& scene, const CollisionChecker& checker, size_t robot,
                              const Pose& start, const Pose& goal) {
  const double delta = checker.tolerance();
  const Robot& r = scene.robots[robot];
  // A disc robot's probe lies inside its disc shrunk by 2 delta by construction.
  const ShrunkShape probe = r.disc > 0
                                ? ShrunkShape{discInscribed({{0, 0}, r.disc - 2 * delta}), {}}
                                : shrinkForContacts(r.shape, 2 * delta);
  // The slice turns the probe by a rational angle within 2^-30 of the robot's: far less than the
  // margin on any scene whose robots are smaller than a thousand times its extent.
  if (probe.error || radius(probe.ring) * 0x1p-28 > delta / 4 ||
      (r.disc == 0 && !insideWithMargin(probe.ring, checker.shrunkShape(robot), delta / 4)))
    return "";
  if (!apartAlone(scene, probe.ring, start.theta, {start.x, start.y}, {goal.x, goal.y})) return "";
  return "robot '" + scene.robots[robot].name +
         "' only translates, and its goal lies in another free region than its start among "
         "the obstacles alone";
}

std::string rigidCutOff(const Scene& scene, const CollisionChecker& checker, size_t robot,
                        const Pose& start, const Pose& goal) {
  const Disc disc = inscribedDisc(checker.shrunkShape(robot));
  const double r = 0.9 * disc.radius;
  if (!(r > 10 * checker.tolerance())) return "";
  constexpr int kSides = 16;
  Ring probe;
  for (int k = 0; k < kSides; ++k) {
    const double a = 2 * M_PI * k / kSides;
    probe.push_back({r * std::cos(a), r * std::sin(a)});
  }
  const Vec2 from = Transform(start)(disc.center), to = Transform(goal)(disc.center);
  // At angle 0 the slice's rotation is exactly the identity.
  if (!apartAlone(scene, probe, 0, from, to)) return "";
  char radiusText[32];
  std::snprintf(radiusText, sizeof radiusText, "%.3g", r);
  return "robot '" + scene.robots[robot].name + "' cannot reach its goal: a disc of radius " +
         radiusText + " inside it cannot get from its start to its goal among the obstacles alone";
}

}  // namespace

bool apartIn(const Slice& alone, const Robot& robot) {
  const int a = alone.locate({robot.start.x, robot.start.y}),
            b = alone.locate({robot.goal.x, robot.goal.y});
  return a >= 0 && b >= 0 && a != b;
}

std::string noPathAlone(const Scene& scene, const CollisionChecker& checker, size_t robot,
                        const Pose& start, const Pose& goal) {
  return scene.robots[robot].motion == Motion::Translate
             ? translatingCutOff(scene, checker, robot, start, goal)
             : rigidCutOff(scene, checker, robot, start, goal);
}

std::string noPathOfAny(const Scene& scene, const CollisionChecker& checker,
                        const std::function<bool(size_t robot)>& asks) {
  for (size_t r = 0; r < scene.robots.size(); ++r)
    if (asks(r)) {
      std::string why = noPathAlone(scene, checker, r, scene.robots[r].start, scene.robots[r].goal);
      if (!why.empty()) return why;
    }
  return "";
}

}  // namespace mms
