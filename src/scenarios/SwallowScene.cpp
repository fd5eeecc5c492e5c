// Swallow and turn: a U turns half round about a part it holds in its mouth, in a round bay
// barely larger than that turn. The U's reference point is the middle of its back, not the
// turning centre: neither a slice (fixed angle) nor a line (turning about the reference point)
// contains the turn.
#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/PolygonOps.h"
#include "scenarios/Generators.h"

namespace mms {

namespace {

// The part, centred on its reference point, inside the circle of radius r: a bar, a T or an L.
Ring partShape(Random& rng, double r) {
  const unsigned kind = unsigned(rng.below(3));
  const double t = r * rng.uniform(0.35, 0.6);  // the bar's or the strokes' thickness
  if (kind == 0) {
    const double h = std::sqrt(r * r - t * t / 4);
    return {{-h, -t / 2}, {h, -t / 2}, {h, t / 2}, {-h, t / 2}};
  }
  const double h = r / std::sqrt(2.0), s = t / 2;  // half the square the strokes fill
  if (kind == 1)  // a T: the top stroke across, the stem down the middle
    return {{-s, -h}, {s, -h}, {s, h - t}, {h, h - t}, {h, h}, {-h, h}, {-h, h - t}, {-s, h - t}};
  return {{-h, -h}, {h, -h}, {h, -h + t}, {-h + t, -h + t}, {-h + t, h}, {-h, h}};  // an L
}

// The walls above the corridor (|y| < half) and the bay (a regular n-gon of inscribed radius
// bay about the origin), from x = -end to end, up to y = top; the walls below are its mirror.
Ring upperWall(double half, double bay, unsigned n, double end, double top) {
  const double circum = bay / std::cos(M_PI / n);
  auto vertex = [&](unsigned i) {
    const double a = 2 * M_PI * (double(i) + 0.5) / n;  // no vertex on the corridor's axis
    return Vec2{circum * std::cos(a), circum * std::sin(a)};
  };
  // The bay's vertices above the corridor's wall, left to right, and where its edges cross
  // that wall (two: the n-gon is convex).
  std::vector<Vec2> arc, crossings;
  for (unsigned i = 0; i < n; ++i) {
    const Vec2 a = vertex(i), b = vertex((i + 1) % n);
    if (a.y > half) arc.push_back(a);
    if ((a.y > half) != (b.y > half))
      crossings.push_back({a.x + (half - a.y) / (b.y - a.y) * (b.x - a.x), half});
  }
  std::sort(arc.begin(), arc.end(), [](Vec2 a, Vec2 b) { return a.x < b.x; });
  std::sort(crossings.begin(), crossings.end(), [](Vec2 a, Vec2 b) { return a.x < b.x; });
  Ring wall{{-end, half}, crossings.front()};
  wall.insert(wall.end(), arc.begin(), arc.end());
  wall.push_back(crossings.back());
  wall.push_back({end, half});
  wall.push_back({end, top});
  wall.push_back({-end, top});
  // The arc runs left to right over the bay: the wall lies above its lower edge, clockwise;
  // counter-clockwise as scenes have it.
  if (signedArea2(wall) < 0) wall = Ring(wall.rbegin(), wall.rend());
  return wall;
}

}  // namespace

Scene swallowScene(uint64_t seed, double slack, bool partMoves) {
  Random rng(seed);
  const double r = rng.uniform(0.3, 0.5);  // the part's circle
  const double play = r * rng.uniform(0.04, 0.12), arm = rng.uniform(0.12, 0.25),
               back = rng.uniform(0.12, 0.25), reach = r * rng.uniform(0.2, 1.0);
  const double drawn = rng.uniform(0.03, 0.12);  // drawn always: a given slack changes no other
  if (slack < 0) slack = drawn;
  const unsigned sides = 16 + 2 * unsigned(rng.below(5));
  const Ring part = partShape(rng, r);
  // The U about its turning centre (the part's centre): the mouth open towards +x, a circle of
  // radius r + play free inside it, the arms reaching `reach` past that circle.
  const double in = r + play, x0 = -in - back, x1 = in + reach, y1 = in + arm;
  Ring u{{x0, -y1}, {x1, -y1}, {x1, -in}, {-in, -in}, {-in, in}, {x1, in}, {x1, y1}, {x0, y1}};
  double turn = 0;  // the turning circle about the part's centre
  for (const Vec2& v : u) turn = std::max(turn, std::hypot(v.x, v.y));
  const double refX = x0 + back / 2;  // the reference point: the middle of the U's back
  for (Vec2& v : u) v.x -= refX;
  const double bay = turn + slack, half = y1 * (1 + rng.uniform(0.03, 0.08));
  const double length = x1 - x0, along = bay + length + 0.3, wall = 0.3;
  const double top = bay / std::cos(M_PI / sides) + wall;
  Scene scene;
  scene.name = "swallow-" + std::to_string(seed);
  Ring upper = upperWall(half, bay, sides, along, top), lower = upper;
  for (Vec2& v : lower) v.y = -v.y;
  lower = Ring(lower.rbegin(), lower.rend());
  scene.obstacles = {upper,
                     lower,
                     {{-along - wall, -top}, {-along, -top}, {-along, top}, {-along - wall, top}},
                     {{along, -top}, {along + wall, -top}, {along + wall, top}, {along, top}}};
  scene.bounds = {-along - wall, -top, along + wall, top};
  // The part, fixed at the bay's centre at a random angle.
  const double angle = rng.uniform(-M_PI, M_PI);
  Ring placed;
  for (const Vec2& v : part)
    placed.push_back({v.x * std::cos(angle) - v.y * std::sin(angle),
                      v.x * std::sin(angle) + v.y * std::cos(angle)});
  if (!partMoves) scene.obstacles.push_back(placed);
  // The U waits in the corridor on the left, mouth first, and ends in the one on the right, mouth
  // last: half a turn, made in the bay about the part.
  const double clear = bay + 0.1;
  const double sense = rng.below(2) == 0 ? 1 : -1;
  Robot gripper;
  gripper.name = "u";
  gripper.shape = u;
  gripper.start = {-clear - x1 + refX, 0, 0};
  gripper.goal = {clear + x1 - refX, 0, sense * M_PI};
  // A quarter turn of the whole scene.
  const double quarter = double(rng.below(4)) * M_PI / 2;
  auto place = [&](Vec2 v) { return rotated(v, quarter); };
  auto placePose = [&](Pose p) {
    const Vec2 v = place({p.x, p.y});
    return Pose{v.x, v.y, std::remainder(p.theta + quarter, 2 * M_PI)};
  };
  for (Ring& o : scene.obstacles)
    for (Vec2& v : o) v = place(v);
  const Vec2 lo = place({scene.bounds.xmin, scene.bounds.ymin}),
             hi = place({scene.bounds.xmax, scene.bounds.ymax});
  scene.bounds = {std::min(lo.x, hi.x), std::min(lo.y, hi.y), std::max(lo.x, hi.x),
                  std::max(lo.y, hi.y)};
  gripper.start = placePose(gripper.start);
  gripper.goal = placePose(gripper.goal);
  scene.robots = {gripper};
  if (partMoves) {
    // The part is a robot too: it waits at the bay's centre while the U turns about it, then
    // leaves for the corridor the U came from (at its own angle, which the corridor allows).
    scene.name = "swallow-two-" + std::to_string(seed);
    Robot held;
    held.name = "part";
    held.shape = part;
    held.start = placePose({0, 0, angle});
    held.goal = placePose({-clear - r, 0, angle});
    scene.robots.push_back(held);
  }
  return scene;
}

std::vector<Config> swallowWitness(const Scene& scene) {
  const Robot& u = scene.robots.at(0);
  // The turning centre in the U's frame: on its axis, as far in front of the reference point as
  // the mouth's back wall (vertex 3) lies plus the half width of the mouth.
  const double k = u.shape.at(3).x - u.shape.at(3).y;
  // The part and the bay are centred on the origin (the whole was turned about it).
  const double theta0 = u.start.theta;
  const double sense = std::remainder(u.goal.theta - theta0, 2 * M_PI) > 0 ? 1 : -1;
  std::vector<Config> w{{u.start.x, u.start.y, theta0}};
  const int steps = 180;  // chords of the turn: 2e-5 of the radius off the circle
  for (int i = 0; i <= steps; ++i) {
    const double theta = theta0 + sense * M_PI * i / steps;
    w.push_back({-k * std::cos(theta), -k * std::sin(theta), theta});
  }
  w.push_back({u.goal.x, u.goal.y, theta0 + sense * M_PI});
  return w;
}

}  // namespace mms
