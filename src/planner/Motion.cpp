#include "planner/Motion.h"

#include <cmath>
#include <set>

#include "check/PathChecker.h"
#include "mms/Termination.h"
#include "path/CellRoute.h"

namespace mms {

std::optional<std::vector<Config>> graphPathMotion(
    const ConnectivityGraph& graph, const std::vector<std::unique_ptr<Subspace>>& subspaces,
    const std::vector<size_t>& nodes, const Config& start, const Config& goal) {
  using Kind = ConnectivityGraph::Kind;
  Config q = start;
  std::vector<Config> w{q};
  for (size_t i = 0; i < nodes.size(); ++i) {
    const ConnectivityGraph::Node& n = graph.node(nodes[i]);
    const Subspace& sub = *subspaces[n.subspace];
    const size_t m = sub.moving();
    Pose exit = poseOf(goal, m);
    if (i + 1 < nodes.size()) {
      const ConnectivityGraph::Node& next = graph.node(nodes[i + 1]);
      if (next.subspace == n.subspace) {
        const ConnectivityGraph::Node& line = n.kind == Kind::LineArc ? n : next;
        const ConnectivityGraph::Node& slice = n.kind == Kind::SliceCell ? n : next;
        const Vec2 p = sub.lines()[line.manifold].point();
        exit = {p.x, p.y, sub.slice(slice.manifold).theta()};
      } else {
        for (const auto& [robot, pose] : subspaces[next.subspace]->held())
          if (robot == m) exit = pose;
      }
    }
    if (n.kind == Kind::LineArc) {
      const Arc& arc = sub.lines()[n.manifold].arcs()[n.cell];
      double& theta = q[3 * m + 2];
      theta += arc.full() ? std::remainder(exit.theta - theta, 2 * M_PI)
                          : arc.unwrap(exit.theta) - arc.unwrap(theta);
      w.push_back(q);
    } else {
      const Slice& slice = sub.slice(n.manifold);
      const auto route =
          routeInCell(slice.cell(n.cell), [&](Vec2 p) { return slice.locate(p) == int(n.cell); },
                      {q[3 * m], q[3 * m + 1]}, {exit.x, exit.y});
      if (!route) return std::nullopt;
      for (size_t j = 1; j < route->size(); ++j) {
        q[3 * m] = (*route)[j].x;
        q[3 * m + 1] = (*route)[j].y;
        w.push_back(q);
      }
    }
  }
  return w;
}

namespace {
// Robots whose configuration changes between waypoints i and j (inclusive stretch).
size_t movingRobots(const std::vector<Config>& w, size_t i, size_t j) {
  size_t count = 0;
  for (size_t r = 0; 3 * r < w[i].size(); ++r) {
    bool moves = false;
    for (size_t k = i + 1; k <= j && !moves; ++k)
      for (size_t c = 3 * r; c < 3 * r + 3; ++c) moves |= w[k][c] != w[i][c];
    count += moves;
  }
  return count;
}
}  // namespace

void shortcutPath(const Scene& scene, const CollisionChecker& checker, Random& rng, size_t attempts,
                  std::vector<Config>& w, bool oneRobotAtATime) {
  PathCheckSettings quick;
  quick.maxEvaluations = 20000;
  // A short path offers few pairs, so attempts repeat them: a refused straight motion stays
  // refused (the check is deterministic), and is not checked again. Same result, less work.
  std::set<std::pair<Config, Config>> refused;
  for (size_t attempt = 0; attempt < attempts && w.size() > 2; ++attempt) {
    size_t i = rng.below(w.size()), j = rng.below(w.size());
    if (i > j) std::swap(i, j);
    if (j < i + 2) continue;
    if (oneRobotAtATime && movingRobots(w, i, j) > 1) continue;
    if (refused.count({w[i], w[j]})) continue;
    if (checkMotion(scene, checker, {w[i], w[j]}, quick).ok)
      w.erase(w.begin() + i + 1, w.begin() + j);
    else
      refused.insert({w[i], w[j]});
  }
}

CertifiedMotion certifiedMotion(const Scene& scene, const CollisionChecker& checker,
                                const ConnectivityGraph& graph,
                                const std::vector<std::unique_ptr<Subspace>>& subspaces,
                                const std::vector<size_t>& nodes, Random& rng,
                                const ShortcutSettings& shortcuts) {
  CertifiedMotion m;
  Stopwatch build;
  auto w = graphPathMotion(graph, subspaces, nodes, startConfig(scene), goalConfig(scene));
  m.buildSeconds = build.seconds();
  if (!w) return m;
  Stopwatch shortcut;
  shortcutPath(scene, checker, rng, shortcuts.attempts, *w, shortcuts.oneRobotAtATime);
  m.shortcutSeconds = shortcut.seconds();
  Stopwatch certify;
  m.certificate = checkPath(scene, checker, *w);
  m.certifySeconds = certify.seconds();
  m.ok = m.certificate.ok;
  m.waypoints = std::move(*w);
  return m;
}

}  // namespace mms
