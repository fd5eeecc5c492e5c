#pragma once
// A route between two points inside one slice FSC (a polygon with holes): a constrained
// triangulation of the cell and a breadth-first search over its triangles. The route runs
// through the midpoints of the edges it crosses, so it keeps off the cell's boundary instead
// of grazing its vertices as a shortest path would.
#include <functional>
#include <optional>
#include <vector>

#include "mms/Geometry.h"

namespace mms {

/// `rings`: the cell's outer boundary and holes; `inCell` tells whether a point lies in the
/// cell's interior (exact point location), used to keep the triangles inside it. Returns the
/// route from a to b, both included, or nothing if none is found.
std::optional<std::vector<Vec2>> routeInCell(const std::vector<Ring>& rings,
                                             const std::function<bool(Vec2)>& inCell, Vec2 a,
                                             Vec2 b);

}  // namespace mms
