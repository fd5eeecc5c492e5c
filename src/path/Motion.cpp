#include "path/Motion.h"

#include <set>

#include "check/PathChecker.h"
#include "mms/Termination.h"

namespace mms {

std::optional<std::vector<Config>> graphPathMotion(const Roadmap& roadmap,
                                                   const std::vector<size_t>& nodes,
                                                   const Config& start, const Config& goal) {
  std::vector<Config> w{start};
  for (size_t i = 0; i < nodes.size(); ++i) {
    checkpoint();  // the planner's time limit, between cells
    const Manifold& here = roadmap.manifold(roadmap.graph().node(nodes[i]).manifold);
    Config exit = goal;
    if (i + 1 < nodes.size()) {
      auto at = meetingPoint(here, roadmap.manifold(roadmap.graph().node(nodes[i + 1]).manifold));
      if (!at) return std::nullopt;
      exit = std::move(*at);
    }
    auto moved = here.motion(roadmap.cellOf(nodes[i]), w.back(), exit);
    if (!moved) return std::nullopt;
    for (Config& q : *moved) w.push_back(std::move(q));
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
  const Termination* stop = StopScope::current();
  for (size_t attempt = 0; attempt < attempts && w.size() > 2 && !(stop && (*stop)()); ++attempt) {
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
                                const Roadmap& roadmap, const std::vector<size_t>& nodes,
                                Random& rng, const ShortcutSettings& shortcuts) {
  CertifiedMotion m;
  // The limit may strike in any step (a path along contacts takes the certifier seconds): then
  // no motion, and the time of each step still counted.
  Stopwatch step;
  double* phase = &m.buildSeconds;  // the step under way
  auto next = [&](double* following) {
    *phase = step.seconds();
    step = Stopwatch();
    phase = following;
  };
  try {
    std::optional<std::vector<Config>> built =
        graphPathMotion(roadmap, nodes, startConfig(scene), goalConfig(scene));
    next(&m.shortcutSeconds);
    if (!built) return m;
    std::vector<Config>& w = *built;
    shortcutPath(scene, checker, rng, shortcuts.attempts, w, shortcuts.oneRobotAtATime);
    next(&m.certifySeconds);
    m.certificate = checkPath(scene, checker, w);
    *phase = step.seconds();
    m.ok = m.certificate.ok;
    m.waypoints = std::move(w);
  } catch (const Stopped&) {
    *phase = step.seconds();
    m.certificate.reason = "the time limit struck before the motion was certified";
  }
  return m;
}

}  // namespace mms
