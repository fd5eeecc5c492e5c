#include "path/Motion.h"

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

CertifiedMotion certifiedMotion(const Scene& scene, const CollisionChecker& checker,
                                const Roadmap& roadmap, const std::vector<size_t>& nodes) {
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
    next(&m.certifySeconds);
    if (!built) return m;
    std::vector<Config>& w = *built;
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
