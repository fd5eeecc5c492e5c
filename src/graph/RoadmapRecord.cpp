#include "graph/RoadmapRecord.h"

#include <algorithm>
#include <map>
#include <set>

namespace mms {

namespace {

// What a manifold adds to a record's file, about (RecordBudget::bytes).
size_t fileBytes(const RecordManifold& m) { return 130 + 18 * m.vertices + 20 * m.cells; }

}  // namespace

RecordGrowth growthOf(std::vector<std::pair<uint32_t, float>> stamps,
                      const std::vector<std::string>& kinds) {
  std::stable_sort(stamps.begin(), stamps.end(),
                   [](const auto& a, const auto& b) { return a.second < b.second; });
  RecordGrowth g;
  for (const std::string& k : kinds) g.counts.emplace_back(k, std::vector<size_t>{});
  const float last = stamps.empty() ? 0.f : stamps.back().second;
  std::vector<size_t> sofar(kinds.size(), 0);
  size_t next = 0;
  for (size_t i = 0; i < kGrowthSamples; ++i) {
    const float t = last * float(i) / float(kGrowthSamples - 1);
    // The last sample takes every stamp, whatever rounding did to t.
    while (next < stamps.size() && (stamps[next].second <= t || i + 1 == kGrowthSamples))
      ++sofar[stamps[next++].first];
    g.at.push_back(t);
    for (size_t k = 0; k < kinds.size(); ++k) g.counts[k].second.push_back(sofar[k]);
  }
  return g;
}

void appendRoadmap(const Roadmap& roadmap, const RecordBudget& budget, PlanRecord& out) {
  const size_t n = roadmap.manifoldCount();
  std::vector<char> onPath(n, 0);
  for (size_t node : roadmap.pathNodes()) onPath[roadmap.graph().node(node).manifold] = 1;
  // What keeping everything would take, to keep every k-th manifold within the budget: a
  // thinned record still shows the whole run, not its first seconds.
  std::vector<std::string> kinds;
  std::map<std::string, uint32_t> kindOf;
  std::vector<std::pair<uint32_t, float>> stamps;  // (kind, time) per manifold
  size_t bytes = 0;
  std::set<uint32_t> groups;
  for (size_t id = 0; id < n; ++id) {
    const Roadmap::Entry& e = roadmap.entry(uint32_t(id));
    RecordManifold m;
    e.manifold->sketch(m, false);
    const auto [it, added] = kindOf.emplace(m.family, uint32_t(kinds.size()));
    if (added) kinds.push_back(m.family);
    stamps.emplace_back(it->second, e.at);
    bytes += fileBytes(m);
    // Its subspace's entry, counted as if every subspace were kept (many robots held: 40
    // bytes each, in as many subspaces as manifolds at worst).
    if (groups.insert(e.group).second) {
      RecordSubspace frame;
      e.manifold->sketchFrame(frame);
      bytes += 40 * (1 + frame.held.size());
    }
  }
  out.growth = growthOf(std::move(stamps), kinds);
  const size_t budgetBytes = std::max<size_t>(budget.bytes, 1),
               stride = std::max<size_t>(1, (bytes + budgetBytes - 1) / budgetBytes);
  std::map<uint32_t, uint32_t> subspaceOf;  // roadmap group -> index in out.subspaces
  for (size_t id = 0; id < n; ++id) {
    if (id % stride != 0 && !onPath[id]) continue;
    const Roadmap::Entry& e = roadmap.entry(uint32_t(id));
    RecordManifold m;
    e.manifold->sketch(m, true);
    m.index = id;
    m.at = e.at;
    m.round = e.round;
    m.reached = e.reached;
    m.onPath = onPath[id];
    const auto [it, added] = subspaceOf.emplace(e.group, uint32_t(out.subspaces.size()));
    if (added) e.manifold->sketchFrame(out.subspaces.emplace_back());
    m.subspace = it->second;
    out.manifolds.push_back(std::move(m));
  }
  for (const RecordSearch& s : roadmap.searches()) out.searches.push_back(s);
}

}  // namespace mms
