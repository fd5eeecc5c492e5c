#include "planner/PebbleMotion.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <queue>
#include <string>
#include <unordered_map>

#include "check/PathChecker.h"
#include "geometry/PolygonOps.h"
#include "util/Random.h"

namespace mms {

namespace {

struct Edge {
  uint32_t to;
  double length;
  std::vector<uint32_t> blockers;  // vertices whose robot the move would meet
};

struct Graph {
  std::vector<Vec2> at;
  std::vector<std::vector<Edge>> out;
};

// Points hashed into square cells of a side, for the points near a point: those in the cells up
// to two away (everything within two sides, and some further).
class PointGrid {
 public:
  explicit PointGrid(double side) : side_(side) {}
  void add(Vec2 p, uint32_t id) { cells_[cell(p)].push_back(id); }
  template <class Visit>
  void near(Vec2 p, const Visit& visit) const {
    const auto [cx, cy] = cell(p);
    for (long long dx = -2; dx <= 2; ++dx)
      for (long long dy = -2; dy <= 2; ++dy)
        if (const auto it = cells_.find({cx + dx, cy + dy}); it != cells_.end())
          for (uint32_t id : it->second) visit(id);
  }

 private:
  std::pair<long long, long long> cell(Vec2 p) const {
    return {std::llround(std::floor(p.x / side_)), std::llround(std::floor(p.y / side_))};
  }
  double side_;
  std::map<std::pair<long long, long long>, std::vector<uint32_t>> cells_;
};

// One robot-width: two robots of the shape this far apart never overlap.
double width(const Scene& scene) {
  const Robot& r = scene.robots[0];
  return 2 * (r.disc > 0 ? r.disc : radius(r.shape));
}

// The grid's spacing: one robot-width, or wider where that would take more than half the
// vertices.
double gridSpacing(const Scene& scene, size_t maxVertices) {
  const Box& b = scene.bounds;
  return std::max(width(scene), std::sqrt(b.width() * b.height() / (0.5 * double(maxVertices))));
}

// Where the robots stand and their goals; then free placements one width from those, clear of
// every placement so far (so that they never block each other): along the square and
// hexagonal lattices of the axes and of the directions to neighbouring placements, which finds
// the empty cells of a packed crowd whichever way it is turned; then a grid over the free space.
std::vector<Vec2> placements(const Scene& scene, const CollisionChecker& checker,
                             const Config& from, size_t maxVertices) {
  const double s = width(scene), theta = from[2];
  std::vector<Vec2> at;
  PointGrid grid(s);
  auto within = [&](Vec2 p, double d, auto&& visit) {
    grid.near(p, [&](uint32_t v) {
      if (norm(at[v] - p) < d) visit(v);
    });
  };
  auto add = [&](Vec2 p) {
    grid.add(p, uint32_t(at.size()));
    at.push_back(p);
  };
  for (size_t i = 0; i < scene.robots.size(); ++i) add({from[3 * i], from[3 * i + 1]});
  for (const Robot& r : scene.robots) {
    bool known = false;
    within({r.goal.x, r.goal.y}, 1e-300, [&](size_t) { known = true; });
    if (!known) add({r.goal.x, r.goal.y});
  }
  auto addClear = [&](Vec2 p) {
    if (at.size() >= maxVertices) return;
    bool clear = true;
    within(p, s * (1 - 1e-9), [&](size_t) { clear = false; });
    if (clear && checker.robotFree(0, {p.x, p.y, theta})) add(p);
  };
  const size_t base = at.size();
  for (size_t v = 0; v < base; ++v) {
    std::vector<double> angles{0};
    within(at[v], 1.5 * s, [&](size_t w) {
      if (w < base && w != v) angles.push_back(std::atan2(at[w].y - at[v].y, at[w].x - at[v].x));
    });
    for (double a : angles)
      for (int k = 0; k < 12; ++k)
        if (k % 3 == 0 || k % 2 == 0) {  // quarter and sixth turns
          const double b = a + k * M_PI / 6;
          addClear(at[v] + s * Vec2{std::cos(b), std::sin(b)});
        }
  }
  // A grid over the free space joins the crowds, in the room left.
  const Box& b = scene.bounds;
  const double h = gridSpacing(scene, maxVertices);
  for (double y = b.ymin + h / 2; y < b.ymax; y += h)
    for (double x = b.xmin + h / 2; x < b.xmax; x += h) addClear({x, y});
  return at;
}

// Vertices near each other joined by the straight translations the obstacles leave free, each
// with the vertices that block it.
Graph build(const Scene& scene, const Config& from, std::vector<Vec2> at, size_t maxVertices,
            const Termination& stop) {
  const double s = width(scene), theta = from[2];
  const double reach = 1.5 * gridSpacing(scene, maxVertices);
  Scene alone = scene, pair;
  alone.robots.resize(1);
  pair.bounds = scene.bounds;
  pair.robots = {scene.robots[0], scene.robots[0]};
  pair.robots[1].name += "-other";
  const CollisionChecker aloneChecker(alone), pairChecker(pair);
  Graph g;
  g.at = std::move(at);
  const size_t n = g.at.size();
  g.out.resize(n);
  PointGrid grid(reach);
  for (uint32_t v = 0; v < n; ++v) grid.add(g.at[v], v);
  for (uint32_t u = 0; u < n && !stop(); ++u)
    grid.near(g.at[u], [&](uint32_t v) {
      const Vec2 a = g.at[u], b = g.at[v];
      if (v <= u || norm(b - a) > reach) return;
      if (!motionFree(aloneChecker, {a.x, a.y, theta}, {b.x, b.y, theta})) return;
      Edge e{v, norm(b - a), {}};
      grid.near(a + 0.5 * (b - a), [&](uint32_t w) {
        if (w == u || pointSegmentDistance(g.at[w], a, b) >= s) return;
        const Vec2 c = g.at[w];
        if (w == v || !motionFree(pairChecker, {a.x, a.y, theta, c.x, c.y, theta},
                                  {b.x, b.y, theta, c.x, c.y, theta}, true))
          e.blockers.push_back(w);
      });
      // The way back meets the same robots, with the ends' roles swapped.
      Edge back{u, e.length, e.blockers};
      for (uint32_t& w : back.blockers)
        if (w == v) w = u;
      g.out[u].push_back(std::move(e));
      g.out[v].push_back(std::move(back));
    });
  return g;
}

// Shortest length in the graph from every vertex to `goal`, blockers ignored.
std::vector<double> distancesTo(const Graph& g, uint32_t goal) {
  std::vector<double> d(g.at.size(), INFINITY);
  using Item = std::pair<double, uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  d[goal] = 0;
  open.push({0, goal});
  while (!open.empty()) {
    const auto [du, u] = open.top();
    open.pop();
    if (du > d[u]) continue;
    for (const Edge& e : g.out[u])
      if (du + e.length < d[e.to]) open.push({d[e.to] = du + e.length, e.to});
  }
  return d;
}

double shortestEdge(const Graph& g) {
  double shortest = INFINITY;
  for (const auto& out : g.out)
    for (const Edge& e : out) shortest = std::min(shortest, e.length);
  return shortest;
}

using State = std::u16string;  // each robot's vertex

// A move along e is legal when no robot stands where the move would meet it.
bool clearOf(const Edge& e, const std::vector<int>& occupant) {
  for (uint32_t w : e.blockers)
    if (occupant[w] >= 0) return false;
  return true;
}

// `count` legal moves of robots chosen at random, none undoing the one before.
std::vector<std::pair<size_t, uint32_t>> randomWalk(const Graph& g, const State& from, size_t count,
                                                    Random& rng) {
  std::vector<std::pair<size_t, uint32_t>> steps;
  State s = from;
  std::vector<int> occupant(g.at.size(), -1);
  for (size_t i = 0; i < s.size(); ++i) occupant[s[i]] = int(i);
  std::vector<std::pair<size_t, uint32_t>> legal;
  for (size_t n = 0; n < count; ++n) {
    legal.clear();
    for (size_t i = 0; i < s.size(); ++i)
      for (const Edge& e : g.out[s[i]])
        if (!(steps.size() && steps.back().first == i) && clearOf(e, occupant))
          legal.emplace_back(i, e.to);
    if (legal.empty()) break;
    const auto [robot, to] = legal[rng.below(legal.size())];
    occupant[s[robot]] = -1;
    occupant[to] = int(robot);
    s[robot] = char16_t(to);
    steps.emplace_back(robot, to);
  }
  return steps;
}

struct Search {
  const Graph& g;
  std::vector<std::vector<double>> dist;  // per robot, to its goal
  // A robot off its goal adds at least one edge's length to the heuristic, which its updates
  // along a search round by far less than this.
  double done = 0;
  struct Node {
    uint32_t parent;
    uint16_t robot;
    uint32_t to;
    double cost, h;
  };
  std::vector<Node> nodes;
  std::vector<State> states;
  std::unordered_map<State, uint32_t> index;

