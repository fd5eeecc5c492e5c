#include "scenarios/Witness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>

#include "geometry/CollisionChecker.h"

namespace mms {

namespace {

// One robot's search: poses (i, j, k) = cell centre (i, j), angle k * step, as one index.
class PoseGrid {
 public:
  PoseGrid(const Scene& scene, const CollisionChecker& checker, size_t robot, double h,
           const Config& parked)
      : scene_(scene), checker_(checker), robot_(robot), parked_(parked), h_(h) {
    const Box& b = scene.bounds;
    nx_ = std::max(1, int(std::floor(b.width() / h)));
    ny_ = std::max(1, int(std::floor(b.height() / h)));
    // An angle step moves no point further than a cell: radius * step <= h. A robot that only
    // translates keeps its start angle: one angle.
    const Robot& r = scene.robots[robot];
    if (r.motion == Motion::Translate) {
      nk_ = 1;
      theta0_ = r.start.theta;
    } else {
      nk_ = std::clamp(int(std::ceil(2 * M_PI * checker.radius(robot) / h)), 4, 720);
    }
    step_ = 2 * M_PI / nk_;
    margin_ = 0.5 * h * (1 + 1e-6);
    clearance_.assign(size_t(nx_) * size_t(ny_) * size_t(nk_),
                      std::numeric_limits<float>::quiet_NaN());
  }

  // The grid poses from `from` to `to` with the angle unwrapped (every step turns by at most
  // one angle step), or empty when the search finds no way.
  std::vector<Pose> route(const Pose& from, const Pose& to) {
    const std::vector<int> starts = entries(from), goals = entries(to);
    if (starts.empty() || goals.empty()) return {};
    std::vector<char> isGoal(clearance_.size(), 0);
    for (const int g : goals) isGoal[size_t(g)] = 1;
    // Greedy best-first on the distance to the goal's position: explores little in open scenes
    // and still every reachable pose before it gives up. Ties go to the earlier pose.
    std::vector<int> parent(clearance_.size(), -2);  // -2 unseen, -1 an entry
    using Item = std::pair<double, long>;            // (distance, -order)
    std::priority_queue<Item> open;
    std::vector<int> byOrder;
    auto push = [&](int n, int from) {
      parent[size_t(n)] = from;
      const Pose p = pose(n);
      open.push({-std::hypot(p.x - to.x, p.y - to.y), -long(byOrder.size())});
      byOrder.push_back(n);
    };
    for (const int s : starts)
      if (parent[size_t(s)] == -2) push(s, -1);
    int reached = -1;
    while (!open.empty()) {
      const int n = byOrder[size_t(-open.top().second)];
      open.pop();
      if (isGoal[size_t(n)]) {
        reached = n;
        break;
      }
      const int i = n % nx_, j = (n / nx_) % ny_, k = n / (nx_ * ny_);
      const int next[6][3] = {{i + 1, j, k}, {i - 1, j, k},         {i, j + 1, k},
                              {i, j - 1, k}, {i, j, (k + 1) % nk_}, {i, j, (k + nk_ - 1) % nk_}};
      for (const auto& m : next) {
        if (m[0] < 0 || m[0] >= nx_ || m[1] < 0 || m[1] >= ny_) continue;
        const int c = index(m[0], m[1], m[2]);
        if (parent[size_t(c)] != -2 || !(clearance(c) > margin_)) continue;
        push(c, n);
      }
    }
    if (reached < 0) return {};
    std::vector<int> cells;
    for (int n = reached; n >= 0; n = parent[size_t(n)]) cells.push_back(n);
    std::reverse(cells.begin(), cells.end());
    std::vector<Pose> out;
    double theta = from.theta + std::remainder(pose(cells[0]).theta - from.theta, 2 * M_PI);
    for (size_t c = 0; c < cells.size(); ++c) {
      if (c > 0) theta += std::remainder(pose(cells[c]).theta - pose(cells[c - 1]).theta, 2 * M_PI);
      out.push_back({pose(cells[c]).x, pose(cells[c]).y, theta});
    }
    return out;
  }

 private:
  int index(int i, int j, int k) const { return (k * ny_ + j) * nx_ + i; }
  Pose pose(int n) const {
    const int i = n % nx_, j = (n / nx_) % ny_, k = n / (nx_ * ny_);
    return {scene_.bounds.xmin + (i + 0.5) * h_, scene_.bounds.ymin + (j + 0.5) * h_,
            theta0_ + k * step_};
  }

