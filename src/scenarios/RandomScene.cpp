#include "scenarios/RandomScene.h"

#include <cmath>
#include <string>

#include "geometry/CollisionChecker.h"
#include "scenarios/Generators.h"
#include "util/Random.h"

namespace mms {

namespace {

// Grid scenes snap rectangles to a coarse lattice that includes the bounds, so edges coincide
// exactly (in doubles: lattice values are computed the same way everywhere).
struct Lattice {
  Box bounds;
  int n;
  double x(int i) const { return bounds.xmin + (bounds.xmax - bounds.xmin) * i / n; }
  double y(int j) const { return bounds.ymin + (bounds.ymax - bounds.ymin) * j / n; }
};

Ring latticeRectangle(Random& rng, const Lattice& g) {
  const int i = int(rng.below(g.n)), j = int(rng.below(g.n));
  const int w = 1 + int(rng.below(std::min(3, g.n - i))),
            h = 1 + int(rng.below(std::min(3, g.n - j)));
  return rect(g.x(i), g.y(j), g.x(i + w), g.y(j + h));
}

Ring robotShape(Random& rng, double size, bool box) {
  if (box) {
    const double w = size * rng.uniform(0.5, 1), h = size * rng.uniform(0.2, 1);
    return rect(-w / 2, -h / 2, w / 2, h / 2);
  }
  return randomStarPolygon(rng, {0, 0}, 0.3 * size / 2, size / 2, 3 + int(rng.below(8)));
}

// A free placement of robot `i` (clear of obstacles and of robots 0..i-1 at the same end), or
// false after `tries` draws.
bool placeRobot(Random& rng, const Scene& scene, const CollisionChecker& checker, size_t i,
                bool goal, int tries, Pose& out) {
  const Box& b = scene.bounds;
  const Robot& r = scene.robots[i];
  for (int t = 0; t < tries; ++t) {
    const Vec2 at = rng.uniformIn(b);
    Pose p{at.x, at.y, rng.uniform(-M_PI, M_PI)};
    if (r.motion == Motion::Translate && goal) p.theta = r.start.theta;
    if (!checker.robotFree(i, p)) continue;
    bool clear = true;
    for (size_t j = 0; j < i && clear; ++j)
      clear = checker.robotsDisjoint(i, p, j, goal ? scene.robots[j].goal : scene.robots[j].start);
    if (clear) {
      out = p;
      return true;
    }
  }
  return false;
}

}  // namespace

Scene randomScene(const RandomSceneSettings& s) {
  Random rng(s.seed);
  Scene scene;
  scene.name = "random-" + std::to_string(s.seed);
  const double w = rng.uniform(4, 60), h = w * rng.uniform(0.5, 2);
  const double x0 = rng.uniform(-w, 0), y0 = rng.uniform(-h, 0);
  scene.bounds = {x0, y0, x0 + w, y0 + h};
  const bool grid = rng.uniform() < 0.5;
  const int obstacles = s.obstacles >= 0 ? s.obstacles : int(rng.below(31));
  // A finer lattice when there are many rectangles, so they do not cover everything.
  const Lattice lattice{scene.bounds,
                        std::max(6 + int(rng.below(10)), int(2 * std::sqrt(double(obstacles))))};
  // Obstacles and robots shrink when there are many, so hundreds still leave room to move.
  const double crowding = std::min(1.0, std::sqrt(30.0 / std::max(1, obstacles)));
  for (int k = 0; k < obstacles; ++k) {
    if (grid) {
      scene.obstacles.push_back(latticeRectangle(rng, lattice));
    } else {
      // Anywhere, possibly overlapping each other or reaching past the bounds.
      const Vec2 c = rng.uniformIn(scene.bounds);
      // Smaller when there are many, so that hundreds still leave room to move.
      const double r = std::min(w, h) * rng.uniform(0.03, 0.15) * crowding;
      scene.obstacles.push_back(randomStarPolygon(rng, c, 0.3 * r, r, 3 + int(rng.below(10))));
    }
  }
  const int robots = s.robots > 0 ? s.robots : 1 + int(rng.below(2));
  // On grid scenes a box robot is sometimes exactly one lattice step wide: it fits the gaps
  // between lattice rectangles with zero clearance.
  const double step = std::min(w, h) / lattice.n;
  for (int i = 0; i < robots; ++i) {
    Robot r;
    r.name = robots == 1 ? "robot" : std::string(1, char('a' + i));
    r.motion = rng.uniform() < 0.3 ? Motion::Translate : Motion::Rigid;
    const bool exactFit = grid && rng.uniform() < 0.3;
    r.shape = exactFit ? rect(-step / 2, -step, step / 2, step)
                       : robotShape(rng, std::min(w, h) * rng.uniform(0.04, 0.25) * crowding,
                                    rng.uniform() < 0.4);
    scene.robots.push_back(r);
  }
  // Free ends for every robot; when the scene is too crowded for that, obstacles go, the last
  // tenth at a time.
  for (;;) {
    const CollisionChecker checker(scene);
    bool placed = true;
    for (size_t i = 0; i < scene.robots.size() && placed; ++i)
      placed = placeRobot(rng, scene, checker, i, false, 500, scene.robots[i].start) &&
               placeRobot(rng, scene, checker, i, true, 500, scene.robots[i].goal);
    if (placed || scene.obstacles.empty()) {
      if (placed) break;
      for (Robot& r : scene.robots)  // empty and still no room: the robots are too big
        for (Vec2& v : r.shape) v = {v.x / 2, v.y / 2};
      continue;
    }
    scene.obstacles.resize(scene.obstacles.size() -
                           std::max<size_t>(1, scene.obstacles.size() / 10));
  }
  return scene;
}

}  // namespace mms
