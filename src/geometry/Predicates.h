#pragma once
// Exact predicates on double input (CGAL's exact-predicates kernel): the loader's validation
// must not be fooled by rounding, e.g. a polygon that self-intersects by 1e-17.
#include <cstddef>
#include <optional>
#include <utility>

#include "mms/Geometry.h"

namespace mms {

/// Every vertex lies on one line (the polygon has zero area).
bool allCollinear(const Ring& ring);

/// Two vertices at the same position: their indices.
std::optional<std::pair<size_t, size_t>> findRepeatedVertex(const Ring& ring);

/// Edge i runs from vertex i to vertex i+1 (cyclically). Returns a pair of edges that meet
/// where a simple polygon's edges may not: non-adjacent edges touching, or adjacent edges
/// overlapping. For very large rings only whether one exists is known: the pair is then
/// (size, size).
std::optional<std::pair<size_t, size_t>> findSelfIntersection(const Ring& ring);

/// Exact orientation of the ring (true for counter-clockwise); the ring must be simple.
bool isCounterClockwise(const Ring& ring);

}  // namespace mms
