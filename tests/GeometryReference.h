#pragma once
// Independent geometric references for tests: plain double-precision polygon tests, separate
// from the exact constructions the manifolds use.
#include <algorithm>
#include <vector>

#include "geometry/PolygonOps.h"
#include "mms/Scene.h"

namespace mms::test {

/// Robot 0's own shape (not shrunk by the tolerance) at `pose` leaves the bounds or shares a
/// point with an obstacle.
inline bool trueShapeOverlaps(const Scene& s, const Pose& pose) {
  Ring placed;
  transformRing(s.robots[0].shape, pose, placed);
  const Box box = boundingBox(placed);
  if (!s.bounds.contains(box)) return true;
  for (const Ring& o : s.obstacles)
    if (ringsIntersect(placed, box, o, boundingBox(o))) return true;
  return false;
}

/// Whether p lies in one of `cells` (each an outer ring then its holes, even-odd), and in
/// `margin` how far it is from the nearest edge of any.
inline bool insideCells(const std::vector<std::vector<Ring>>& cells, Vec2 p, double& margin) {
  bool in = false;
  margin = 1e300;
  for (const auto& cell : cells) {
    bool inCell = false;
    for (const Ring& r : cell) {
      inCell ^= insideRing(r, p);
      margin = std::min(margin, distanceToEdges(r, p));
    }
    in = in || inCell;
  }
  return in;
}

}  // namespace mms::test
