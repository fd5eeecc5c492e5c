#pragma once
// The roadmap: the connectivity graph and the table that maps its nodes to (manifold, cell),
// each manifold with its family and its planner's bookkeeping (group, index). It joins any
// two manifolds through the meeting table (manifolds/Manifold.h), so the graph, the search and
// the path stage need no edit when a family is added.
//
// Most joins come in weaves: every line of a subspace meets every slice of it, so their edges
// grow with the product of the manifolds. A weave's edges are not stored: adding a manifold to
// a weave only unites the cells it meets in the union-find (which decides when to search), and
// the search recomputes the edges of the manifolds it reaches. The roadmap's memory then grows
// with the manifolds and their cells, not with the meetings.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "graph/ConnectivityGraph.h"
#include "manifolds/Manifold.h"
#include "mms/Record.h"
#include "mms/Termination.h"

namespace mms {

class Roadmap {
 public:
  struct Entry {
    std::unique_ptr<Manifold> manifold;
    uint32_t group;  // the planner's grouping, e.g. the subspace it belongs to
    uint32_t index;  // the planner's own number for it within the group
    size_t firstNode;
    uint32_t weave = kNoWeave;  // the weave it is in, if any, and on which side
    uint8_t side = 0;
    // For a record of the planning: seconds since the clock started and the round it was
    // built in; when its cells first joined the start's and the goal's component (-1: not
    // yet, or not tracked).
    float at = 0;
    uint32_t round = 0;
    std::array<float, 2> reached{-1, -1};
  };
  static constexpr uint32_t kNoWeave = ~uint32_t(0);

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

  /// A new, empty weave: two sides, each manifold on one joined to every manifold on the other.
  uint32_t addWeave();
  /// Adds manifold `id` (in no weave yet) to side `side` (0 or 1) of weave `w`, joined to the
  /// manifolds on the other side. Side 0 is located in first when two meet: put the family
  /// whose location is cheaper there (lines before slices).
  void weave(uint32_t w, int side, uint32_t id);

  /// Fewest-cells path from node `from` to node `to` (inclusive) through stored edges and
  /// weaves; nothing if they are not connected, or if `stop` turns true during the search.
  std::optional<std::vector<size_t>> path(size_t from, size_t to,
                                          const std::function<bool()>& stop = {}) const;

  const ConnectivityGraph& graph() const { return graph_; }
  size_t nodeCount() const { return graph_.nodeCount(); }
  size_t edgeCount() const { return graph_.edgeCount(); }

  /// How many distinct manifolds (and groups) the cells of `path` lie on: what an oracle that
  /// built only the manifolds of the solution would have built.
  struct Footprint {
    size_t manifolds = 0, groups = 0;
  };
  Footprint footprint(const std::vector<size_t>& path) const;

  // The chronicle a record of the planning reads (mms/Record.h). Stamping costs a clock read
  // per manifold; tracking the components a pass over the nodes per search, so it is asked for.
  /// Starts the clock manifolds are stamped with, unless it runs (multi-query: the first query).
  void startClock();
  /// Manifolds added from now on belong to round `round`.
  void beginRound(uint32_t round) { round_ = round; }
  /// Whether noteSearch stamps when manifolds join the start's and the goal's component.
  void trackReached(bool on) { trackReached_ = on; }
  /// A search between nodes from and to has run: the graph's size, and (tracked) the
  /// manifolds now reached.
  void noteSearch(size_t from, size_t to);
  /// The graph path of the motion found.
  void notePath(std::vector<size_t> nodes) { path_ = std::move(nodes); }
  const std::vector<RecordSearch>& searches() const { return searches_; }
  const std::vector<size_t>& pathNodes() const { return path_; }

 private:
  struct Weave {
    std::vector<uint32_t> sides[2];
  };
  /// The cells of a and b that hold their meeting point (a located first); false if they do
  /// not meet or the point is in no cell of one of them.
  bool meeting(uint32_t a, uint32_t b, long& cellA, long& cellB) const;
  /// The weave edges of manifold id, grouped by its cell: the nodes cell c meets are
  /// targets[start[c] .. start[c + 1]).
  struct Woven {
    std::vector<uint32_t> start, targets;
  };
  Woven woven(uint32_t id) const;

  ConnectivityGraph graph_;
  std::vector<Entry> entries_;
  std::vector<Weave> weaves_;
  mutable Config meeting_;  // meeting()'s scratch: no allocation per pair
  Stopwatch clock_;
  bool clockStarted_ = false, trackReached_ = false;
  uint32_t round_ = 0;
  std::vector<RecordSearch> searches_;
  std::vector<size_t> path_;
};

}  // namespace mms
