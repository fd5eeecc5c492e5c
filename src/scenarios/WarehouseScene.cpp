// Rigid rectangles in a warehouse: rows of shelves, aisles between them and cross-aisles
// through them; carts that park along one side of the aisles (lengthwise) and of the
// cross-aisles (crosswise), so that another passes them, and a cart going from one to the other
// turns where there is room.
#include <algorithm>
#include <cmath>
#include <string>

#include "scenarios/Generators.h"

namespace mms {

namespace {

struct Slot {
  Vec2 at;
  double theta;
};

}  // namespace

Scene warehouseScene(uint64_t seed, size_t count) {
  Random rng(seed);
  // The cart, and aisles that a cart drives along past a parked one but cannot turn in.
  const double len = rng.uniform(1.2, 1.8), wid = len * rng.uniform(0.35, 0.42);
  const double aisle = 2 * wid + len * rng.uniform(0.1, 0.2);
  const double cross = std::hypot(len, wid) * rng.uniform(1.1, 1.4);  // a cart turns here
  const double gap = 0.02 * len;  // between a parked cart and the shelf it parks along
  const double depth = rng.uniform(0.8, 1.4), pitch = 1.3 * len;
  const size_t segments = 2 + rng.below(2);
  const size_t perShelf = 3 + rng.below(3);  // parking places along one shelf
  const double shelf = pitch * double(perShelf);
  // Rows enough for the carts' starts and goals with places to spare.
  const size_t perAisle = segments * perShelf;
  size_t rows = 2;
  while ((rows + 1) * perAisle + (rows * (segments + 1)) < 2 * count + 4) ++rows;
  const double width = cross + double(segments) * (shelf + cross);
  const double height = aisle + double(rows) * (depth + aisle);
  Scene scene;
  scene.name = "warehouse-";
  scene.name += std::to_string(count) + "-" + std::to_string(seed);
  scene.bounds = {0, 0, width, height};
  std::vector<Slot> slots;
  for (size_t r = 0; r <= rows; ++r) {
    const double y = double(r) * (depth + aisle);  // the aisle's lower edge
    for (size_t s = 0; s < segments; ++s) {
      const double x0 = cross + double(s) * (shelf + cross);
      if (r < rows) scene.obstacles.push_back(rect(x0, y + aisle, x0 + shelf, y + aisle + depth));
      for (size_t k = 0; k < perShelf; ++k)
        slots.push_back({{x0 + pitch * (double(k) + 0.5), y + gap + wid / 2}, 0});
    }
    // Cross-aisles beside the shelves of this row: a cart parks crosswise, along one side.
    if (r < rows)
      for (size_t s = 0; s <= segments; ++s)
        slots.push_back(
            {{double(s) * (shelf + cross) + gap + wid / 2, y + aisle + depth / 2}, M_PI / 2});
  }
  // Starts and goals: distinct places each, drawn without replacement; a cart may face either
  // way along its aisle.
  const std::vector<size_t> starts = rng.sample(slots.size(), count),
                            goals = rng.sample(slots.size(), count);
  const Ring cart = rect(-len / 2, -wid / 2, len / 2, wid / 2);
  for (size_t i = 0; i < count; ++i) {
    Robot r;
    r.name = "cart-" + std::to_string(i);
    r.shape = cart;
    const Slot a = slots[starts[i]], b = slots[goals[i]];
    r.start = {a.at.x, a.at.y, a.theta + (rng.below(2) ? M_PI : 0)};
    r.goal = {b.at.x, b.at.y, b.theta + (rng.below(2) ? M_PI : 0)};
    scene.robots.push_back(r);
  }
  return scene;
}

}  // namespace mms
