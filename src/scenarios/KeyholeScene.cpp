// A key through a keyhole: turning in a chamber barely larger than its turning circle.
#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/PolygonOps.h"
#include "scenarios/Generators.h"

namespace mms {

namespace {

// The chamber's walls: the bounding box's rectangles around the rooms and slots, and the four
// corners cut off the chamber's square so that it is an octagon of inscribed radius a.
std::vector<Ring> keyholeWalls(double a, double slot, double ex, double ey, double thick,
                               double room, double wall) {
  const double right = a + thick + room, low = -a - thick - room, d = a * std::sqrt(2.0) - a;
  std::vector<Ring> walls{rect(-a - wall, a, right + wall, a + wall),  // top
                          rect(-a - wall, low - wall, -a, a),          // left
                          rect(-a, low - wall, right + wall, low),     // bottom
                          rect(-a, -a - thick, ex - slot / 2, -a),     // floor, left of the keyhole
                          rect(ex + slot / 2, -a - thick, a, -a),      // floor, right of it
                          rect(a, low, right + wall, -a),              // below the goal's room
                          rect(a, -a, a + thick, ey - slot / 2),       // side wall, below the exit
                          rect(a, ey + slot / 2, a + thick, a),        // side wall, above it
                          rect(right, -a, right + wall, a),            // right
                          {{a, d}, {a, a}, {d, a}},                    // the chamber's corners
                          {{-d, a}, {-a, a}, {-a, d}},
                          {{-a, -d}, {-a, -a}, {-d, -a}},
                          {{d, -a}, {a, -a}, {a, -d}}};
  return walls;
}

}  // namespace

Scene keyholeScene(uint64_t seed, double slack) {
  Random rng(seed);
  const double length = rng.uniform(1.4, 2.2), shaft = rng.uniform(0.14, 0.26);
  const double bow = shaft * rng.uniform(1.6, 2.4), bowLength = bow * rng.uniform(0.8, 1.2);
  const double drawn = rng.uniform(0.03, 0.12);  // drawn always: a given slack changes no other
  if (slack < 0) slack = drawn;
  const double h = length / 2;
  // The key along x, its bow at the left, its reference point the middle of its length.
  const Ring key{
      {-h, -bow / 2}, {-h + bowLength, -bow / 2},  {-h + bowLength, -shaft / 2}, {h, -shaft / 2},
      {h, shaft / 2}, {-h + bowLength, shaft / 2}, {-h + bowLength, bow / 2},    {-h, bow / 2}};
  // Its smallest turning circle: through the bow's outer corners and the shaft's tip, centred
  // on the axis at c (left of the reference point).
  const double c = (shaft * shaft - bow * bow) / (16 * h);
  const double turning = std::hypot(h + c, bow / 2);
  const double a = turning + slack;                      // the chamber's inscribed radius
  const double slot = bow * rng.uniform(1.04, 1.12);     // the keyhole and the exit
  const double thick = length * rng.uniform(0.25, 0.5);  // the walls the slots cross
  const double room = length + 0.4, wall = 0.3, d = a * std::sqrt(2.0) - a;
  // The slots open into the octagon's flat sides, anywhere along them.
  const double reach = std::max(0.0, d - slot / 2 - 0.02);
  const double ex = rng.uniform(-reach, reach), ey = rng.uniform(-reach, reach);
  Scene scene;
  scene.name = "keyhole-" + std::to_string(seed);
  scene.obstacles = keyholeWalls(a, slot, ex, ey, thick, room, wall);
  scene.bounds = {-a - wall, -a - thick - room - wall, a + thick + room + wall, a + wall};
  Robot k;
  k.name = "key";
  k.shape = key;
  // In the room below, upright (bow up or down); at the goal, in the room on the right, lying
  // (bow first or last): a quarter turn either way, made in the chamber.
  k.start = {ex, -a - thick - room / 2, rng.below(2) == 0 ? M_PI / 2 : -M_PI / 2};
  k.goal = {a + thick + room / 2, ey, rng.below(2) == 0 ? 0.0 : M_PI};
  // A quarter turn of the whole scene, and a mirror image.
  const double quarter = double(rng.below(4)) * M_PI / 2;
  const bool mirror = rng.below(2) == 1;
  auto place = [&](Vec2 v) {
    if (mirror) v.x = -v.x;
    return rotated(v, quarter);
  };
  auto placePose = [&](Pose p) {
    const Vec2 v = place({p.x, p.y});
    return Pose{v.x, v.y, std::remainder((mirror ? M_PI - p.theta : p.theta) + quarter, 2 * M_PI)};
  };
  for (Ring& o : scene.obstacles) {
    for (Vec2& v : o) v = place(v);
    if (signedArea2(o) < 0) o = Ring(o.rbegin(), o.rend());
  }
  if (mirror) {
    for (Vec2& v : k.shape) v.y = -v.y;  // the key mirrored in its own axis, as the scene is
    k.shape = Ring(k.shape.rbegin(), k.shape.rend());
  }
  k.start = placePose(k.start);
  k.goal = placePose(k.goal);
  const Vec2 lo = place({scene.bounds.xmin, scene.bounds.ymin}),
             hi = place({scene.bounds.xmax, scene.bounds.ymax});
  scene.bounds = {std::min(lo.x, hi.x), std::min(lo.y, hi.y), std::max(lo.x, hi.x),
                  std::max(lo.y, hi.y)};
  scene.robots = {k};
  return scene;
}

}  // namespace mms
