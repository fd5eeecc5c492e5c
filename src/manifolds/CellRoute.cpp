#include "manifolds/CellRoute.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <tuple>

#include "mms/Termination.h"

namespace mms {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  bool inside = false;
  int visitedFrom = -2;  // -2: unvisited; -1: root; else index of the edge crossed to get here
  double reached = std::numeric_limits<double>::infinity();  // a shortest search's distance
};
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Face = CDT::Face_handle;
using P = K::Point_2;

Vec2 toVec(const P& p) { return {p.x(), p.y()}; }

// The cell triangulated, each triangle marked inside or not. A cell among thousands of
// obstacles takes seconds to triangulate and classify: the planner's time limit is checked as
// it goes (checkpoint throws Stopped).
void triangulate(CDT& cdt, const std::vector<Ring>& rings,
                 const std::function<bool(Vec2)>& inCell) {
  size_t steps = 0;
  for (const Ring& r : rings)
    for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
      if (++steps % 16 == 0) checkpoint();
      if (!(r[j] == r[i])) cdt.insert_constraint(P(r[j].x, r[j].y), P(r[i].x, r[i].y));
    }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (++steps % 16 == 0) checkpoint();
    const Vec2 c = (1.0 / 3) * (toVec(f->vertex(0)->point()) + toVec(f->vertex(1)->point()) +
                                toVec(f->vertex(2)->point()));
    f->info().inside = inCell(c);
  }
}

// The inside triangle holding p, also where p lies on an edge.
std::optional<Face> insideFace(const CDT& cdt, Vec2 p) {
  Face f = cdt.locate(P(p.x, p.y));
  if (f == nullptr || cdt.is_infinite(f)) return std::nullopt;
  if (f->info().inside) return f;
  for (int i = 0; i < 3; ++i) {  // p on an edge: the other side may be the inside one
    Face g = f->neighbor(i);
    if (!cdt.is_infinite(g) && g->info().inside &&
        cdt.triangle(g).bounded_side(P(p.x, p.y)) != CGAL::ON_UNBOUNDED_SIDE)
      return g;
  }
  return std::nullopt;
}

// Whether the search may cross edge i of f: into an inside triangle, never across a
// constraint (the cell's boundary).
bool crossable(const CDT& cdt, Face f, int i) {
  const Face g = f->neighbor(i);
  return !cdt.is_infinite(g) && g->info().inside && !f->is_constrained(i);
}

Vec2 edgeMidpoint(Face f, int i) {
  return 0.5 * (toVec(f->vertex(CDT::cw(i))->point()) + toVec(f->vertex(CDT::ccw(i))->point()));
}

// Fewest triangles from `from` to `to` (breadth first); whether `to` was reached.
bool fewestTriangles(const CDT& cdt, Face from, Face to) {
  std::deque<Face> queue{from};
  from->info().visitedFrom = -1;
  while (!queue.empty() && to->info().visitedFrom == -2) {
    Face f = queue.front();
    queue.pop_front();
    for (int i = 0; i < 3; ++i) {
      Face g = f->neighbor(i);
      if (!crossable(cdt, f, i) || g->info().visitedFrom != -2) continue;
      g->info().visitedFrom = g->index(f);
      queue.push_back(g);
    }
  }
  return to->info().visitedFrom != -2;
}

// Shortest from `a` (in `from`) to `to` along the midpoints of the edges crossed (Dijkstra);
// whether `to` was reached.
bool shortestTriangles(const CDT& cdt, Face from, Face to, Vec2 a) {
  using Item = std::pair<double, Face>;
  auto later = [](const Item& x, const Item& y) { return x.first > y.first; };
  std::priority_queue<Item, std::vector<Item>, decltype(later)> queue(later);
  from->info().visitedFrom = -1;
  from->info().reached = 0;
  queue.emplace(0.0, from);
  while (!queue.empty()) {
    const auto [d, f] = queue.top();
    queue.pop();
    if (d > f->info().reached) continue;
    if (f == to) return true;
    const int in = f->info().visitedFrom;
    const Vec2 at = in < 0 ? a : edgeMidpoint(f, in);
    for (int i = 0; i < 3; ++i) {
      Face g = f->neighbor(i);
      if (!crossable(cdt, f, i)) continue;
      const double e = d + norm(edgeMidpoint(f, i) - at);
      if (e >= g->info().reached) continue;
      g->info().reached = e;
      g->info().visitedFrom = g->index(f);
      queue.emplace(e, g);
    }
  }
  return false;
}

