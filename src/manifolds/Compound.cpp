#include "manifolds/Compound.h"

#include <cmath>

namespace mms {

const ManifoldFamily CompoundSliceManifold::kFamily{"compound-slice"};
const ManifoldFamily CompoundLineManifold::kFamily{"compound-line"};

namespace {
Vec2 rotated(Vec2 v, double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}
Pose poseIn(const Config& q, size_t robot) { return poseOf(q, robot); }
void put(Config& q, size_t robot, const Pose& p) {
  q[3 * robot] = p.x;
  q[3 * robot + 1] = p.y;
  q[3 * robot + 2] = p.theta;
}
// Poses computed through the relative pose carry rounding: equal within a hair.
bool near(double a, double b) { return std::abs(a - b) <= 1e-9 * (1 + std::abs(a)); }
bool nearAngle(double a, double b) { return std::abs(std::remainder(a - b, 2 * M_PI)) <= 1e-9; }
// Whether pose p has the fixed coordinates, and p with them snapped to their exact values.
bool pin(unsigned fixes, const Pose& at, Pose& p) {
  if (fixes & OneRobotManifold::kX) {
    if (!near(p.x, at.x)) return false;
    p.x = at.x;
  }
  if (fixes & OneRobotManifold::kY) {
    if (!near(p.y, at.y)) return false;
    p.y = at.y;
  }
  if (fixes & OneRobotManifold::kTheta) {
    if (!nearAngle(p.theta, at.theta)) return false;
    p.theta = at.theta;
  }
  return true;
}
}  // namespace

Pose CompoundFrame::attachedPose(const Pose& c) const {
  const Vec2 p = Vec2{c.x, c.y} + rotated(offset, c.theta);
  return {p.x, p.y, c.theta + dtheta};
}

Pose CompoundFrame::carrierFor(const Pose& a) const {
  const double theta = a.theta - dtheta;
  const Vec2 p = Vec2{a.x, a.y} - rotated(offset, theta);
  return {p.x, p.y, theta};
}

Config CompoundFrame::moved(const Config& q, const Pose& c) const {
  Config out = q;
  put(out, carrier, c);
  put(out, attached, attachedPose(c));
  return out;
}

Config CompoundFrame::config(const Pose& c) const {
  Config q(3 * robots);
  put(q, carrier, c);
  put(q, attached, attachedPose(c));
  return q;
}

std::vector<Ring> compoundShapes(const Scene& scene, const CompoundFrame& f) {
  Ring attached;
  for (const Vec2 v : scene.robots[f.attached].shape)
    attached.push_back(f.offset + rotated(v, f.dtheta));
  return {scene.robots[f.carrier].shape, attached};
}

long CompoundSliceManifold::locate(const Config& q) const {
  const size_t c = frame().carrier;
  return item().locate({q[3 * c], q[3 * c + 1]});
}

std::optional<std::vector<Config>> CompoundSliceManifold::motion(size_t cell, const Config& from,
                                                                 const Config& to) const {
  const size_t c = frame().carrier;
  const auto route =
      slideInCell(item(), cell, {from[3 * c], from[3 * c + 1]}, {to[3 * c], to[3 * c + 1]});
  if (!route) return std::nullopt;
  const double theta = from[3 * c + 2];
  std::vector<Config> out;
  for (const Vec2 p : *route) out.push_back(frame().moved(from, {p.x, p.y, theta}));
  return out;
}

long CompoundLineManifold::locate(const Config& q) const {
  return item().arcContaining(q[3 * frame().carrier + 2]);
}

std::optional<std::vector<Config>> CompoundLineManifold::motion(size_t cell, const Config& from,
                                                                const Config& to) const {
  const size_t c = frame().carrier;
  const double theta0 = from[3 * c + 2];
  const double turn = item().arcs()[cell].turn(theta0, to[3 * c + 2]);
  const int steps = std::max(1, int(std::ceil(std::abs(turn) / kStep)));
  std::vector<Config> out;
  Pose carrier = poseIn(from, c);
  for (int i = 1; i <= steps; ++i) {
    carrier.theta = theta0 + turn * i / steps;
    out.push_back(frame().moved(from, carrier));
  }
  return out;
}

bool meetCompound(const Manifold& ma, const Manifold& mb, Config& at) {
  const auto& a = static_cast<const CompoundManifold&>(ma);
  const auto& b = static_cast<const CompoundManifold&>(mb);
  if (&a.frame() != &b.frame() || (a.fixes() & b.fixes()) != 0 || (a.fixes() | b.fixes()) != 7u)
    return false;
  const Pose pa = a.fixedAt(), pb = b.fixedAt();
  const Pose carrier{a.fixes() & OneRobotManifold::kX ? pa.x : pb.x,
                     a.fixes() & OneRobotManifold::kY ? pa.y : pb.y,
                     a.fixes() & OneRobotManifold::kTheta ? pa.theta : pb.theta};
  at = a.frame().config(carrier);
  return true;
}

bool meetCompoundOneRobot(const Manifold& mc, const Manifold& mo, Config& at) {
  const auto& c = static_cast<const CompoundManifold&>(mc);
  const auto& o = static_cast<const OneRobotManifold&>(mo);
  const CompoundFrame& f = c.frame();
  const HeldFrame& h = o.frame();
  if (h.robots != 2 || h.held.size() != 1) return false;
  const auto& [heldRobot, heldPose] = h.held.front();
  // The carrier's pose is fixed by where the one-robot frame holds a robot of the pair.
  Pose carrier = heldRobot == f.carrier ? heldPose : f.carrierFor(heldPose);
  if (!pin(c.fixes(), c.fixedAt(), carrier)) return false;
  Pose moving = h.moving == f.carrier ? carrier : f.attachedPose(carrier);
  if (!pin(o.fixes(), o.fixedAt(), moving)) return false;
  at.assign(3 * f.robots, 0.0);
  put(at, heldRobot, heldPose);
  put(at, h.moving, moving);
  return true;
}

}  // namespace mms
