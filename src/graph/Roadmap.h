#pragma once
// The roadmap: the connectivity graph and the table that maps its nodes to (manifold, cell),
// each manifold with its family and its planner's bookkeeping (group, index). It joins any
// two manifolds through the meeting table (manifolds/Manifold.h), so the graph, the search and
// the path stage need no edit when a family is added.
#include <cstdint>
#include <memory>
#include <vector>

#include "graph/ConnectivityGraph.h"
#include "manifolds/Manifold.h"

namespace mms {

class Roadmap {
 public:
  struct Entry {
    std::unique_ptr<Manifold> manifold;
    uint32_t group;  // the planner's grouping, e.g. the subspace it belongs to
    uint32_t index;  // the planner's own number for it within the group
    size_t firstNode;
  };

  /// Adds a manifold and one node per cell (numbered consecutively). Returns its id.
  uint32_t add(std::unique_ptr<Manifold> manifold, uint32_t group, uint32_t index);
  const Entry& entry(uint32_t id) const { return entries_[id]; }
  const Manifold& manifold(uint32_t id) const { return *entries_[id].manifold; }
  size_t manifoldCount() const { return entries_.size(); }
  /// The node of cell `cell` of manifold `id`.
  size_t node(uint32_t id, size_t cell) const { return entries_[id].firstNode + cell; }
  /// The entry a node's cell belongs to.
  const Entry& entryOf(size_t node) const { return entries_[graph_.node(node).manifold]; }
  uint32_t cellOf(size_t node) const { return graph_.node(node).cell; }

  /// Joins the cells of manifolds a and b that hold their meeting point, if they meet there.
  /// Locates in a first: pass the manifold whose location is cheaper first. Returns whether
  /// an edge was added.
  bool join(uint32_t a, uint32_t b);
  void addEdge(size_t nodeA, size_t nodeB) { graph_.addEdge(nodeA, nodeB); }

  const ConnectivityGraph& graph() const { return graph_; }
  size_t nodeCount() const { return graph_.nodeCount(); }
  size_t edgeCount() const { return graph_.edgeCount(); }

  /// How many distinct manifolds (and groups) the cells of `path` lie on: what an oracle that
  /// built only the manifolds of the solution would have built.
  struct Footprint {
    size_t manifolds = 0, groups = 0;
  };
  Footprint footprint(const std::vector<size_t>& path) const;

 private:
  ConnectivityGraph graph_;
  std::vector<Entry> entries_;
  Config meeting_;  // join's scratch: no allocation per pair
};

}  // namespace mms
