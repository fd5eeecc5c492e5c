#include "manifolds/OneRobot.h"

#include <cmath>

#include "manifolds/CellRoute.h"

namespace mms {

const ManifoldFamily HeldFrame::kSliceFamily{"slice"};
const ManifoldFamily HeldFrame::kLineFamily{"line"};

const Pose* HeldFrame::heldPose(size_t robot) const {
  for (const auto& [r, pose] : held)
    if (r == robot) return &pose;
  return nullptr;
}

std::optional<std::vector<Vec2>> slideInCell(const Slice& slice, size_t cell, Vec2 a, Vec2 b) {
  auto route = routeInCell(
      slice.cell(cell), [&](Vec2 p) { return slice.locate(p) == long(cell); }, a, b);
  if (route) route->erase(route->begin());
  return route;
}

Config HeldFrame::moved(const Config& q, const Pose& p) const {
  Config out = q;
  out[3 * moving] = p.x;
  out[3 * moving + 1] = p.y;
  out[3 * moving + 2] = p.theta;
  return out;
}

namespace {
// Whether pose p has the coordinates manifold m fixes. Angles are compared modulo a turn and
// within a hair: a translating robot is held at its own angle, its slice at the nearest
// rational angle.
bool onManifold(const OneRobotManifold& m, const Pose& p) {
  const Pose at = m.fixedAt();
  if ((m.fixes() & OneRobotManifold::kX) && p.x != at.x) return false;
  if ((m.fixes() & OneRobotManifold::kY) && p.y != at.y) return false;
  if ((m.fixes() & OneRobotManifold::kTheta) &&
      std::abs(std::remainder(p.theta - at.theta, 2 * M_PI)) > 1e-6)
    return false;
  return true;
}
void put(Config& q, size_t robot, const Pose& p) {
  q[3 * robot] = p.x;
  q[3 * robot + 1] = p.y;
  q[3 * robot + 2] = p.theta;
}
}  // namespace

bool meetOneRobot(const Manifold& ma, const Manifold& mb, Config& q) {
  const auto& a = static_cast<const OneRobotManifold&>(ma);
  const auto& b = static_cast<const OneRobotManifold&>(mb);
  const HeldFrame &fa = a.frame(), &fb = b.frame();
  q.resize(3 * fa.robots);
  if (&fa == &fb) {
    if ((a.fixes() | b.fixes()) !=
            (OneRobotManifold::kX | OneRobotManifold::kY | OneRobotManifold::kTheta) ||
        (a.fixes() & b.fixes()) != 0)
      return false;  // two slices or two lines: no single meeting point
    const Pose pa = a.fixedAt(), pb = b.fixedAt();
    const Pose moving{a.fixes() & OneRobotManifold::kX ? pa.x : pb.x,
                      a.fixes() & OneRobotManifold::kY ? pa.y : pb.y,
                      a.fixes() & OneRobotManifold::kTheta ? pa.theta : pb.theta};
    for (const auto& [robot, pose] : fa.held) put(q, robot, pose);
    put(q, fa.moving, moving);
    return true;
  }
  if (fa.moving == fb.moving) return false;  // different held poses: disjoint
  for (size_t r = 0; r < fa.robots; ++r) {
    const Pose *inA = fa.heldPose(r), *inB = fb.heldPose(r);
    if (r == fa.moving) {
      if (!inB || !onManifold(a, *inB)) return false;
      put(q, r, *inB);
    } else if (r == fb.moving) {
      if (!inA || !onManifold(b, *inA)) return false;
      put(q, r, *inA);
    } else {
      if (!inA || !inB || !(inA->x == inB->x && inA->y == inB->y && inA->theta == inB->theta))
        return false;
      put(q, r, *inA);
    }
  }
  return true;
}

}  // namespace mms
