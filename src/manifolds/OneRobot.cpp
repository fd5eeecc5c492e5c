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
  setPose(out, moving, p);
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
}  // namespace

bool meetOneRobot(const Manifold& ma, const Manifold& mb, Config& q) {
  const auto& a = static_cast<const OneRobotManifold&>(ma);
  const auto& b = static_cast<const OneRobotManifold&>(mb);
  const HeldFrame &fa = a.frame(), &fb = b.frame();
  q.resize(3 * fa.robots);
  if (&fa == &fb) {
    Pose moving;
    if (!jointPose(a, b, moving)) return false;
    for (const auto& [robot, pose] : fa.held) setPose(q, robot, pose);
    setPose(q, fa.moving, moving);
    return true;
  }
  if (fa.moving == fb.moving) return false;  // different held poses: disjoint
  for (size_t r = 0; r < fa.robots; ++r) {
    const Pose *inA = fa.heldPose(r), *inB = fb.heldPose(r);
    if (r == fa.moving) {
      if (!inB || !onManifold(a, *inB)) return false;
      setPose(q, r, *inB);
    } else if (r == fb.moving) {
      if (!inA || !onManifold(b, *inA)) return false;
      setPose(q, r, *inA);
    } else {
      if (!inA || !inB || !(inA->x == inB->x && inA->y == inB->y && inA->theta == inB->theta))
        return false;
      setPose(q, r, *inA);
    }
  }
  return true;
}

}  // namespace mms
