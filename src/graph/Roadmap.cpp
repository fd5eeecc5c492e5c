#include "graph/Roadmap.h"

#include <set>

namespace mms {

uint32_t Roadmap::add(std::unique_ptr<Manifold> manifold, uint32_t group, uint32_t index) {
  const auto id = uint32_t(entries_.size());
  const size_t first = graph_.nodeCount(), cells = manifold->cellCount();
  for (size_t c = 0; c < cells; ++c) graph_.addNode({id, uint32_t(c)});
  Entry e{std::move(manifold), group, index, first};
  e.at = float(clock_.seconds());
  e.round = round_;
  entries_.push_back(std::move(e));
  return id;
}

void Roadmap::startClock() {
  if (clockStarted_) return;
  clock_ = Stopwatch();
  clockStarted_ = true;
}

void Roadmap::noteSearch(size_t from, size_t to) {
  const float now = float(clock_.seconds());
  searches_.push_back(
      {now, round_, entries_.size(), nodeCount(), edgeCount(), graph_.connected(from, to)});
  if (!trackReached_) return;
  const size_t ends[2] = {from, to};
  for (Entry& e : entries_) {
    const size_t cells = e.manifold->cellCount();
    for (int s = 0; s < 2; ++s)
      for (size_t c = 0; c < cells && e.reached[s] < 0; ++c)
        if (graph_.connected(e.firstNode + c, ends[s])) e.reached[s] = now;
  }
}

bool Roadmap::meeting(uint32_t a, uint32_t b, long& cellA, long& cellB) const {
  const Manifold &ma = manifold(a), &mb = manifold(b);
  if (ma.cellCount() == 0 || mb.cellCount() == 0 || !meet(ma, mb, meeting_)) return false;
  cellA = ma.locate(meeting_);
  if (cellA < 0) return false;
  cellB = mb.locate(meeting_);
  return cellB >= 0;
}

bool Roadmap::join(uint32_t a, uint32_t b) {
  long ca, cb;
  if (!meeting(a, b, ca, cb)) return false;
  graph_.addEdge(node(a, size_t(ca)), node(b, size_t(cb)));
  return true;
}

uint32_t Roadmap::addWeave() {
  weaves_.emplace_back();
  return uint32_t(weaves_.size() - 1);
}

void Roadmap::weave(uint32_t w, int side, uint32_t id) {
  if (manifold(id).cellCount() == 0) return;  // meets nothing
  entries_[id].weave = w;
  entries_[id].side = uint8_t(side);
  weaves_[w].sides[side].push_back(id);
  for (const uint32_t other : weaves_[w].sides[1 - side]) {
    const uint32_t a = side == 0 ? id : other, b = side == 0 ? other : id;
    const Manifold &ma = manifold(a), &mb = manifold(b);
    if (!meet(ma, mb, meeting_)) continue;
    const long ca = ma.locate(meeting_);
    if (ca < 0) continue;
    // Once a's cell is joined with every cell of a b of few cells (open space, and any scene
    // once its parts connect), the union changes nothing: skip locating in b, the costly half.
    const size_t na = node(a, size_t(ca)), cells = mb.cellCount();
    constexpr size_t kFewCells = 8;
    bool joined = cells <= kFewCells;
    for (size_t c = 0; joined && c < cells; ++c) joined = graph_.connected(na, node(b, c));
    if (joined) continue;
    const long cb = mb.locate(meeting_);
    if (cb >= 0) graph_.unite(na, node(b, size_t(cb)));
  }
}

Roadmap::Woven Roadmap::woven(uint32_t id) const {
  const Entry& e = entries_[id];
  const std::vector<uint32_t>& others = weaves_[e.weave].sides[1 - e.side];
  std::vector<std::pair<uint32_t, uint32_t>> found;  // (cell of id, node met)
  for (const uint32_t other : others) {
    long ca, cb;
    const bool first = e.side == 0;
    if (!meeting(first ? id : other, first ? other : id, ca, cb)) continue;
    found.emplace_back(uint32_t(first ? ca : cb), uint32_t(node(other, size_t(first ? cb : ca))));
  }
  Woven out;  // counting sort by cell, keeping the weave's order within each cell
  out.start.assign(manifold(id).cellCount() + 1, 0);
  for (const auto& f : found) ++out.start[f.first + 1];
  for (size_t c = 1; c < out.start.size(); ++c) out.start[c] += out.start[c - 1];
  out.targets.resize(found.size());
  std::vector<uint32_t> fill(out.start.begin(), out.start.end() - 1);
  for (const auto& [cell, target] : found) out.targets[fill[cell]++] = target;
  return out;
}

std::optional<std::vector<size_t>> Roadmap::path(size_t from, size_t to,
                                                 const std::function<bool()>& stop) const {
  if (!graph_.connected(from, to)) return std::nullopt;
  // Breadth-first by hand rather than with Boost's: the weave edges are computed a manifold at
  // a time as the search first reaches one of its cells, and the search ends at `to`, so the
  // weaves the path does not need are never computed.
  constexpr uint32_t kNone = ~uint32_t(0);
  std::vector<uint32_t> pred(nodeCount(), kNone);
  std::vector<Woven> wovens(entries_.size());
  std::vector<bool> computed(entries_.size(), false);
  std::vector<uint32_t> queue{uint32_t(from)};
  pred[from] = uint32_t(from);
  bool reached = from == to;
  auto visit = [&](uint32_t v, uint32_t u) {
    if (pred[u] != kNone) return;
    pred[u] = v;
    queue.push_back(u);
    reached = reached || u == to;
  };
  for (size_t head = 0; head < queue.size() && !reached; ++head) {
    const uint32_t v = queue[head];
    for (const uint32_t u : graph_.neighbours(v)) visit(v, u);
    const uint32_t id = graph_.node(v).manifold;
    if (entries_[id].weave == kNoWeave) continue;
    if (!computed[id]) {
      if (stop && stop()) return std::nullopt;
      wovens[id] = woven(id);
      computed[id] = true;
    }
    const Woven& w = wovens[id];
    const uint32_t c = graph_.node(v).cell;
    for (uint32_t i = w.start[c]; i < w.start[c + 1]; ++i) visit(v, w.targets[i]);
  }
  if (!reached) return std::nullopt;
  std::vector<size_t> out{to};
  while (out.back() != from) out.push_back(pred[out.back()]);
  return std::vector<size_t>(out.rbegin(), out.rend());
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
