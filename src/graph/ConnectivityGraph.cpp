#include "graph/ConnectivityGraph.h"

// The adaptor first: breadth_first_search finds vertices() and out_edges() for std::vector by
// ordinary lookup, which sees only what was declared before it (ADL looks in std).
// clang-format off
#include <boost/graph/vector_as_graph.hpp>
#include <boost/graph/breadth_first_search.hpp>
// clang-format on
#include <boost/pending/disjoint_sets.hpp>
#include <stdexcept>

namespace mms {

namespace {
using Sets = boost::disjoint_sets<size_t*, size_t*>;
}

size_t ConnectivityGraph::addNode(const Node& n) {
  nodes_.push_back(n);
  rank_.push_back(0);
  parent_.push_back(parent_.size());
  if (adjacency_.size() >= UINT32_MAX) throw std::length_error("roadmap: more than 2^32 cells");
  adjacency_.emplace_back();
  return adjacency_.size() - 1;
}

void ConnectivityGraph::addEdge(size_t a, size_t b) {
  adjacency_[a].push_back(uint32_t(b));
  adjacency_[b].push_back(uint32_t(a));
  unite(a, b);
}

void ConnectivityGraph::unite(size_t a, size_t b) {
  ++edges_;
  Sets(rank_.data(), parent_.data()).union_set(a, b);
}

bool ConnectivityGraph::connected(size_t a, size_t b) const {
  Sets sets(rank_.data(), parent_.data());
  return sets.find_set(a) == sets.find_set(b);
}

std::optional<std::vector<size_t>> ConnectivityGraph::path(size_t from, size_t to) const {
  const size_t n = adjacency_.size();
  constexpr uint32_t kNone = ~uint32_t(0);
  std::vector<uint32_t> pred(n, kNone);
  pred[from] = uint32_t(from);
  std::vector<boost::default_color_type> color(n, boost::white_color);
  auto recorder = boost::record_predecessors(pred.data(), boost::on_tree_edge());
  boost::breadth_first_search(
      adjacency_, uint32_t(from),
      boost::visitor(boost::make_bfs_visitor(recorder)).color_map(color.data()));
  if (pred[to] == kNone) return std::nullopt;
  std::vector<size_t> out{to};
  while (out.back() != from) out.push_back(pred[out.back()]);
  return std::vector<size_t>(out.rbegin(), out.rend());
}

}  // namespace mms
