#include "scenarios/Generators.h"

#include <algorithm>
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

namespace {
Ring counterClockwise(Ring r) {
  double a = 0;
  for (size_t i = 0; i < r.size(); ++i) {
    const Vec2 p = r[i], q = r[(i + 1) % r.size()];
    a += p.x * q.y - q.x * p.y;
  }
  if (a < 0) std::reverse(r.begin(), r.end());
  return r;
}
Vec2 turned(Vec2 p, double a) {
  return {p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a)};
}
}  // namespace

Scene carryTurnScene(uint64_t seed) {
  Random rng(seed);
  const double w = rng.uniform(0.8, 1.2), h = w * rng.uniform(0.7, 1.3);  // the part
  const double play = rng.uniform(0.04, 0.1) * std::max(w, h);
  const double wall = rng.uniform(0.2, 0.35) * std::max(w, h);  // the gripper's walls
  // The pair in the gripper's frame, centred on its bounding box: back wall at the left, the
  // pocket open to the right, the part in the pocket with the play all round.
  const double length = wall + w + play, height = h + 2 * play + 2 * wall;
  const double x0 = -length / 2, x1 = length / 2, y0 = -height / 2, y1 = height / 2;
  const double inner = h / 2 + play, back = x0 + wall;
  const Ring gripper{{x0, y0},      {x1, y0},    {x1, -inner}, {back, -inner},
                     {back, inner}, {x1, inner}, {x1, y1},     {x0, y1}};
  const Ring part{{-w / 2, -h / 2}, {w / 2, -h / 2}, {w / 2, h / 2}, {-w / 2, h / 2}};
  const double deepest = back + w / 2;  // the part's centre against the pocket's back
  // The chamber: a polygonal circle whose inscribed circle clears the pair's circumscribed one
  // by 2-8 %. The corridor: the pair's height plus 5-15 %, 1.5-3 pair lengths long.
  const int arcSides = 96;
  const double circum = std::hypot(length / 2, height / 2);
  const double chamber = circum * rng.uniform(1.02, 1.08) / std::cos(M_PI / arcSides);
  const double corridor = height * rng.uniform(1.05, 1.15);
  const double run = length * rng.uniform(1.5, 3.0);
  const double mouth = std::sqrt(chamber * chamber - corridor * corridor / 4);
  const double left = -(mouth + run), margin = 0.5 * height, top = chamber + margin;
  // Upper wall (corridor's upper side, the chamber's upper half, half the dead end's cap);
  // the lower wall is its mirror image.
  Ring upper{{left, 0}, {left, corridor / 2}};
  const double from = M_PI - std::asin(corridor / 2 / chamber);
  const int steps = int(std::ceil(from / (2 * M_PI / arcSides)));
  for (int i = 0; i <= steps; ++i) {
    const double a = from * (1 - double(i) / steps);
    upper.push_back({chamber * std::cos(a), chamber * std::sin(a)});
  }
  upper.push_back({chamber + margin, 0});
  upper.push_back({chamber + margin, top});
  upper.push_back({left - margin, top});
  upper.push_back({left - margin, 0});
  Ring lower;
  for (auto it = upper.rbegin(); it != upper.rend(); ++it) lower.push_back({it->x, -it->y});
  // A quarter turn of the whole scene, and the direction of the pair's turn.
  const double frame = M_PI / 2 * double(rng.below(4));
  const double turn = rng.uniform() < 0.5 ? M_PI : -M_PI;
  Scene scene;
  scene.name = "carry-turn-" + std::to_string(seed);
  Box box{left - margin, -top, chamber + margin, top};
  Vec2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  for (const Vec2 c : {Vec2{box.xmin, box.ymin}, Vec2{box.xmax, box.ymax}}) {
    const Vec2 t = turned(c, frame);
    lo = {std::min(lo.x, t.x), std::min(lo.y, t.y)};
    hi = {std::max(hi.x, t.x), std::max(hi.y, t.y)};
  }
  scene.bounds = {lo.x, lo.y, hi.x, hi.y};
  for (const Ring& r : {upper, lower}) {
    Ring t;
    for (const Vec2 p : r) t.push_back(turned(p, frame));
    scene.obstacles.push_back(counterClockwise(t));
  }
  // The pair in the corridor, opening towards the chamber; at the goal, turned half round.
  const double along = rng.uniform(left + length / 2 + 0.1 * run, -mouth - length / 2 - 0.1 * run);
  const Vec2 centre = turned({along, 0}, frame);
  auto pose = [&](double theta, Vec2 offset) {
    const Vec2 p = centre + turned(offset, theta);
    return Pose{p.x, p.y, std::remainder(theta, 2 * M_PI)};
  };
  // The part anywhere in the pocket's play, at the start and (independently) at the goal: the
  // gripper may have to regrip.
  auto inPocket = [&] {
    return Vec2{deepest + rng.uniform(0.15, 0.85) * play, rng.uniform(-0.85, 0.85) * play};
  };
  const Vec2 startHold = inPocket(), goalHold = inPocket();
  Robot g, p;
  g.name = "gripper";
  g.shape = counterClockwise(gripper);
  g.start = pose(frame, {0, 0});
  g.goal = pose(frame + turn, {0, 0});
  p.name = "part";
  p.shape = part;
  p.start = pose(frame, startHold);
  p.goal = pose(frame + turn, goalHold);
  scene.robots = {g, p};
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

Scene nicheSwapScene(uint64_t seed) {
  Random rng(seed);
  const double size = 1;
  // Blocky shapes: a vertex near each corner of the size x size box, one more on a random side;
  // each fits the corridor at angle 0, two side by side do not.
  auto blocky = [&] {
    const double h = size / 2, j = 0.15 * size;
    Ring r{{-h + rng.uniform(0, j), -h + rng.uniform(0, j)},
           {h - rng.uniform(0, j), -h + rng.uniform(0, j)},
           {h - rng.uniform(0, j), h - rng.uniform(0, j)},
           {-h + rng.uniform(0, j), h - rng.uniform(0, j)}};
    const size_t side = rng.below(4);
    const Vec2 a = r[side], b = r[(side + 1) % 4], mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
    const Vec2 inward{-mid.x, -mid.y};  // towards the centre: keeps the ring simple
    r.insert(r.begin() + long(side) + 1, mid + rng.uniform(0, 0.3) * inward);
    return r;
  };
  const Ring shapeA = blocky(), shapeB = blocky();
  auto height = [](const Ring& r) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec2 v : r) lo = std::min(lo, v.y), hi = std::max(hi, v.y);
    return hi - lo;
  };
  // Room for either robot, not for both side by side.
  const double hA = height(shapeA), hB = height(shapeB);
  const double width = rng.uniform(1.1 * std::max(hA, hB), 0.95 * (hA + hB));
  const double length = size * rng.uniform(8, 14);
  const double nicheWidth = size * rng.uniform(1.2, 1.6), depth = size * rng.uniform(1.2, 1.8);
  const double nicheX = rng.uniform(0.3, 0.7) * length - nicheWidth / 2;
  const double wall = size;
  Scene scene;
  scene.name = "niche-swap-" + std::to_string(seed);
  scene.bounds = {0, 0, length, width + depth + wall};
  scene.obstacles = {rect(0, width, nicheX, width + depth + wall),
                     rect(nicheX + nicheWidth, width, length, width + depth + wall),
                     rect(nicheX, width + depth, nicheX + nicheWidth, width + depth + wall)};
  const double y = width / 2, margin = 0.6 * size;
  Robot a, b;
  a.name = "left";
  a.shape = shapeA;
  a.start = {margin, y, 0};
  a.goal = {length - margin, y, 0};
  b.name = "right";
  b.shape = shapeB;
  b.start = {length - margin, y, 0};
  b.goal = {margin, y, 0};
  scene.robots = {a, b};
  return scene;
}

}  // namespace mms
