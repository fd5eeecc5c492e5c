#include "manifolds/OneRobot.h"

#include <cmath>

#include "manifolds/CellRoute.h"

namespace mms {

const ManifoldFamily SliceManifold::kFamily{"slice"};
const ManifoldFamily LineManifold::kFamily{"line"};

const Pose* HeldFrame::heldPose(size_t robot) const {
  for (const auto& [r, pose] : held)
    if (r == robot) return &pose;
  return nullptr;
}

long SliceManifold::locate(const Config& q) const {
  const size_t m = frame().moving;
  return slice().locate({q[3 * m], q[3 * m + 1]});
}

std::optional<std::vector<Vec2>> slideInCell(const Slice& slice, size_t cell, Vec2 a, Vec2 b) {
  auto route = routeInCell(
      slice.cell(cell), [&](Vec2 p) { return slice.locate(p) == long(cell); }, a, b);
  if (route) route->erase(route->begin());
  return route;
}

std::optional<std::vector<Config>> SliceManifold::motion(size_t cell, const Config& from,
                                                         const Config& to) const {
  const size_t m = frame().moving;
  const auto route =
      slideInCell(slice(), cell, {from[3 * m], from[3 * m + 1]}, {to[3 * m], to[3 * m + 1]});
  if (!route) return std::nullopt;
  std::vector<Config> out(route->size(), from);
  for (size_t j = 0; j < route->size(); ++j) {
    out[j][3 * m] = (*route)[j].x;
    out[j][3 * m + 1] = (*route)[j].y;
  }
  return out;
}

long LineManifold::locate(const Config& q) const {
  return line().arcContaining(q[3 * frame().moving + 2]);
}

std::optional<std::vector<Config>> LineManifold::motion(size_t cell, const Config& from,
                                                        const Config& to) const {
  const size_t m = frame().moving;
  Config q = from;
  q[3 * m + 2] += line().arcs()[cell].turn(from[3 * m + 2], to[3 * m + 2]);
  return std::vector<Config>{q};
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
