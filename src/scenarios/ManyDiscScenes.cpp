// Scenes of many discs, the kind discopygal's users bring: grids going to another grid, and
// discs among random triangles.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "geometry/PolygonOps.h"
#include "scenarios/Generators.h"

namespace mms {

Scene discGridScene(uint64_t seed, size_t count, double spacing) {
  Random rng(seed);
  const double r = 1;
  if (spacing <= 0) spacing = std::array<double, 3>{3, 5, 10}[rng.below(3)];
  spacing *= r;
  // A grid of cols x rows (an aspect from the seed), and the same grid moved along one of eight
  // directions, one to three spacings clear of it; each disc goes to its own place in the other
  // grid. The grids turn by an angle from the seed.
  const double aspect = rng.uniform(0.5, 2);
  const size_t cols = std::max<size_t>(1, size_t(std::ceil(std::sqrt(double(count) * aspect))));
  const size_t rows = (count + cols - 1) / cols;
  const int dir = int(rng.below(8));
  const double gap = spacing * double(1 + rng.below(3));
  const double w = spacing * double(cols - 1), h = spacing * double(rows - 1);
  constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1}, kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  const double dx = kDx[dir], dy = kDy[dir];
  const Vec2 shift{dx * (w + gap + spacing), dy * (h + gap + spacing)};
  const double turn = rng.uniform(0, 2 * M_PI);
  auto turned = [&](Vec2 p) { return rotated(p, turn); };
  Scene scene;
  scene.name = "disc-grid-";
  scene.name += std::to_string(count) + "-" + std::to_string(seed);
  std::vector<Vec2> ends;
  for (size_t i = 0; i < count; ++i) {
    const Vec2 at{spacing * double(i % cols), spacing * double(i / cols)};
    const Vec2 from = turned(at), to = turned(at + shift);
    scene.robots.push_back(exactDiscRobot(i, r, from, to));
    ends.push_back(from), ends.push_back(to);
  }
  // Room round both grids for a disc to pass: two spacings and a diameter.
  const Box b = boundingBox(ends);
  const double margin = 2 * spacing + 2 * r;
  scene.bounds = b.grown(margin);
  return scene;
}

namespace {

struct Round {
  Vec2 c;
  double radius;
};

// Triangles and the starts and goals in a square of side 2 half, or nothing when a start or goal
// finds no room (the caller tries a larger square).
bool placeDiscsAmongTriangles(Random& rng, size_t count, size_t triangles, double half,
                              Scene& scene, std::vector<Vec2>& places) {
  const double r = 1;
  std::vector<Round> kept;
  auto clear = [&](Vec2 c, double radius, double gap) {
    for (const Round& k : kept)
      if (norm(c - k.c) < radius + k.radius + gap) return false;
    return c.x - radius > -half + gap && c.x + radius < half - gap && c.y - radius > -half + gap &&
           c.y + radius < half - gap;
  };
  // Triangles inside circles kept a disc's diameter and more apart: the discs' free space among
  // them is one piece.
  for (size_t t = 0, attempts = 0; t < triangles && attempts < 100000; ++attempts) {
    const double size = rng.uniform(1.5, 4);
    const Vec2 c{rng.uniform(-half, half), rng.uniform(-half, half)};
    if (!clear(c, size, 2 * r + 0.2)) continue;
    const double a = rng.uniform(0, 2 * M_PI);
    Ring tri;
    for (int k = 0; k < 3; ++k) {
      const double b = a + 2 * M_PI * k / 3 + rng.uniform(-0.5, 0.5);
      tri.push_back({c.x + size * std::cos(b), c.y + size * std::sin(b)});
    }
    scene.obstacles.push_back(tri);
    kept.push_back({c, size});
    ++t;
  }
  // Starts and goals each in a free disc of twice the robot's radius holding no other start or
  // goal (the revolving areas of Agarwal et al.), so that an order of moves exists.
  for (size_t i = 0; i < 2 * count; ++i) {
    bool placed = false;
    for (int attempt = 0; attempt < 20000 && !placed; ++attempt) {
      const Vec2 c{rng.uniform(-half, half), rng.uniform(-half, half)};
      if (!clear(c, 2 * r, 0.05)) continue;
      bool apart = true;
      for (Vec2 p : places) apart = apart && norm(p - c) >= 4 * r + 0.05;
      if (!apart) continue;
      places.push_back(c);
      placed = true;
    }
    if (!placed) return false;
  }
  return true;
}

}  // namespace

