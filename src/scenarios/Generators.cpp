#include "scenarios/Generators.h"

#include <cmath>
#include <cstdio>
#include <string>

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
    scene.obstacles.push_back(
        randomStarPolygon(rng, c, 0.12 * cell, 0.32 * cell, s.obstacleVertices));
  }
  // Grid corners lie between obstacles: free for robots this small.
  const double lo = -s.extent + cell, hi = s.extent - cell;
  const Vec2 starts[2] = {{lo, lo}, {hi, lo}}, goals[2] = {{hi, hi}, {lo, hi}};
  for (int i = 0; i < std::min(s.robots, 2); ++i) {
    Robot robot;
    robot.name = s.robots == 1 ? "robot" : std::string(1, char('a' + i));
    robot.shape = randomStarPolygon(rng, {0, 0}, 0.04 * cell, 0.12 * cell, s.robotVertices);
    robot.start = {starts[i].x, starts[i].y, rng.uniform(-M_PI, M_PI)};
    robot.goal = {goals[i].x, goals[i].y, rng.uniform(-M_PI, M_PI)};
    scene.robots.push_back(robot);
  }
  return scene;
}

Scene randomPolygonsTwoRobots(uint64_t seed) {
  RandomPolygonsSettings st;
  st.seed = seed;
  st.obstacles = 25;
  st.obstacleVertices = 8;
  st.robotVertices = 8;
  st.extent = 55;
  st.robots = 2;
  Scene s = randomPolygonsScene(st);
  s.name = "random-polygons";
  return s;
}

namespace {

Ring rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A ring of outer radius R and inner radius r with a slot of width w cut along +x: the
// Pacman. Counter-clockwise: the outer arc one way, the inner arc back.
Ring pacmanShape(double R, double r, double w, int nOuter, int nInner) {
  const double ao = std::asin(0.5 * w / R), ai = std::asin(0.5 * w / r);
  Ring c;
  for (int i = 0; i <= nOuter; ++i) {
    const double a = ao + (2 * M_PI - 2 * ao) * i / nOuter;
    c.push_back({R * std::cos(a), R * std::sin(a)});
  }
  for (int i = 0; i <= nInner; ++i) {
    const double a = 2 * M_PI - ai - (2 * M_PI - 2 * ai) * i / nInner;
    c.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return c;
}

}  // namespace

Scene pacmanScene(double tightness) {
  const double R = 2.0, r = 1.2, w = 1.6;  // outer, inner radius, mouth width
  const double s0 = 0.8, sMax = w;         // the square's side at tightness 0 and 1
  const double side = s0 + tightness * (sMax - s0);
  Scene scene;
  char name[64];
  std::snprintf(name, sizeof name, "pacman-%.3g", tightness);
  scene.name = name;
  scene.bounds = {-9, -2.15, 9, 2.15};  // a corridor the Pacman barely fits: nobody passes it
  Robot pac;
  pac.name = "pacman";
  pac.shape = pacmanShape(R, r, w, 40, 32);
  pac.start = {-5, 0, 0};
  pac.goal = {5, 0, 0};
  Robot sq;
  sq.name = "square";
  sq.shape = rect(-side / 2, -side / 2, side / 2, side / 2);
  sq.start = {5, 0, 0};
  sq.goal = {-5, 0, 0};
  scene.robots = {pac, sq};
  return scene;
}

Scene vikingHelmetScene() {
  Scene s;
  s.name = "viking-helmet";
  s.bounds = {0, 0, 20, 14};
  s.obstacles = {
      rect(0, 0, 20, 1),   rect(0, 0, 1, 14),       rect(19, 0, 20, 14),
      rect(0, 13, 20, 14),                                                  // shell
      rect(1, 5, 3.05, 9), rect(3.95, 5, 16.05, 9), rect(16.95, 5, 19, 9),  // passages
      rect(6, 9, 14, 13),                                                   // between the horns
      rect(8, 1, 12, 4),                                                    // pillar
  };
  Robot a, b;
  a.name = "left";
  a.shape = rect(-1, -0.25, 1, 0.25);
  a.start = {3.5, 11, 0};
  a.goal = {15, 2.5, 0};
  b.name = "right";
  b.shape = {{-1, -0.25}, {1, -0.25}, {1, 0.25}, {0, 0.1}, {-1, 0.25}};
  b.start = {16.5, 11, 0};
  b.goal = {5, 2.5, 0};
  s.robots = {a, b};
  return s;
}

}  // namespace mms
