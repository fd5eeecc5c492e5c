#include "path/GridRoute.h"

#include <algorithm>
#include <boost/graph/astar_search.hpp>
#include <boost/graph/grid_graph.hpp>
#include <boost/property_map/function_property_map.hpp>
#include <cmath>
#include <limits>

#include "check/PathChecker.h"

namespace mms {

namespace {

using Grid = boost::grid_graph<2>;
using Cell = boost::graph_traits<Grid>::vertex_descriptor;
using Step = boost::graph_traits<Grid>::edge_descriptor;

struct Reached {};  // the goal cell is examined: the search ends
struct GaveUp {};   // out of placements to test, or stopped

// The grid's cells, each tested once and only when the search reaches it: a search towards a
// goal in open space tests a band of cells, not the grid.
class GridSearch {
 public:
  GridSearch(const CollisionChecker& checker, const Box& bounds, double theta,
             const GridRouteSettings& settings, const Termination& stop)
      : checker_(checker),
        theta_(theta),
        settings_(settings),
        stop_(stop),
        bounds_(bounds),
        grid_(boost::array<size_t, 2>{
            {extent(bounds.xmax - bounds.xmin), extent(bounds.ymax - bounds.ymin)}}),
        state_(num_vertices(grid_), Unknown),
        barred_(num_vertices(grid_), 0),
        previous_(num_vertices(grid_)),
        distance_(num_vertices(grid_), kNoStep),
        rank_(num_vertices(grid_), kNoStep),
        colour_(num_vertices(grid_), boost::white_color) {}

  Vec2 centre(const Cell& c) const {
    return {bounds_.xmin + (double(c[0]) + 0.5) * settings_.cell,
            bounds_.ymin + (double(c[1]) + 0.5) * settings_.cell};
  }
  Cell cellOf(Vec2 p) const {
    auto at = [&](double v, double lo, size_t dim) {
      const double k = std::floor((v - lo) / settings_.cell);
      return size_t(std::clamp(k, 0.0, double(grid_.length(dim) - 1)));
    };
    return {{at(p.x, bounds_.xmin, 0), at(p.y, bounds_.ymin, 1)}};
  }
  bool free(const Cell& c) {
    uint8_t& s = state_[get(boost::vertex_index, grid_, c)];
    if (s == Unknown) {
      if (checks_++ == settings_.maxChecks || stop_()) throw GaveUp{};
      const Vec2 p = centre(c);
      s = checker_.robotFree(0, {p.x, p.y, theta_}) ? Free : Blocked;
    }
    return s == Free;
  }
  /// No walk steps between these two neighbouring cells any more.
  void bar(const Cell& u, const Cell& v) {
    barred_[get(boost::vertex_index, grid_, u)] |= direction(u, v);
    barred_[get(boost::vertex_index, grid_, v)] |= direction(v, u);
  }
  /// The cost of a step from u into its neighbour v: infinite where v is blocked or the step
  /// barred.
  double stepCost(const Cell& u, const Cell& v) {
    if (barred_[get(boost::vertex_index, grid_, u)] & direction(u, v)) return kNoStep;
    return free(v) ? 1.0 : kNoStep;
  }
  static constexpr double kNoStep = std::numeric_limits<double>::infinity();
  /// The cells of a walk from `from` to `to` (both free), both included.
  std::optional<std::vector<Cell>> walk(const Cell& from, const Cell& to);