  // The robot's clearance at a grid pose to the bounds, the obstacles and the parked robots,
  // measured up to two cells: steps need more than half a cell, and an entry whose move is
  // longer than two cells is refused (conservative, never unsafe).
  double clearance(int n) {
    float& memo = clearance_[size_t(n)];
    if (std::isnan(memo)) memo = float(measure(pose(n)));
    return double(memo);
  }
  double measure(const Pose& p) const {
    const double bound = 4 * margin_;
    double d = checker_.robotClearance(robot_, p, bound).distance;
    for (size_t j = 0; j < checker_.robotCount() && d > 0; ++j)
      if (j != robot_)
        d = std::min(d, checker_.robotsDistance(robot_, p, j, poseOf(parked_, j), d));
    return d;
  }

  // Grid poses joined to `p` by a straight move that stays free: the move displaces no point
  // by more than |dp| + radius * |dtheta|, which the clearance at the grid pose must exceed.
  std::vector<int> entries(const Pose& p) {
    std::vector<int> out;
    const Box& b = scene_.bounds;
    const int i0 = std::clamp(int(std::floor((p.x - b.xmin) / h_ - 0.5)), 0, nx_ - 1);
    const int j0 = std::clamp(int(std::floor((p.y - b.ymin) / h_ - 0.5)), 0, ny_ - 1);
    const double turns = (p.theta - theta0_) / step_;
    const int k0 = int(std::floor(turns - nk_ * std::floor(turns / nk_)));
    for (int dk = 0; dk <= 1; ++dk)
      for (int dj = 0; dj <= 1; ++dj)
        for (int di = 0; di <= 1; ++di) {
          const int n =
              index(std::min(i0 + di, nx_ - 1), std::min(j0 + dj, ny_ - 1), (k0 + dk) % nk_);
          const Pose q = pose(n);
          const double move =
              std::hypot(q.x - p.x, q.y - p.y) +
              checker_.radius(robot_) * std::fabs(std::remainder(q.theta - p.theta, 2 * M_PI));
          const double c = clearance(n);
          if (c > margin_ && c > move * (1 + 1e-6)) out.push_back(n);
        }
    return out;
  }

  const Scene& scene_;
  const CollisionChecker& checker_;
  size_t robot_;
  const Config& parked_;
  double h_, step_ = 0, margin_ = 0, theta0_ = 0;
  int nx_ = 1, ny_ = 1, nk_ = 4;
  std::vector<float> clearance_;
};

// A pose between two equal steps lies on the straight move that joins its neighbours.
void appendStraightened(std::vector<Config>& path, size_t robot, const std::vector<Pose>& poses,
                        Config& q) {
  auto delta = [](const Pose& a, const Pose& b) {
    return std::array<double, 3>{b.x - a.x, b.y - a.y, b.theta - a.theta};
  };
  for (size_t k = 0; k < poses.size(); ++k) {
    if (k > 0 && k + 1 < poses.size() &&
        delta(poses[k - 1], poses[k]) == delta(poses[k], poses[k + 1]))
      continue;
    setPose(q, robot, poses[k]);
    path.push_back(q);
  }
}

std::optional<std::vector<Config>> inOrder(const Scene& scene, const CollisionChecker& checker,
                                           const std::vector<size_t>& order, double h) {
  Config q = startConfig(scene);
  std::vector<Config> path{q};
  for (const size_t i : order) {
    const Robot& robot = scene.robots[i];
    PoseGrid grid(scene, checker, i, h, q);
    std::vector<Pose> poses = grid.route(robot.start, robot.goal);
    if (poses.empty()) return std::nullopt;
    // The goal's angle as the representative nearest the route's last, so the final move
    // turns by less than an angle step.
    Pose goal = robot.goal;
    goal.theta = poses.back().theta + std::remainder(goal.theta - poses.back().theta, 2 * M_PI);
    poses.push_back(goal);
    appendStraightened(path, i, poses, q);
  }
  return path;
}

}  // namespace

std::optional<std::vector<Config>> gridWitness(const Scene& scene, int cellsAcross) {
  const CollisionChecker checker(scene);
  const double h = std::max(scene.bounds.width(), scene.bounds.height()) / std::max(1, cellsAcross);
  std::vector<size_t> order(scene.robots.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  if (auto path = inOrder(scene, checker, order, h)) return path;
  if (order.size() < 2) return std::nullopt;
  std::reverse(order.begin(), order.end());
  return inOrder(scene, checker, order, h);
}

}  // namespace mms
