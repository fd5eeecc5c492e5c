#pragma once
// A way for one robot held at an angle, found with the collision checker on a grid of its
// reference point's places and pulled tight by the continuous certifier: what the optimiser's
// routed turns (HeldRoute.h) try before an exact slice. In open clutter a slice of an L among
// 30 obstacles costs 6-9 ms, most of it Minkowski sums, where the grid finds the same way
// round in a fraction of that; a passage narrower than a cell is missed, and the slice is the
// fallback. Internal to path/.
#include <optional>
#include <vector>

#include "geometry/CollisionChecker.h"
#include "mms/Termination.h"

namespace mms {

struct GridRouteSettings {
  double cell = 0;          // side of a grid cell (of the reference point's places)
  size_t maxChecks = 4000;  // placements tested before the search gives up
  /// Cells at most: in a scene large for its robot the cells are made larger, so that the
  /// search's memory (under 50 bytes a cell) stays bounded.
  size_t maxCells = 1 << 16;
};

/// The way of the reference point of a one-robot checker's robot from `a` to `b` (both
/// included) at angle `theta`: a 4-connected walk over the cells whose centres are free,
/// searched greedily towards `b`, its ends joined to `a` and `b`, then pulled tight so that
/// each segment is a motion the certifier proves free. Nothing when the search runs out of
/// tests or of cells, when `a` or `b` does not reach its cell's centre, or once `stop` holds.
std::optional<std::vector<Vec2>> gridRoute(const CollisionChecker& checker, const Box& bounds,
                                           double theta, Vec2 a, Vec2 b,
                                           const GridRouteSettings& settings,
                                           const Termination& stop);

}  // namespace mms
