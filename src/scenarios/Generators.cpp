#include "scenarios/Generators.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "geometry/PolygonOps.h"
#include "scenarios/Witness.h"

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
}  // namespace

Scene carryTurnScene(uint64_t seed, double playShare) {
  Random rng(seed);
  const double w = rng.uniform(0.8, 1.2), h = w * rng.uniform(0.7, 1.3);  // the part
  const double drawn = rng.uniform(0.04, 0.1);  // drawn always: a given play changes nothing else
  const double play = (playShare >= 0 ? playShare : drawn) * std::max(w, h);
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
    const Vec2 t = rotated(c, frame);
    lo = {std::min(lo.x, t.x), std::min(lo.y, t.y)};
    hi = {std::max(hi.x, t.x), std::max(hi.y, t.y)};
  }
  scene.bounds = {lo.x, lo.y, hi.x, hi.y};
  for (const Ring& r : {upper, lower}) {
    Ring t;
    for (const Vec2 p : r) t.push_back(rotated(p, frame));
    scene.obstacles.push_back(counterClockwise(t));
  }
  // The pair in the corridor, opening towards the chamber; at the goal, turned half round.
  const double along = rng.uniform(left + length / 2 + 0.1 * run, -mouth - length / 2 - 0.1 * run);
  const Vec2 centre = rotated({along, 0}, frame);
  auto pose = [&](double theta, Vec2 offset) {
    const Vec2 p = centre + rotated(offset, theta);
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

Ring rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

namespace {

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

Scene nicheSwapScene(uint64_t seed, double play) {
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
  auto extent = [](const Ring& r, double Vec2::*axis) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec2 v : r) lo = std::min(lo, v.*axis), hi = std::max(hi, v.*axis);
    return hi - lo;
  };
  // Room for either robot, not for both side by side.
  const double hA = extent(shapeA, &Vec2::y), hB = extent(shapeB, &Vec2::y);
  const double width = rng.uniform(1.1 * std::max(hA, hB), 0.95 * (hA + hB));
  const double length = size * rng.uniform(8, 14);
  // The niche fits the larger robot at angle 0 with `play` to spare in width and in depth: a
  // narrow passage of the 6-D space (one robot tucked in while the other passes).
  if (play < 0) play = rng.uniform(0.04, 0.1);
  const double nicheWidth =
      std::max(extent(shapeA, &Vec2::x), extent(shapeB, &Vec2::x)) + play * size;
  const double depth = std::max(hA, hB) + play * size;
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

Scene nicheThreeScene(uint64_t seed) {
  Random rng(seed);
  // Three rectangles, each too long to turn in the corridor, any two too tall to pass side by
  // side.
  struct Size {
    double length, height;
  };
  std::array<Size, 3> box;
  for (Size& b : box) b = {rng.uniform(0.8, 1.1), rng.uniform(0.45, 0.6)};
  std::array<double, 3> h{box[0].height, box[1].height, box[2].height};
  std::sort(h.begin(), h.end());
  const double width = rng.uniform(1.1 * h[2], 0.95 * (h[0] + h[1]));
  const double length = rng.uniform(8, 12);
  // The niche, in the upper wall, fits the largest robot with `play` to spare.
  const double play = rng.uniform(0.04, 0.1);
  double longest = 0;
  for (const Size& b : box) longest = std::max(longest, b.length);
  const double nicheWidth = longest + play, depth = h[2] + play;
  const double nicheMid = rng.uniform(3.5, length - 3.5);
  const double nx0 = nicheMid - nicheWidth / 2, nx1 = nicheMid + nicheWidth / 2;
  const double top = width + depth + 1;
  Scene scene;
  scene.name = "niche-three-" + std::to_string(seed);
  scene.bounds = {0, 0, length, top};
  scene.obstacles = {rect(0, width, nx0, top), rect(nx1, width, length, top),
                     rect(nx0, width + depth, nx1, top)};
  const char* names[3] = {"first", "second", "oncoming"};
  for (size_t i = 0; i < 3; ++i) {
    Robot r;
    r.name = names[i];
    r.shape = rect(-box[i].length / 2, -box[i].height / 2, box[i].length / 2, box[i].height / 2);
    scene.robots.push_back(std::move(r));
  }
  // Robots 0 and 1 go from the corridor's left end to its right end, keeping their order; robot
  // 2 the other way. Gaps of 0.1-0.3 between them and from the ends.
  auto gap = [&] { return rng.uniform(0.1, 0.3); };
  const double y = width / 2;
  const double a0 = gap() + box[0].length / 2,
               b0 = a0 + box[0].length / 2 + gap() + box[1].length / 2;
  const double b1 = length - gap() - box[1].length / 2;
  const double a1 = b1 - box[1].length / 2 - gap() - box[0].length / 2;
  const double c0 = length - gap() - box[2].length / 2, c1 = gap() + box[2].length / 2;
  scene.robots[0].start = {a0, y, 0};
  scene.robots[0].goal = {a1, y, 0};
  scene.robots[1].start = {b0, y, 0};
  scene.robots[1].goal = {b1, y, 0};
  scene.robots[2].start = {c0, y, 0};
  scene.robots[2].goal = {c1, y, 0};
  return scene;
}

namespace {
// The polygon's largest distance from its reference point (its circumscribed disc's radius).
double reach(const Ring& r) {
  double out = 0;
  for (const Vec2 v : r) out = std::max(out, std::hypot(v.x, v.y));
  return out;
}
// A convex polygon: `n` points on a circle at sorted random angles.
Ring randomConvex(Random& rng, Vec2 c, double radius, int n) {
  std::vector<double> a(static_cast<size_t>(n));
  for (double& x : a) x = rng.uniform(0, 2 * M_PI);
  std::sort(a.begin(), a.end());
  Ring r;
  for (const double t : a) r.push_back({c.x + radius * std::cos(t), c.y + radius * std::sin(t)});
  return r;
}
double area(const Ring& r) {
  double a = 0;
  for (size_t i = 0; i < r.size(); ++i) {
    const Vec2 p = r[i], q = r[(i + 1) % r.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return a / 2;
}
}  // namespace

Scene openClutterScene(uint64_t seed) {
  Random rng(seed);
  const double half = 10;
  Scene scene;
  scene.name = "open-clutter-" + std::to_string(seed);
  scene.bounds = {-half, -half, half, half};
  const int robots = 1 + int(rng.below(2));
  std::vector<Ring> shapes;
  for (int i = 0; i < robots; ++i) {
    const double arm1 = rng.uniform(1.0, 1.8), arm2 = rng.uniform(0.7, 1.4),
                 t = rng.uniform(0.25, 0.45);
    // An L about its corner's centre: one arm along x, one along y.
    const double cx = arm1 / 3, cy = arm2 / 3;
    shapes.push_back({{-cx, -cy},
                      {arm1 - cx, -cy},
                      {arm1 - cx, t - cy},
                      {t - cx, t - cy},
                      {t - cx, arm2 - cy},
                      {-cx, arm2 - cy}});
  }
  // Starts and goals first (discs kept clear), then the obstacles around them.
  struct Disc {
    Vec2 c;
    double r;
  };
  std::vector<Disc> kept;
  auto clear = [&](Vec2 c, double r) {
    for (const Disc& d : kept)
      if (std::hypot(c.x - d.c.x, c.y - d.c.y) < r + d.r) return false;
    return true;
  };
  auto placeOnEdge = [&](double x, double r) {
    for (int attempt = 0; attempt < 1000; ++attempt) {
      const Vec2 c{x, rng.uniform(-half + r + 0.5, half - r - 0.5)};
      if (clear(c, r)) return c;
    }
    return Vec2{x, 0};
  };
  for (int i = 0; i < robots; ++i) {
    Robot robot;
    robot.name = robots == 1 ? "robot" : std::string(1, char('a' + i));
    robot.shape = shapes[size_t(i)];
    const double r = reach(robot.shape) + 0.05, edge = half - r - 0.3;
    const Vec2 s = placeOnEdge(i == 0 ? -edge : edge, r);
    kept.push_back({s, r});
    const Vec2 g = placeOnEdge(i == 0 ? edge : -edge, r);
    kept.push_back({g, r});
    robot.start = {s.x, s.y, rng.uniform(-M_PI, M_PI)};
    robot.goal = {g.x, g.y, rng.uniform(-M_PI, M_PI)};
    scene.robots.push_back(robot);
  }
  const int count = 20 + int(rng.below(11));
  // Overlapping obstacles can wall a start or a goal in: draw them again (the stream goes on,
  // so a scene that passes at once is what it was before this check) until the grid witness
  // finds a way for the robots, one after the other. Every tenth failed draw places one
  // obstacle fewer, so the loop ends even where few draws would pass.
  for (int draw = 0;; ++draw) {
    scene.obstacles.clear();
    const int wanted = std::max(0, count - draw / 10);
    for (int k = 0, attempts = 0; k < wanted && attempts < 10000; ++attempts) {
      const double radius = rng.uniform(0.6, 1.6);
      const Vec2 c{rng.uniform(-half + radius, half - radius),
                   rng.uniform(-half + radius, half - radius)};
      if (!clear(c, radius)) continue;
      scene.obstacles.push_back(randomConvex(rng, c, radius, 3 + int(rng.below(5))));
      if (std::abs(area(scene.obstacles.back())) < 0.05 * radius * radius)
        scene.obstacles.pop_back();  // a sliver: draw again
      else
        ++k;
    }
    if (gridWitness(scene) || wanted == 0) return scene;
  }
}

// A disc robot's shape: the regular 16-gon whose inscribed circle is the disc (as discopygal's
// discs are imported, with fewer sides), about its centre.
Ring discShape(double radius) {
  constexpr int kSides = 16;
  const double R = radius / std::cos(M_PI / kSides);
  Ring r;
  for (int i = 0; i < kSides; ++i) {
    const double a = 2 * M_PI * i / kSides;
    r.push_back({R * std::cos(a), R * std::sin(a)});
  }
  return r;
}
Robot discRobot(size_t i, double radius, Vec2 start, Vec2 goal) {
  Robot r;
  r.name = "disc-" + std::to_string(i);
  r.motion = Motion::Translate;
  r.shape = discShape(radius);
  r.start = {start.x, start.y, 0};
  r.goal = {goal.x, goal.y, 0};
  return r;
}

Robot exactDiscRobot(size_t i, double radius, Vec2 start, Vec2 goal) {
  Robot r = discRobot(i, radius, start, goal);
  r.disc = radius;
  r.shape = discStandIn({{0, 0}, radius});
  return r;
}

namespace {
// n translating discs of radius r evenly round a circle of radius `ring` from a random phase,
// each going `shift` places round, to where another starts.
void addDiscsGoingRound(Scene& scene, Random& rng, size_t n, double r, double ring, size_t shift) {
  const double phase = rng.uniform(0, 2 * M_PI);
  auto place = [&](size_t i) {
    const double a = phase + 2 * M_PI * double(i) / double(n);
    return Vec2{ring * std::cos(a), ring * std::sin(a)};
  };
  for (size_t i = 0; i < n; ++i)
    scene.robots.push_back(discRobot(i, r, place(i), place((i + shift) % n)));
}
}  // namespace

Scene discsSwapScene(uint64_t seed) {
  Random rng(seed);
  const size_t n = 4 + rng.below(2);
  const double r = rng.uniform(0.4, 0.6);
  // A central block (a regular polygon), the discs on a ring around it, a square room around
  // that: the band between block and walls is 4.15-4.6 radii wide, so two discs pass each other
  // only just, and more easily in the room's corners.
  const int sides = 5 + int(rng.below(4));
  const double block = rng.uniform(1.5, 2.5), turn = rng.uniform(0, 2 * M_PI);
  const double band = r * rng.uniform(4.15, 4.6), inner = r * rng.uniform(0.1, 0.4);
  const double ring = block + inner + r, half = block + band;
  Scene scene;
  scene.name = "discs-swap-" + std::to_string(seed);
  scene.bounds = {-half, -half, half, half};
  Ring poly;
  for (int i = 0; i < sides; ++i) {
    const double a = turn + 2 * M_PI * i / sides;
    poly.push_back({block * std::cos(a), block * std::sin(a)});
  }
  scene.obstacles.push_back(poly);
  // Each disc goes `shift` places round the ring (to a place another disc starts at).
  const size_t shift = 1 + rng.below(n - 1);
  addDiscsGoingRound(scene, rng, n, r, ring, shift);
  return scene;
}

Scene roundRoomScene(uint64_t seed, size_t count) {
  Random rng(seed);
  const size_t n = count ? count : 3 + rng.below(3);
  // The room: a ring of 16-24 blocks whose inner faces are tangent to a circle of radius `room`
  // (the polygon's apothem). A disc centre within room - r of the middle clears every block.
  const int blocks = 16 + int(rng.below(9));
  const double room = 5, wall = rng.uniform(0.6, 1.2), turn = rng.uniform(0, 2 * M_PI);
  // The discs' places: on a circle as far out as leaves each a little play (0.02-0.3 radii) to
  // the wall, neighbours at least 1.1 diameters apart; a disc that must cross the middle may
  // find it too narrow to pass the others (the free centre's radius is 1.9-2.5 radii). More
  // than five discs get smaller so that they fit on the circle so far apart.
  const double fit = 1.1 / std::sin(M_PI / double(std::max<size_t>(n, 2)));
  const double r = std::min(room / rng.uniform(2.9, 3.5), room / (1.05 + fit));
  const double ring = std::max(room - r * (1 + rng.uniform(0.02, 0.3)), fit * r);
  Scene scene;
  scene.name = "round-room-" + std::to_string(seed);
  // The blocks' corners: on circles of the room's and the wall's circumradius.
  const double in = room / std::cos(M_PI / blocks), out = (room + wall) / std::cos(M_PI / blocks);
  scene.bounds = {-out - 0.1, -out - 0.1, out + 0.1, out + 0.1};
  for (int b = 0; b < blocks; ++b) {
    const double a0 = turn + 2 * M_PI * b / blocks, a1 = turn + 2 * M_PI * (b + 1) / blocks;
    scene.obstacles.push_back({{in * std::cos(a0), in * std::sin(a0)},
                               {in * std::cos(a1), in * std::sin(a1)},
                               {out * std::cos(a1), out * std::sin(a1)},
                               {out * std::cos(a0), out * std::sin(a0)}});
  }
  // Each disc goes `shift` places round (to where another starts); half round when n is even
  // with even odds, as in discopygal's four discs in a circular room.
  const size_t shift = (n % 2 == 0 && rng.uniform() < 0.5) ? n / 2 : 1 + rng.below(n - 1);
  addDiscsGoingRound(scene, rng, n, r, ring, shift);
  return scene;
}

Scene discsRoomScene(uint64_t seed, size_t count) {
  Random rng(seed);
  const double half = 1.6 * std::sqrt(double(count)) + 1;
  Scene scene;
  scene.name = "discs-room-" + std::to_string(seed);
  scene.bounds = {-half, -half, half, half};
  struct Disc {
    Vec2 c;
    double r;
  };
  std::vector<Disc> starts, goals;
  auto clear = [](const std::vector<Disc>& kept, Vec2 c, double r) {
    for (const Disc& d : kept)
      if (std::hypot(c.x - d.c.x, c.y - d.c.y) < r + d.r + 0.05) return false;
    return true;
  };
  auto place = [&](std::vector<Disc>& kept, double r) {
    for (int attempt = 0; attempt < 10000; ++attempt) {
      const Vec2 c{rng.uniform(-half + r + 0.05, half - r - 0.05),
                   rng.uniform(-half + r + 0.05, half - r - 0.05)};
      if (clear(kept, c, r)) {
        kept.push_back({c, r});
        return c;
      }
    }
    throw std::logic_error("discs-room: no room for the discs");
  };
  std::vector<double> radii(count);
  for (double& r : radii) r = rng.uniform(0.3, 0.5);
  for (size_t i = 0; i < count; ++i) {
    const Vec2 s = place(starts, radii[i]), g = place(goals, radii[i]);
    scene.robots.push_back(discRobot(i, radii[i], s, g));
  }
  // A few obstacles clear of every start and goal, and apart from each other and from the
  // walls by more than the widest disc: no disc is walled in, its free space among the
  // obstacles is one piece.
  std::vector<Disc> kept = starts;
  kept.insert(kept.end(), goals.begin(), goals.end());
  std::vector<Disc> placed;
  const double gap = 2 * 0.5 + 0.1;
  const int obstacles = 3 + int(rng.below(4));
  for (int k = 0, attempts = 0; k < obstacles && attempts < 10000; ++attempts) {
    const double radius = rng.uniform(0.5, 1.0);
    const double edge = half - radius - gap;
    if (edge <= 0) break;
    const Vec2 c{rng.uniform(-edge, edge), rng.uniform(-edge, edge)};
    if (!clear(kept, c, radius) || !clear(placed, c, radius + gap)) continue;
    scene.obstacles.push_back(randomConvex(rng, c, radius, 3 + int(rng.below(5))));
    if (std::abs(area(scene.obstacles.back())) < 0.05 * radius * radius) {
      scene.obstacles.pop_back();
    } else {
      kept.push_back({c, radius});
      placed.push_back({c, radius});
      ++k;
    }
  }
  return scene;
}

Scene bendScene(uint64_t seed) {
  Random rng(seed);
  const double w1 = rng.uniform(1.0, 1.6), w2 = rng.uniform(1.0, 1.6);
  const double thick = rng.uniform(0.08, 0.2);
  // The longest segment that turns from a corridor of width a into one of width b.
  auto ladder = [](double a, double b) {
    return std::pow(std::pow(a, 2.0 / 3) + std::pow(b, 2.0 / 3), 1.5);
  };
  const double length = rng.uniform(0.8, 0.95) * ladder(w1 - thick, w2 - thick);
  const double arm1 = length + rng.uniform(2, 5), arm2 = length + rng.uniform(2, 5);
  const double wall = 1;
  // Arm 1 runs along x from x = -arm1 to the corner [0, w2] x [0, w1]; arm 2 up along y.
  const double x0 = -arm1, x1 = w2, y0 = 0, y1 = w1 + arm2;
  Scene scene;
  scene.name = "bend-" + std::to_string(seed);
  scene.obstacles = {rect(x0 - wall, y0 - wall, x1 + wall, y0),  // floor of arm 1
                     rect(x1, y0, x1 + wall, y1),                // outer wall of arm 2
                     rect(x0 - wall, w1, 0, y1)};                // the inner block
  scene.bounds = {x0 - wall, y0 - wall, x1 + wall, y1};
  const double h = length / 2, t = thick / 2;
  Robot plank;
  plank.name = "plank";
  plank.shape = {{-h, -t}, {h, -t}, {h, t}, {-h, t}};
  plank.start = {x0 + h + 0.2, w1 / 2, 0};
  plank.goal = {w2 / 2, y1 - h - 0.2, M_PI / 2};
  // Which way it turns (mirror in y = x swaps the arms' roles) and a quarter turn of the whole.
  const bool mirror = rng.below(2) == 1;
  const double quarter = double(rng.below(4)) * M_PI / 2;
  auto place = [&](Vec2 v) { return rotated(mirror ? Vec2{v.y, v.x} : v, quarter); };
  for (Ring& o : scene.obstacles) {
    for (Vec2& v : o) v = place(v);
    o = counterClockwise(o);
  }
  auto placePose = [&](Pose p) {
    const Vec2 v = place({p.x, p.y});
    const double theta = (mirror ? M_PI / 2 - p.theta : p.theta) + quarter;
    return Pose{v.x, v.y, std::remainder(theta, 2 * M_PI)};
  };
  plank.start = placePose(plank.start);
  plank.goal = placePose(plank.goal);
  const Vec2 a = place({scene.bounds.xmin, scene.bounds.ymin}),
             b = place({scene.bounds.xmax, scene.bounds.ymax});
  scene.bounds = {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
  scene.robots = {plank};
  return scene;
}

Scene doorsScene(uint64_t seed) {
  Random rng(seed);
  // A long robot: a length x width rectangle with its corners cut at random.
  const double length = rng.uniform(1.5, 2.5), width = rng.uniform(0.3, 0.6);
  const double h = length / 2, t = width / 2;
  Ring shape;
  for (const Vec2 corner : {Vec2{-h, -t}, Vec2{h, -t}, Vec2{h, t}, Vec2{-h, t}}) {
    const double cut = rng.uniform(0, 0.4) * t;
    const Vec2 along{corner.x > 0 ? -1.0 : 1.0, 0}, across{0, corner.y > 0 ? -1.0 : 1.0};
    // Counter-clockwise: the vertex before the corner first.
    const bool xFirst = (corner.x > 0) == (corner.y > 0);
    const Vec2 a = corner + cut * (xFirst ? across : along),
               b = corner + cut * (xFirst ? along : across);
    if (cut < 0.01) {
      shape.push_back(corner);
    } else {
      shape.push_back(a);
      shape.push_back(b);
    }
  }
  const int walls = 1 + int(rng.below(3));
  const double room = length + rng.uniform(0.8, 1.5), thickness = 0.2;
  const double height = length + rng.uniform(1, 2.5), widthAll = walls * (room + thickness) + room;
  Scene scene;
  scene.name = "doors-" + std::to_string(seed);
  scene.bounds = {0, 0, widthAll, height};
  for (int k = 1; k <= walls; ++k) {
    const double x = k * room + (k - 1) * thickness;
    const double door = width * rng.uniform(1.05, 1.3);  // shorter than the robot is long
    const double y = rng.uniform(0.2, height - door - 0.2);
    scene.obstacles.push_back(rect(x, 0, x + thickness, y));
    scene.obstacles.push_back(rect(x, y + door, x + thickness, height));
  }
  Robot robot;
  robot.name = "bar";
  robot.shape = counterClockwise(shape);
  robot.start = {room / 2, height / 2, rng.uniform(-M_PI, M_PI)};
  robot.goal = {widthAll - room / 2, height / 2, rng.uniform(-M_PI, M_PI)};
  scene.robots = {robot};
  return scene;
}

}  // namespace mms