  double h(const State& s) const {
    double sum = 0;
    for (size_t i = 0; i < s.size(); ++i) sum += dist[i][s[i]];
    return sum;
  }

  struct Leg {
    std::vector<std::pair<size_t, uint32_t>> moves;  // (robot, vertex) in order
    double h = 0;                                    // left at the leg's end; 0 at the goal
  };
  // Moves from `start` to a state whose heuristic is 0 or, when `budget` states are spent or
  // `stop` ends, to the state of least heuristic seen (the next search restarts there).
  Leg run(State start, double weight, size_t budget, const Termination& stop) {
    using Item = std::tuple<double, int64_t, uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    nodes.assign(1, {0, 0, 0, 0, h(start)});
    states.assign(1, start);
    index.clear();
    index.emplace(std::move(start), 0);
    open.push({weight * nodes[0].h, 0, 0});
    uint32_t best = 0;
    std::vector<int> occupant(g.at.size(), -1);
    for (int64_t pushed = 1; !open.empty() && states.size() < budget;) {
      const uint32_t id = std::get<2>(open.top());
      open.pop();
      if (nodes[id].h < nodes[best].h) best = id;
      if (nodes[id].h <= done || ((pushed & 255) == 0 && stop())) break;
      const State s = states[id];
      for (size_t i = 0; i < s.size(); ++i) occupant[s[i]] = int(i);
      for (size_t i = 0; i < s.size(); ++i)
        for (const Edge& e : g.out[s[i]]) {
          if (!clearOf(e, occupant)) continue;
          State t = s;
          t[i] = char16_t(e.to);
          if (index.count(t)) continue;
          const double ht = nodes[id].h - dist[i][s[i]] + dist[i][e.to];
          const double cost = nodes[id].cost + e.length;
          nodes.push_back({id, uint16_t(i), e.to, cost, std::max(0.0, ht)});
          index.emplace(t, uint32_t(states.size()));
          states.push_back(std::move(t));
          // Ties to the newest state: depth first along a plateau of the heuristic.
          open.push({cost + weight * nodes.back().h, -pushed, uint32_t(states.size() - 1)});
          ++pushed;
        }
      for (size_t i = 0; i < s.size(); ++i) occupant[s[i]] = -1;
    }
    return {movesTo(best), nodes[best].h};
  }

