#include "manifolds/Compound.h"

#include <cmath>

namespace mms {

const ManifoldFamily CompoundFrame::kSliceFamily{"compound-slice"};
const ManifoldFamily CompoundFrame::kLineFamily{"compound-line"};

namespace {
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

CompoundFrame CompoundFrame::between(const Pose& c, const Pose& a) {
  CompoundFrame f;
  f.offset = rotated({a.x - c.x, a.y - c.y}, -c.theta);
  f.dtheta = std::remainder(a.theta - c.theta, 2 * M_PI);
  return f;
}

Config CompoundFrame::moved(const Config& q, const Pose& c) const {
  Config out = q;
  setPose(out, carrier, c);
  setPose(out, attached, attachedPose(c));
  return out;
}

Config CompoundFrame::config(const Pose& c) const { return moved(Config(3 * robots), c); }

std::vector<Ring> compoundShapes(const Scene& scene, const CompoundFrame& f) {
  Ring attached;
  for (const Vec2 v : scene.robots[f.attached].shape)
    attached.push_back(f.offset + rotated(v, f.dtheta));
  return {scene.robots[f.carrier].shape, attached};
}

bool meetCompound(const Manifold& ma, const Manifold& mb, Config& at) {
  const auto& a = static_cast<const CompoundManifold&>(ma);
  const auto& b = static_cast<const CompoundManifold&>(mb);
  Pose carrier;
  if (&a.frame() != &b.frame() || !jointPose(a, b, carrier)) return false;
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
  setPose(at, heldRobot, heldPose);
  setPose(at, h.moving, moving);
  return true;
}

}  // namespace mms
