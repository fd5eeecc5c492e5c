#include "scene/Generators.h"

#include <cmath>

namespace mms {

Ring randomStarPolygon(Random& rng, Vec2 center, double rmin, double rmax, int n) {
  Ring r;
  const double step = 2 * M_PI / n;
  for (int i = 0; i < n; ++i) {
    // Jitter the angle within its sector so consecutive vertices stay ordered.
    const double a = (i + rng.uniform(0.1, 0.9)) * step;
    const double rad = rng.uniform(rmin, rmax);
    r.push_back({center.x + rad * std::cos(a), center.y + rad * std::sin(a)});
  }
  return r;
}

Scene randomPolygonsScene(const RandomPolygonsSettings& s) {
  Random rng(s.seed);
  Scene scene;
  scene.name = "random-polygons-" + std::to_string(s.seed);
  scene.bounds = {-s.extent, -s.extent, s.extent, s.extent};
  // Obstacles on a jittered grid so they leave corridors between them.
  const int side = int(std::ceil(std::sqrt(double(s.obstacles))));
  const double cell = 2 * s.extent / side;
  for (int k = 0; k < s.obstacles; ++k) {
    const Vec2 c{-s.extent + (k % side + 0.5) * cell + rng.uniform(-0.1, 0.1) * cell,
                 -s.extent + (k / side + 0.5) * cell + rng.uniform(-0.1, 0.1) * cell};
    scene.obstacles.push_back(randomStarPolygon(rng, c, 0.12 * cell, 0.32 * cell, s.obstacleVertices));
  }
  Robot robot;
  robot.name = "robot";
  robot.shape = randomStarPolygon(rng, {0, 0}, 0.04 * cell, 0.12 * cell, s.robotVertices);
  // Grid corners lie between obstacles: free for a robot this small.
  robot.start = {-s.extent + cell, -s.extent + cell, rng.uniform(-M_PI, M_PI)};
  robot.goal = {s.extent - cell, s.extent - cell, rng.uniform(-M_PI, M_PI)};
  scene.robots.push_back(robot);
  return scene;
}

}  // namespace mms
