#pragma once
// A route between two points inside one slice FSC (a polygon with holes): a constrained
// triangulation of the cell and a search over its triangles. By default the route runs through
// the midpoints of the edges it crosses (fewest triangles), so it keeps off the cell's boundary
// instead of grazing its vertices as a shortest path would. Pulled, it is the shortest way
// through the middle halves of the edges crossed (shortest along their midpoints): for a
// route whose length decides whether it is taken (the optimiser's).
#include <functional>
#include <optional>
#include <vector>

#include "mms/Geometry.h"

namespace mms {

enum class RouteShape { Midpoints, Pulled };

/// `rings`: the cell's outer boundary and holes; `inCell` tells whether a point lies in the
/// cell's interior (exact point location), used to keep the triangles inside it. Returns the
/// route from a to b, both included, or nothing if none is found.
std::optional<std::vector<Vec2>> routeInCell(const std::vector<Ring>& rings,
                                             const std::function<bool(Vec2)>& inCell, Vec2 a,
                                             Vec2 b, RouteShape shape = RouteShape::Midpoints);

}  // namespace mms