 private:
  size_t extent(double length) const {
    return std::max<size_t>(1, size_t(std::ceil(length / settings_.cell)));
  }
  static uint8_t direction(const Cell& u, const Cell& v) {
    return v[0] > u[0] ? 1 : v[0] < u[0] ? 2 : v[1] > u[1] ? 4 : 8;
  }
  enum : uint8_t { Unknown, Free, Blocked };
  const CollisionChecker& checker_;
  double theta_;
  const GridRouteSettings& settings_;
  const Termination& stop_;
  Box bounds_;
  Grid grid_;
  std::vector<uint8_t> state_;
  std::vector<uint8_t> barred_;  // per cell, the directions of its barred steps
  size_t checks_ = 0;
  // The search's maps, made once for all walks; a walk resets only the cells it discovered
  // (a search towards a goal in open space meets a band of cells, where Boost's own setup
  // would fill every map over the whole grid, walk after walk).
  std::vector<Cell> previous_;
  std::vector<double> distance_, rank_;
  std::vector<boost::default_color_type> colour_;
  std::vector<size_t> discovered_;
};

// Steps in a 4-connected grid, weighted: the walk is pulled tight and shortened afterwards, so
// it need not be the shortest, and a greedier search tests a band of cells towards the goal
// instead of the diamond of equally short walks (open clutter, tuning scenes: without it a
// third of the routes ran out of tests and fell back to slices).
struct Manhattan : boost::astar_heuristic<Grid, double> {
  static constexpr double kGreed = 2;
  Cell goal;
  double operator()(const Cell& c) const {
    auto d = [](size_t a, size_t b) { return double(a > b ? a - b : b - a); };
    return kGreed * (d(c[0], goal[0]) + d(c[1], goal[1]));
  }
};

// Boost's search queues every cell it meets, a blocked one too (at an infinite distance), and
// goes on to those once the reachable ones are spent: the first of them examined ends the
// search without a way.
struct EndAtGoal : boost::default_astar_visitor {
  Cell goal;
  const std::vector<double>* distance;
  std::vector<size_t>* discovered;  // every cell whose maps the search wrote
  void discover_vertex(const Cell& c, const Grid& grid) const {
    discovered->push_back(get(boost::vertex_index, grid, c));
  }
  void examine_vertex(const Cell& c, const Grid& grid) const {
    if (std::isinf((*distance)[get(boost::vertex_index, grid, c)])) throw GaveUp{};
    if (c == goal) throw Reached{};
  }
};

std::optional<std::vector<Cell>> GridSearch::walk(const Cell& from, const Cell& to) {
  const auto index = get(boost::vertex_index, grid_);
  // A step into a blocked cell costs infinity, which relaxes nothing: the graph stays the
  // plain grid and a cell is tested only when a step into it is weighed.
  const auto weight = boost::make_function_property_map<Step, double>(
      [this](const Step& e) { return stepCost(source(e, grid_), target(e, grid_)); });
  const Manhattan toGoal{{}, to};
  distance_[index[from]] = 0;
  rank_[index[from]] = toGoal(from);
  discovered_.clear();
  bool reached = false;
  try {
    boost::astar_search_no_init(
        grid_, from, toGoal,
        boost::visitor(EndAtGoal{{}, to, &distance_, &discovered_})
            .predecessor_map(make_iterator_property_map(previous_.begin(), index))
            .rank_map(make_iterator_property_map(rank_.begin(), index))
            .distance_map(make_iterator_property_map(distance_.begin(), index))
            .color_map(make_iterator_property_map(colour_.begin(), index))
            .weight_map(weight)
            .distance_inf(kNoStep));
    // (Ending here, the search ran out of cells: no way on the grid.)
  } catch (const Reached&) {
    reached = true;
  } catch (const GaveUp&) {
  }
  std::optional<std::vector<Cell>> cells;
  if (reached) {
    cells.emplace(1, to);
    while (cells->back() != from) cells->push_back(previous_[index[cells->back()]]);
    std::reverse(cells->begin(), cells->end());
  }
  for (size_t i : discovered_) {
    distance_[i] = rank_[i] = kNoStep;
    colour_[i] = boost::white_color;
  }
  return cells;
}

// The walk pulled tight: from each point kept, on to the furthest point of the walk that the
// certifier proves reachable in a straight motion, found by doubling the reach and halving
// back (a point between two reachable ones is not always reachable, so the furthest is not
// guaranteed, only a reachable one; the optimiser's shortcuts take what is left). Where a
// point does not reach the next, nothing, and `failed` names it.
std::optional<std::vector<Vec2>> pulledTight(const CollisionChecker& checker, double theta,
                                             const std::vector<Vec2>& points,
                                             const Termination& stop, size_t& failed) {
  auto reaches = [&](size_t i, size_t j) {
    return motionFree(checker, {points[i].x, points[i].y, theta},
                      {points[j].x, points[j].y, theta});
  };
  std::vector<Vec2> out{points.front()};
  for (size_t i = 0; i + 1 < points.size();) {
    if (stop()) throw GaveUp{};
    if (!reaches(i, i + 1)) {
      failed = i;
      return std::nullopt;
    }
    size_t good = i + 1, step = 1;
    while (good + step < points.size() && reaches(i, good + step)) good += step, step *= 2;
    size_t bad = std::min(good + step, points.size());  // unreachable, or past the end
    while (bad - good > 1) {
      const size_t mid = good + (bad - good) / 2;
      (reaches(i, mid) ? good : bad) = mid;
    }
    out.push_back(points[good]);
    i = good;
  }
  return out;
}

}  // namespace

// Steps are tested only on the walks found: a step between two free centres that cuts an
// obstacle's corner is barred and the walk searched again, up to kWalks times (the cells
// already tested are not tested again).
std::optional<std::vector<Vec2>> gridRoute(const CollisionChecker& checker, const Box& bounds,
                                           double theta, Vec2 a, Vec2 b,
                                           const GridRouteSettings& settings,
                                           const Termination& stop) {
  constexpr size_t kWalks = 8;
  if (!(settings.cell > 0) || !bounds.contains(a) || !bounds.contains(b)) return std::nullopt;
  GridRouteSettings sized = settings;
  const double area = (bounds.xmax - bounds.xmin) * (bounds.ymax - bounds.ymin);
  const double side = bounds.xmax - bounds.xmin + bounds.ymax - bounds.ymin;
  // Cells of side c cover the box in at most (w/c + 1)(h/c + 1) <= area/c^2 + side/c + 1.
  while (area / (sized.cell * sized.cell) + side / sized.cell + 1 > double(sized.maxCells))
    sized.cell *= 1.25;
  GridSearch search(checker, bounds, theta, sized, stop);
  const Cell from = search.cellOf(a), to = search.cellOf(b);
  try {
    if (!search.free(from) || !search.free(to)) return std::nullopt;
    for (size_t walks = 0; walks < kWalks; ++walks) {
      const std::optional<std::vector<Cell>> cells = search.walk(from, to);
      if (!cells) return std::nullopt;
      std::vector<Vec2> points{a};
      for (const Cell& c : *cells) points.push_back(search.centre(c));
      points.push_back(b);
      size_t failed = 0;
      if (auto route = pulledTight(checker, theta, points, stop, failed)) return route;
      // Point k of the walk is cell k - 1: only a step between two cells can be barred.
      if (failed == 0 || failed + 2 >= points.size()) return std::nullopt;
      search.bar((*cells)[failed - 1], (*cells)[failed]);
    }
  } catch (const GaveUp&) {
  }
  return std::nullopt;
}

}  // namespace mms
