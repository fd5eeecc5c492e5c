#pragma once
// Points inside the free-space cells of a slice: where the two-robot planner fixes a robot to
// grow its graph. All answers are checked by exact point location in the slice.
#include <optional>

#include "manifolds/Slice.h"
#include "util/Random.h"

namespace mms {

/// A point in the interior of FSC `cell` of `slice`, uniform over the cell (rejection in its
/// bounding box), or nothing if `tries` draws all missed (a sliver in a large box).
std::optional<Vec2> samplePointInCell(const Slice& slice, size_t cell, Random& rng, int tries = 64);

/// A point in the interior of FSC `cell` as close to `target` as it gets: the target itself
/// when it lies in the cell, else a point just inside the cell's boundary next to the boundary
/// point nearest to it (how far inside is tried from close to far).
std::optional<Vec2> pointTowards(const Slice& slice, size_t cell, Vec2 target, Random& rng);

/// A point in the interior of FSC `cell` close to one of its vertices (chosen uniformly): in
/// the corner spanned by the vertex's two edges, at most half their lengths away. The vertices
/// of a cell are placements in contact with two features, so this finds the small pockets of a
/// cell (a part tucked into a corner) that uniform points almost never hit.
std::optional<Vec2> samplePointNearVertex(const Slice& slice, size_t cell, Random& rng,
                                          int tries = 16);

}  // namespace mms
