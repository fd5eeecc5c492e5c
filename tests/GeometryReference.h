#pragma once
// Independent geometric references for tests: plain double-precision polygon tests, separate
// from the exact constructions the manifolds use.
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

}  // namespace mms::test
