#include "manifolds/CellRoute.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <deque>
#include <map>

#include "mms/Termination.h"

namespace mms {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  bool inside = false;
  int visitedFrom = -2;  // -2: unvisited; -1: root; else index of the edge crossed to get here
};
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using P = K::Point_2;

Vec2 toVec(const P& p) { return {p.x(), p.y()}; }

}  // namespace

std::optional<std::vector<Vec2>> routeInCell(const std::vector<Ring>& rings,
                                             const std::function<bool(Vec2)>& inCell, Vec2 a,
                                             Vec2 b) {
  // A cell among thousands of obstacles takes seconds to triangulate and classify: the
  // planner's time limit is checked as it goes (checkpoint throws Stopped).
  CDT cdt;
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
  auto insideFace = [&](Vec2 p) -> std::optional<CDT::Face_handle> {
    CDT::Face_handle f = cdt.locate(P(p.x, p.y));
    if (f == nullptr || cdt.is_infinite(f)) return std::nullopt;
    if (f->info().inside) return f;
    for (int i = 0; i < 3; ++i) {  // p on an edge: the other side may be the inside one
      CDT::Face_handle g = f->neighbor(i);
      if (!cdt.is_infinite(g) && g->info().inside &&
          cdt.triangle(g).bounded_side(P(p.x, p.y)) != CGAL::ON_UNBOUNDED_SIDE)
        return g;
    }
    return std::nullopt;
  };
  const auto fa = insideFace(a), fb = insideFace(b);
  if (!fa || !fb) return std::nullopt;

  // Breadth-first over inside triangles, never across a constraint (the cell's boundary).
  std::deque<CDT::Face_handle> queue{*fa};
  (*fa)->info().visitedFrom = -1;
  while (!queue.empty() && (*fb)->info().visitedFrom == -2) {
    CDT::Face_handle f = queue.front();
    queue.pop_front();
    for (int i = 0; i < 3; ++i) {
      CDT::Face_handle g = f->neighbor(i);
      if (cdt.is_infinite(g) || !g->info().inside || g->info().visitedFrom != -2 ||
          f->is_constrained(i))
        continue;
      g->info().visitedFrom = g->index(f);
      queue.push_back(g);
    }
  }
  if ((*fb)->info().visitedFrom == -2) return std::nullopt;

  std::vector<Vec2> back{b};
  for (CDT::Face_handle f = *fb; f->info().visitedFrom != -1;) {
    const int i = f->info().visitedFrom;  // edge i of f (opposite vertex i) leads back
    const Vec2 p = toVec(f->vertex(CDT::cw(i))->point()),
               q = toVec(f->vertex(CDT::ccw(i))->point());
    back.push_back(0.5 * (p + q));
    f = f->neighbor(i);
  }
  back.push_back(a);
  return std::vector<Vec2>(back.rbegin(), back.rend());
}

}  // namespace mms