  std::vector<std::pair<size_t, uint32_t>> movesTo(uint32_t id) const {
    std::vector<std::pair<size_t, uint32_t>> moves;
    for (; id != 0; id = nodes[id].parent) moves.emplace_back(nodes[id].robot, nodes[id].to);
    return {moves.rbegin(), moves.rend()};
  }
};

}  // namespace

bool pebbleApplies(const Scene& scene, const Config& from) {
  if (scene.robots.size() < 2 || scene.robots.size() > 0xffff) return false;
  const Robot& first = scene.robots[0];
  for (size_t i = 0; i < scene.robots.size(); ++i) {
    const Robot& r = scene.robots[i];
    if (r.motion != Motion::Translate || r.disc != first.disc || from[3 * i + 2] != from[2] ||
        (first.disc == 0 && r.shape != first.shape))
      return false;
  }
  return true;
}

std::optional<std::vector<Config>> pebbleMotion(const Scene& scene, const CollisionChecker& checker,
                                                const Config& from, const Termination& stop,
                                                PebbleStats& stats,
                                                const PebbleSettings& settings) {
  if (!pebbleApplies(scene, from)) return std::nullopt;
  const Graph g = build(scene, from, placements(scene, checker, from, settings.maxVertices),
                        settings.maxVertices, stop);
  stats.vertices = g.at.size();
  for (const auto& out : g.out) stats.edges += out.size();
  if (stop() || g.at.size() > 0xffff) return std::nullopt;
  // Vertex i is where robot i stands; a goal is the first vertex at its place (a robot's, or
  // its own after them).
  auto vertexOf = [&](Vec2 p) {
    for (uint32_t v = 0; v < g.at.size(); ++v)
      if (g.at[v] == p) return v;
    return uint32_t(g.at.size());
  };
  Search search{g, {}, 0, {}, {}, {}};
  State start;
  std::map<uint32_t, std::vector<double>> byGoal;
  for (size_t i = 0; i < scene.robots.size(); ++i) {
    start.push_back(char16_t(i));
    const uint32_t goal = vertexOf({scene.robots[i].goal.x, scene.robots[i].goal.y});
    if (!byGoal.count(goal)) byGoal[goal] = distancesTo(g, goal);
    search.dist.push_back(byGoal[goal]);
  }
  // Searches of a bounded size, each from where the last came nearest the goal: a crowd that
  // must make way for one robot is searched around that robot's progress, not all at once.
  double best = search.h(start);
  if (!std::isfinite(best)) return std::nullopt;
  std::vector<std::pair<size_t, uint32_t>> moves;
  State now = start;
  size_t walk = 0;
  Random rng(settings.seed);
  search.done = 0.5 * shortestEdge(g);
  for (double left = best; left > search.done;) {
    if (stats.states >= settings.maxStates || stop()) return std::nullopt;
    const size_t budget = std::min(settings.legStates, settings.maxStates - stats.states);
    Search::Leg leg = search.run(now, settings.weight, budget, stop);
    stats.states += search.states.size();
    if (leg.h >= left) {
      // No nearer than where the leg began: a local minimum of the heuristic (robots that must
      // make way for each other far from the empty places). A random walk of the empty places,
      // longer each time, then a search from there.
      walk += walk / 2 + 8;
      const auto steps = randomWalk(g, now, walk, rng);
      for (const auto& [robot, to] : steps) now[robot] = char16_t(to);
      moves.insert(moves.end(), steps.begin(), steps.end());
      left = search.h(now);
      continue;
    }
    for (const auto& [robot, to] : leg.moves) now[robot] = char16_t(to);
    moves.insert(moves.end(), leg.moves.begin(), leg.moves.end());
    left = leg.h;
    if (left < best) best = left, walk = 0;  // walks start short again past a new best
  }
  stats.moves = moves.size();
  std::vector<Config> path{from};
  for (const auto& [robot, to] : moves) {
    Config q = path.back();
    q[3 * robot] = g.at[to].x;
    q[3 * robot + 1] = g.at[to].y;
    path.push_back(std::move(q));
  }
  return path;
}

}  // namespace mms
