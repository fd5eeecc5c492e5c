#pragma once
// The connectivity graph of MMS: one node per free-space cell, one edge per pair of cells
// (of manifolds of different families) that intersect. Boost Graph Library underneath. It
// knows cells by number only: Roadmap maps them to manifolds.
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
  /// Records that a and b are connected without storing the edge (its owner recomputes it
  /// when searching): the union-find only.
  void unite(size_t a, size_t b);
  /// The stored edges of v, both ways.
  const std::vector<uint32_t>& neighbours(size_t v) const { return adjacency_[v]; }
  const Node& node(size_t v) const { return nodes_[v]; }
  size_t nodeCount() const { return nodes_.size(); }
  /// Stored edges plus those recorded by unite().
  size_t edgeCount() const { return edges_; }

  /// Whether a and b are connected (incremental union-find, kept as edges are added).
  bool connected(size_t a, size_t b) const;

  /// Fewest-cells path from `from` to `to` (inclusive), if they are connected.
  std::optional<std::vector<size_t>> path(size_t from, size_t to) const;

 private:
  // Each node's neighbours as 32-bit indices, both ways (Boost's vector-as-graph adaptor):
  // 8 bytes an edge, where adjacency_list's undirected edge list took about 80. The roadmap's
  // edges grow with lines times slices, so this is most of its memory.
  std::vector<std::vector<uint32_t>> adjacency_;
  size_t edges_ = 0;
  std::vector<Node> nodes_;
  // boost::disjoint_sets storage; mutable because find_set compresses paths.
  mutable std::vector<size_t> rank_, parent_;
};

}  // namespace mms
