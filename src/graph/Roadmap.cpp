#include "graph/Roadmap.h"

#include <set>

namespace mms {

uint32_t Roadmap::add(std::unique_ptr<Manifold> manifold, uint32_t group, uint32_t index) {
  const auto id = uint32_t(entries_.size());
  const size_t first = graph_.nodeCount(), cells = manifold->cellCount();
  for (size_t c = 0; c < cells; ++c) graph_.addNode({id, uint32_t(c)});
  entries_.push_back({std::move(manifold), group, index, first});
  return id;
}

bool Roadmap::join(uint32_t a, uint32_t b) {
  const Manifold &ma = manifold(a), &mb = manifold(b);
  if (ma.cellCount() == 0 || mb.cellCount() == 0) return false;
  if (!meet(ma, mb, meeting_)) return false;
  const long ca = ma.locate(meeting_);
  if (ca < 0) return false;
  const long cb = mb.locate(meeting_);
  if (cb < 0) return false;
  graph_.addEdge(node(a, size_t(ca)), node(b, size_t(cb)));
  return true;
}

Roadmap::Footprint Roadmap::footprint(const std::vector<size_t>& path) const {
  std::set<uint32_t> manifolds, groups;
  for (const size_t v : path) {
    manifolds.insert(graph_.node(v).manifold);
    groups.insert(entryOf(v).group);
  }
  return {manifolds.size(), groups.size()};
}

}  // namespace mms
