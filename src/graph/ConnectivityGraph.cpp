#include "graph/ConnectivityGraph.h"

#include <boost/graph/breadth_first_search.hpp>
#include <boost/pending/disjoint_sets.hpp>

namespace mms {

namespace {
using Sets = boost::disjoint_sets<size_t*, size_t*>;
}

size_t ConnectivityGraph::addNode(const Node& n) {
  nodes_.push_back(n);
  rank_.push_back(0);
  parent_.push_back(parent_.size());
  return boost::add_vertex(g_);
}

void ConnectivityGraph::addEdge(size_t a, size_t b) {
  boost::add_edge(a, b, g_);
  Sets(rank_.data(), parent_.data()).union_set(a, b);
}

bool ConnectivityGraph::connected(size_t a, size_t b) const {
  Sets sets(rank_.data(), parent_.data());
  return sets.find_set(a) == sets.find_set(b);
}

std::optional<std::vector<size_t>> ConnectivityGraph::path(size_t from, size_t to) const {
  const size_t n = boost::num_vertices(g_);
  constexpr size_t kNone = ~size_t(0);
  std::vector<size_t> pred(n, kNone);
  pred[from] = from;
  auto recorder = boost::record_predecessors(pred.data(), boost::on_tree_edge());
  boost::breadth_first_search(g_, from, boost::visitor(boost::make_bfs_visitor(recorder)));
  if (pred[to] == kNone) return std::nullopt;
  std::vector<size_t> out{to};
  while (out.back() != from) out.push_back(pred[out.back()]);
  return std::vector<size_t>(out.rbegin(), out.rend());
}

}  // namespace mms