// The edges crossed from the root to `to`, in order, each as (left, right) seen going along.
std::vector<std::pair<Vec2, Vec2>> portals(Face to) {
  std::vector<std::pair<Vec2, Vec2>> back;
  for (Face f = to; f->info().visitedFrom != -1;) {
    const int i = f->info().visitedFrom;  // edge i of f (opposite vertex i) leads back
    // f lies to the left of its edge from ccw(i) to cw(i): going into f, ccw(i) is on the left.
    back.emplace_back(toVec(f->vertex(CDT::ccw(i))->point()),
                      toVec(f->vertex(CDT::cw(i))->point()));
    f = f->neighbor(i);
  }
  return {back.rbegin(), back.rend()};
}

std::vector<Vec2> throughMidpoints(Vec2 a, const std::vector<std::pair<Vec2, Vec2>>& gates,
                                   Vec2 b) {
  std::vector<Vec2> out{a};
  for (const auto& [l, r] : gates) out.push_back(0.5 * (r + l));
  out.push_back(b);
  return out;
}

// How much of a gate, at each end, a pulled route keeps off: it bends at the middle half.
constexpr double kPulledMargin = 0.25;

// The shortest way from a to b through the gates (the funnel algorithm): the way bends only
// at gates' ends. Each bend moves the funnel's apex to a later gate, so it ends.
std::vector<Vec2> pulledThrough(Vec2 a, std::vector<std::pair<Vec2, Vec2>> gates, Vec2 b) {
  gates.emplace_back(b, b);
  std::vector<Vec2> out{a};
  Vec2 apex = a, left = a, right = a;
  size_t leftAt = 0, rightAt = 0;
  for (size_t i = 0; i < gates.size(); ++i) {
    const auto [l, r] = gates[i];
    if (cross(right - apex, r - apex) >= 0) {  // r narrows the funnel from the right
      if (apex == right || cross(left - apex, r - apex) < 0) {
        right = r;
        rightAt = i;
      } else {  // r crosses over the left side: the way bends at the left corner
        if (!(out.back() == left)) out.push_back(left);
        apex = right = left;
        i = rightAt = leftAt;
        continue;
      }
    }
    if (cross(left - apex, l - apex) <= 0) {  // l narrows the funnel from the left
      if (apex == left || cross(right - apex, l - apex) > 0) {
        left = l;
        leftAt = i;
      } else {
        if (!(out.back() == right)) out.push_back(right);
        apex = left = right;
        i = leftAt = rightAt;
        continue;
      }
    }
  }
  if (!(out.back() == b)) out.push_back(b);
  return out;
}

}  // namespace

std::optional<std::vector<Vec2>> routeInCell(const std::vector<Ring>& rings,
                                             const std::function<bool(Vec2)>& inCell, Vec2 a,
                                             Vec2 b, RouteShape shape) {
  CDT cdt;
  triangulate(cdt, rings, inCell);
  const auto fa = insideFace(cdt, a), fb = insideFace(cdt, b);
  if (!fa || !fb) return std::nullopt;
  if (shape == RouteShape::Midpoints) {
    if (!fewestTriangles(cdt, *fa, *fb)) return std::nullopt;
    return throughMidpoints(a, portals(*fb), b);
  }
  if (!shortestTriangles(cdt, *fa, *fb, a)) return std::nullopt;
  // Each gate narrowed to its middle, so that the way keeps off the cell's corners.
  std::vector<std::pair<Vec2, Vec2>> gates = portals(*fb);
  for (auto& [l, r] : gates) {
    const Vec2 d = kPulledMargin * (r - l);
    std::tie(l, r) = std::pair{l + d, r - d};
  }
  return pulledThrough(a, gates, b);
}

}  // namespace mms
