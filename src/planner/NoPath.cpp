#include "planner/NoPath.h"

#include <cmath>
#include <cstdio>

#include "geometry/Exact.h"
#include "geometry/PolygonOps.h"

namespace mms {

std::string goalCutOffAlone(const Slice& alone, const Robot& robot) {
  const int a = alone.locate({robot.start.x, robot.start.y}),
            b = alone.locate({robot.goal.x, robot.goal.y});
  if (a < 0 || b < 0 || a == b) return "";
  return "robot '" + robot.name +
         "' only translates, and its goal lies in another free region than its start among "
         "the obstacles alone";
}

std::string discCutOff(const Scene& scene, const CollisionChecker& checker, size_t robot,
                       const Pose& start, const Pose& goal) {
  const Disc disc = inscribedDisc(checker.shrunkShape(robot));
  // A tenth of the radius to spare: the disc strictly inside the checker's shape, so a free
  // robot leaves the polygon clear of every obstacle, rounding of its vertices included.
  const double r = 0.9 * disc.radius;
  if (!(r > 10 * checker.tolerance())) return "";
  constexpr int kSides = 16;
  Robot probe{"disc", {}, {}, {}, Motion::Translate};
  for (int k = 0; k < kSides; ++k) {
    const double a = 2 * M_PI * k / kSides;
    probe.shape.push_back({r * std::cos(a), r * std::sin(a)});
  }
  auto centre = [&](const Pose& p) {
    const Vec2 c = Transform(p)(disc.center);
    return Pose{c.x, c.y, 0};
  };
  probe.start = centre(start);
  probe.goal = centre(goal);
  Scene alone;
  alone.bounds = scene.bounds;
  alone.obstacles = scene.obstacles;
  alone.robots = {probe};
  const SliceWorld world(alone, 0);
  const Slice slice(world, exact::rationalAngleNear(0, 30));
  const int a = slice.locate({probe.start.x, probe.start.y}),
            b = slice.locate({probe.goal.x, probe.goal.y});
  if (a < 0 || b < 0 || a == b) return "";
  char radius[32];
  std::snprintf(radius, sizeof radius, "%.3g", r);
  return "robot '" + scene.robots[robot].name + "' cannot reach its goal: a disc of radius " +
         radius + " inside it cannot get from its start to its goal among the obstacles alone";
}

}  // namespace mms
