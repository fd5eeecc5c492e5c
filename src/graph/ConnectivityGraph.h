#pragma once
// The connectivity graph of MMS: one node per free-space cell, one edge per pair of cells
// (of manifolds of different families) that intersect. Boost Graph Library underneath. It
// knows cells by number only: Roadmap maps them to manifolds.
#include <boost/graph/adjacency_list.hpp>
#include <cstdint>
#include <optional>
#include <vector>

namespace mms {

class ConnectivityGraph {
 public:
  struct Node {
    uint32_t manifold;  // the caller's number for the manifold (Roadmap: its table index)
    uint32_t cell;      // FSC index within the manifold
  };

  size_t addNode(const Node& n);
  void addEdge(size_t a, size_t b);
  const Node& node(size_t v) const { return nodes_[v]; }
  size_t nodeCount() const { return nodes_.size(); }
  size_t edgeCount() const { return boost::num_edges(g_); }
  size_t degree(size_t v) const { return boost::out_degree(v, g_); }

  /// Whether a and b are connected (incremental union-find, kept as edges are added).
  bool connected(size_t a, size_t b) const;

  /// Fewest-cells path from `from` to `to` (inclusive), if they are connected.
  std::optional<std::vector<size_t>> path(size_t from, size_t to) const;

 private:
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  Graph g_;
  std::vector<Node> nodes_;
  // boost::disjoint_sets storage; mutable because find_set compresses paths.
  mutable std::vector<size_t> rank_, parent_;
};

}  // namespace mms
