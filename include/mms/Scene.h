#pragma once
// The planning problem: bounds, obstacles and robots with their start and goal placements.
#include <algorithm>
#include <string>
#include <vector>

#include "mms/Geometry.h"

namespace mms {

enum class Motion { Rigid, Translate };

struct Robot {
  std::string name;
  Ring shape;  // counter-clockwise, in the robot's frame
  Pose start, goal;
  Motion motion = Motion::Rigid;
};

struct Scene {
  std::string name;  // may be empty
  Box bounds;
  std::vector<Ring> obstacles;  // counter-clockwise; may overlap each other
  std::vector<Robot> robots;

  /// Contacts up to this depth count as touching, not colliding (see docs/formats.md).
  double tolerance() const {
    return kRelativeTolerance * std::max(bounds.width(), bounds.height());
  }
  static constexpr double kRelativeTolerance = 1e-6;

  /// Number of coordinates of a full configuration (x, y, theta per robot).
  size_t dof() const { return 3 * robots.size(); }
};

/// One configuration of all robots: x, y, theta per robot, in scene order.
using Config = std::vector<double>;

inline Pose poseOf(const Config& q, size_t robot) {
  return {q[3 * robot], q[3 * robot + 1], q[3 * robot + 2]};
}
inline void setPose(Config& q, size_t robot, const Pose& p) {
  q[3 * robot] = p.x;
  q[3 * robot + 1] = p.y;
  q[3 * robot + 2] = p.theta;
}
Config startConfig(const Scene& scene);
Config goalConfig(const Scene& scene);

}  // namespace mms
