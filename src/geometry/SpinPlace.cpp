#include "geometry/SpinPlace.h"

#include <algorithm>
#include <cmath>

#include "geometry/PolygonOps.h"

namespace mms {

namespace {

// The scene's walls with each obstacle's bounding box: an obstacle whose box is no nearer than
// the nearest edge so far cannot be nearer (a climb evaluates hundreds of points).
class Walls {
 public:
  explicit Walls(const Scene& scene) : scene_(scene) {
    for (const Ring& o : scene.obstacles) boxes_.push_back(boundingBox(o));
  }
  double distance(Vec2 p) const {
    const Box& b = scene_.bounds;
    double d = std::min({p.x - b.xmin, b.xmax - p.x, p.y - b.ymin, b.ymax - p.y});
    const Box at{p.x, p.y, p.x, p.y};
    for (size_t i = 0; i < boxes_.size(); ++i)
      if (boxes_[i].distance2(at) < d * d) d = std::min(d, distanceToEdges(scene_.obstacles[i], p));
    return d;
  }

 private:
  const Scene& scene_;
  std::vector<Box> boxes_;
};

}  // namespace

double wallDistance(const Scene& scene, Vec2 p) { return Walls(scene).distance(p); }

Vec2 clearestNear(const Scene& scene, Vec2 p, double step, double reach) {
  const Walls walls(scene);
  const Vec2 start = p;
  const double last = step * 1e-3;
  double best = walls.distance(p);
  // Each move gains; the bound keeps a search along a ridge (a slot's axis) short.
  for (int moves = 0; step > last && moves < 1000; ++moves) {
    bool moved = false;
    for (int d = 0; d < 8 && !moved; ++d) {
      const Vec2 q{p.x + step * std::cos(d * M_PI / 4), p.y + step * std::sin(d * M_PI / 4)};
      if (std::hypot(q.x - start.x, q.y - start.y) > reach) continue;
      const double v = walls.distance(q);
      if (v > best) best = v, p = q, moved = true;
    }
    if (!moved) step /= 2;
  }
  return p;
}

namespace {

// The pose at `q`'s angle whose reference point is the one `to` has at that angle, moved along
// the robot's heading through `q` (its x axis): where a robot that came along its axis through
// a slot leaves the slot's line.
Pose alongHeading(const Config& q, size_t robot, Vec2 to) {
  const size_t x = 3 * robot;
  const Vec2 u{std::cos(q[x + 2]), std::sin(q[x + 2])};
  const double s = (to.x - q[x]) * u.x + (to.y - q[x + 1]) * u.y;
  return {q[x] + s * u.x, q[x + 1] + s * u.y, q[x + 2]};
}

}  // namespace

Pose poseWithPointAt(Vec2 local, Vec2 at, double angle) {
  const Vec2 offset = Transform(Pose{0, 0, angle})(local);
  return {at.x - offset.x, at.y - offset.y, angle};
}

std::vector<Config> turnAbout(const Config& a, const Config& b, size_t robot, Vec2 centre, Vec2 at,
                              double maxStep) {
  const size_t x = 3 * robot;
  const double from = a[x + 2], to = b[x + 2];
  auto spun = [&](double angle) { return poseWithPointAt(centre, at, angle); };
  std::vector<Pose> poses{alongHeading(a, robot, {spun(from).x, spun(from).y})};
  const size_t steps = std::max<size_t>(1, size_t(std::ceil(std::fabs(to - from) / maxStep)));
  for (size_t k = 0; k <= steps; ++k) poses.push_back(spun(from + (to - from) * double(k) / steps));
  poses.push_back(alongHeading(b, robot, {spun(to).x, spun(to).y}));
  std::vector<Config> out;
  for (size_t k = 0; k < poses.size(); ++k) {
    Config q = lerp(a, b, double(k + 1) / double(poses.size() + 1));
    setPose(q, robot, poses[k]);
    out.push_back(std::move(q));
  }
  return out;
}

}  // namespace mms
