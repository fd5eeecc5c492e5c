#include "lab/EuclideanMms.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "graph/ConnectivityGraph.h"
#include "util/Random.h"

namespace mms::lab {

namespace {

struct Manifold {
  size_t family;
  SubspaceCells cells;
  size_t firstNode;  // graph node of FSC 0
};

AxisSubspace subspaceFixing(const std::vector<int>& fixed, Point point) {
  AxisSubspace s{{}, std::move(point)};
  for (int i = 0; i < int(s.point.size()); ++i)
    if (std::find(fixed.begin(), fixed.end(), i) == fixed.end()) s.freeAxes.push_back(i);
  return s;
}

}  // namespace

EuclideanMmsResult solveEuclideanMms(const BoxSpace& space, const Point& start, const Point& goal,
                                     const EuclideanMmsSettings& settings) {
  auto t0 = std::chrono::steady_clock::now();
  const int d = space.dim();
  if (int(start.size()) != d || !space.isFree(start))
    throw std::invalid_argument("start is not a free point");
  if (int(goal.size()) != d || !space.isFree(goal))
    throw std::invalid_argument("goal is not a free point");
  if (settings.families.empty()) throw std::invalid_argument("no manifold family");
  for (const auto& f : settings.families)
    for (int axis : f)
      if (axis < 0 || axis >= d) throw std::invalid_argument("family fixes an axis out of range");
  for (int f : settings.queryFamilies)
    if (f < 0 || f >= int(settings.families.size()))
      throw std::invalid_argument("query family out of range");

  std::vector<Manifold> manifolds;
  ConnectivityGraph graph;
  EuclideanMmsResult result;

  auto add = [&](size_t family, Point point) {
    Manifold m{family, SubspaceCells(space, subspaceFixing(settings.families[family], point)),
               graph.nodeCount()};
    uint32_t index = uint32_t(manifolds.size());
    for (size_t c = 0; c < m.cells.components(); ++c) graph.addNode({index, uint32_t(c)});
    result.cells += m.cells.cellCount();
    // Every earlier manifold of another family it meets: each FSC of the intersection lies in
    // one FSC of each, so one representative point per FSC joins them.
    for (const Manifold& other : manifolds) {
      if (other.family == family) continue;
      std::optional<AxisSubspace> common = intersect(m.cells.subspace(), other.cells.subspace());
      if (!common) continue;
      SubspaceCells meet(space, *common);
      for (const Point& p : meet.representatives()) {
        int a = m.cells.locate(p), b = other.cells.locate(p);
        if (a >= 0 && b >= 0) graph.addEdge(m.firstNode + a, other.firstNode + b);
      }
    }
    manifolds.push_back(std::move(m));
  };

  // The query manifolds, and the FSCs holding start and goal.
  std::vector<size_t> startNodes, goalNodes;
  for (int f : settings.queryFamilies) {
    for (const Point* q : {&start, &goal}) {
      add(size_t(f), *q);
      const Manifold& m = manifolds.back();
      int c = m.cells.locate(*q);
      if (c < 0) throw std::logic_error("query point not in its own manifold's free space");
      (q == &start ? startNodes : goalNodes).push_back(m.firstNode + c);
    }
  }
  auto connected = [&] {
    for (size_t s : startNodes)
      for (size_t g : goalNodes)
        if (graph.connected(s, g)) return true;
    return false;
  };

  Random random(settings.seed);
  size_t round = 0;
  for (; !connected() && round < settings.maxRounds; ++round)
    for (size_t f = 0; f < settings.families.size(); ++f) {
      Point p(d);
      for (double& v : p) v = random.uniform();
      add(f, std::move(p));
    }
  if (connected()) result.rounds = round;
  result.manifolds = manifolds.size();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

std::vector<std::vector<int>> perpendicularFamilies(int d, int k) {
  if (k < 1 || k >= d) throw std::invalid_argument("k must be in 1..d-1");
  std::vector<int> a, b;
  for (int i = 0; i < d; ++i) (i < k ? a : b).push_back(i);
  return {a, b};
}

std::vector<std::vector<int>> linesAndPlanes3d() { return {{0}, {1}, {2}, {1, 2}, {0, 2}, {0, 1}}; }

}  // namespace mms::lab
