#include "geometry/Predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <vector>

namespace mms {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P = K::Point_2;

P pt(Vec2 v) { return P(v.x, v.y); }

std::vector<P> points(const Ring& ring) {
  std::vector<P> out;
  out.reserve(ring.size());
  for (Vec2 v : ring) out.push_back(pt(v));
  return out;
}

bool edgesMeet(const std::vector<P>& p, size_t i, size_t j) {
  const size_t n = p.size();
  const P &a = p[i], &b = p[(i + 1) % n], &c = p[j], &d = p[(j + 1) % n];
  if ((i + 1) % n == j) {  // adjacent: share b == c; overlap iff they fold back on a line
    return CGAL::collinear(a, b, d) && !CGAL::collinear_are_ordered_along_line(a, b, d);
  }
  if ((j + 1) % n == i) {  // adjacent the other way: share d == a
    return CGAL::collinear(c, a, b) && !CGAL::collinear_are_ordered_along_line(c, a, b);
  }
  return CGAL::do_intersect(K::Segment_2(a, b), K::Segment_2(c, d));
}

}  // namespace

bool allCollinear(const Ring& ring) {
  for (size_t i = 2; i < ring.size(); ++i)
    if (!CGAL::collinear(pt(ring[0]), pt(ring[1]), pt(ring[i]))) return false;
  return true;
}

std::optional<std::pair<size_t, size_t>> findRepeatedVertex(const Ring& ring) {
  std::vector<size_t> order(ring.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  auto key = [&](size_t i) { return std::pair(ring[i].x, ring[i].y); };
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return key(a) < key(b); });
  for (size_t k = 1; k < order.size(); ++k)
    if (ring[order[k]] == ring[order[k - 1]])
      return std::pair(std::min(order[k], order[k - 1]), std::max(order[k], order[k - 1]));
  return std::nullopt;
}

std::optional<std::pair<size_t, size_t>> findSelfIntersection(const Ring& ring) {
  const std::vector<P> p = points(ring);
  const size_t n = p.size();
  constexpr size_t kPairwiseLimit = 4000;
  if (n > kPairwiseLimit) {  // sweep-line test only; the pair is not located
    if (CGAL::is_simple_2(p.begin(), p.end(), K())) return std::nullopt;
    return std::pair(n, n);
  }
  std::vector<Box> boxes(n);
  for (size_t i = 0; i < n; ++i) boxes[i] = boundingBox(Ring{ring[i], ring[(i + 1) % n]});
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j)
      if (boxes[i].overlaps(boxes[j]) && edgesMeet(p, i, j)) return std::pair(i, j);
  return std::nullopt;
}

bool isCounterClockwise(const Ring& ring) {
  const std::vector<P> p = points(ring);
  return CGAL::orientation_2(p.begin(), p.end(), K()) == CGAL::COUNTERCLOCKWISE;
}

}  // namespace mms