Scene discTrianglesScene(uint64_t seed, size_t count) {
  Random rng(seed);
  // Density from the seed: the box holds count discs at 70-150 area per disc; a quarter to 0.85
  // of count triangles (10-17 for 20 discs). A square too crowded for the draws is grown by a
  // tenth until they fit.
  const double perDisc = rng.uniform(70, 150);
  double half = 0.5 * std::sqrt(perDisc * double(count));
  const size_t triangles =
      std::max<size_t>(1, size_t(std::lround(double(count) * rng.uniform(0.25, 0.85))));
  for (;; half *= 1.1) {
    Scene scene;
    scene.name = "disc-triangles-";
    scene.name += std::to_string(count) + "-" + std::to_string(seed);
    scene.bounds = {-half, -half, half, half};
    std::vector<Vec2> places;
    if (!placeDiscsAmongTriangles(rng, count, triangles, half, scene, places)) continue;
    for (size_t i = 0; i < count; ++i)
      scene.robots.push_back(exactDiscRobot(i, 1, places[2 * i], places[2 * i + 1]));
    return scene;
  }
}

Scene discBoxScene(uint64_t seed, size_t count) {
  Random rng(seed);
  constexpr double r = 0.5;
  // Cells of one diameter, two to a fifth more than the discs (at least two empty), in a box
  // of an aspect from the seed; discs touch their neighbours and the walls.
  const size_t holes = 2 + rng.below(std::max<size_t>(1, count / 5));
  const double aspect = rng.uniform(0.6, 1.6);
  const size_t cols =
      std::max<size_t>(2, size_t(std::ceil(std::sqrt(double(count + holes) * aspect))));
  const size_t rows = std::max<size_t>(2, (count + holes + cols - 1) / cols);
  const std::vector<size_t> starts = rng.sample(cols * rows, count),
                            goals = rng.sample(cols * rows, count);
  // The whole box turned by an angle from the seed: its walls are obstacles, the bounds the box
  // round them.
  const double turn = rng.uniform(0, 2 * M_PI);
  auto turned = [&](Vec2 p) { return rotated(p, turn); };
  auto centre = [&](size_t cell) {
    return turned({2 * r * (double(cell % cols) + 0.5), 2 * r * (double(cell / cols) + 0.5)});
  };
  Scene scene;
  scene.name = "disc-box-";
  scene.name += std::to_string(count) + "-" + std::to_string(seed);
  const double w = 2 * r * double(cols), h = 2 * r * double(rows), t = 2 * r;
  for (const Box& wall :
       {Box{-t, -t, w + t, 0}, Box{-t, h, w + t, h + t}, Box{-t, 0, 0, h}, Box{w, 0, w + t, h}})
    scene.obstacles.push_back({turned({wall.xmin, wall.ymin}), turned({wall.xmax, wall.ymin}),
                               turned({wall.xmax, wall.ymax}), turned({wall.xmin, wall.ymax})});
  std::vector<Vec2> corners;
  for (const Ring& o : scene.obstacles) corners.insert(corners.end(), o.begin(), o.end());
  scene.bounds = boundingBox(corners);
  for (size_t i = 0; i < count; ++i) {
    scene.robots.push_back(exactDiscRobot(i, r, centre(starts[i]), centre(goals[i])));
  }
  return scene;
}

}  // namespace mms
