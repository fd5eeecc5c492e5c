#include "manifolds/CellSampling.h"

#include <cmath>

#include "geometry/PolygonOps.h"

namespace mms {

std::optional<Vec2> samplePointInCell(const Slice& slice, size_t cell, Random& rng, int tries) {
  const Box b = boundingBox(slice.cell(cell).front());
  for (int i = 0; i < tries; ++i) {
    const Vec2 p = rng.uniformIn(b);
    if (slice.locate(p) == int(cell)) return p;
  }
  return std::nullopt;
}

std::optional<Vec2> pointTowards(const Slice& slice, size_t cell, Vec2 target, Random& rng) {
  if (slice.locate(target) == int(cell)) return target;
  Vec2 nearest = target;
  double best = INFINITY;
  for (const Ring& r : slice.cell(cell))
    for (size_t i = 0; i < r.size(); ++i) {
      const Vec2 c = closestPointOnSegment(target, r[i], r[(i + 1) % r.size()]);
      if (const double d = norm(target - c); d < best) best = d, nearest = c;
    }
  // Step from the boundary point towards points inside the cell, shortest steps first. Not
  // closer than a tenth of the way: a fixing pressed against the boundary leaves the other
  // robot slivers of free space as thin as the contact tolerance, and point location on such
  // slivers decides little.
  for (int attempt = 0; attempt < 4; ++attempt) {
    const auto inside = samplePointInCell(slice, cell, rng, 16);
    if (!inside) break;
    for (const double t : {0.1, 0.3, 0.6}) {
      const Vec2 p = nearest + t * (*inside - nearest);
      if (slice.locate(p) == int(cell)) return p;
    }
  }
  return std::nullopt;
}

std::optional<Vec2> samplePointNearVertex(const Slice& slice, size_t cell, Random& rng, int tries) {
  const std::vector<Ring>& rings = slice.cell(cell);
  size_t total = 0;
  for (const Ring& r : rings) total += r.size();
  for (int i = 0; i < tries; ++i) {
    size_t k = rng.below(total), ring = 0;
    while (k >= rings[ring].size()) k -= rings[ring++].size();
    const Ring& r = rings[ring];
    const Vec2 v = r[k], prev = r[(k + r.size() - 1) % r.size()], next = r[(k + 1) % r.size()];
    const double s = rng.uniform(0, 0.5), t = rng.uniform(0, 0.5);
    // A vertex where the boundary runs straight on (an edge split where a curve of the overlay
    // crossed it) is no corner: every point drawn there lies on the boundary itself, inside the
    // exact cell or not by a rounding error, and no route can start there.
    const Vec2 a = prev - v, b = next - v;
    if (std::fabs(a.x * b.y - a.y * b.x) <= 1e-9 * std::hypot(a.x, a.y) * std::hypot(b.x, b.y))
      continue;
    const Vec2 p = v + s * (prev - v) + t * (next - v);
    if (slice.locate(p) == int(cell)) return p;
  }
  return std::nullopt;
}

}  // namespace mms
