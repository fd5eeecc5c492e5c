#pragma once
// Floating-point polygon helpers for the fast paths (collision checking, clearance).
// They are not exact; exact predicates live in Predicates.h, exact constructions in Exact.h.
#include <limits>
#include <optional>
#include <string>

#include "mms/Geometry.h"

namespace mms {

/// Twice the signed area (positive for counter-clockwise rings).
double signedArea2(const Ring& ring);

/// Largest distance of a vertex from the frame origin: bounds how far any point of the shape
/// moves under a rotation by dtheta (at most radius * |dtheta|).
double radius(const Ring& ring);

/// Point in polygon by crossing number; points on the boundary may go either way.
bool insideRing(const Ring& ring, Vec2 p);

/// The distance from p to the nearest edge of `ring`.
double distanceToEdges(const Ring& ring, Vec2 p);

Box discBox(const Disc& disc);
/// Sides of a disc's polygonal stand-ins.
constexpr int kDiscSides = 32;
/// The regular polygon around a disc (its inscribed circle is the disc), with edges facing the
/// axes: planners that need polygons work on it, a conservative stand-in. Discs that touch
/// along an axis (a grid at spacing one diameter) keep stand-ins that only touch.
Ring discStandIn(const Disc& disc, int sides = kDiscSides);
/// The regular polygon inside a disc, vertices on its circle: for proofs that no path exists,
/// which must never take more room than the disc has.
Ring discInscribed(const Disc& disc, int sides = kDiscSides);
/// A disc inside a simple polygon: its centre lies inside the ring and `radius` is the centre's
/// distance to the ring's edges (so the disc lies inside). The centre is the best of a grid
/// over the ring's box, refined by a pattern search: near the largest inscribed disc, not
/// always it. Radius 0 when no grid point lies inside (a sliver thinner than the grid).
Disc inscribedDisc(const Ring& ring);

/// Closed segments [a,b] and [c,d] share a point (floating-point orientation tests).
bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b);
Vec2 closestPointOnSegment(Vec2 p, Vec2 a, Vec2 b);
double segmentSegmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

/// Distance between two closed polygons (0 when they intersect or one contains the other).
/// Distances of `bound` or more are reported as `bound`: a caller after the nearest of several
/// rings passes the nearest so far and skips the segment pairs that cannot beat it.
double ringDistance(const Ring& a, const Box& boxA, const Ring& b, const Box& boxB,
                    double bound = std::numeric_limits<double>::infinity());

/// Closed polygons a and b share a point.
bool ringsIntersect(const Ring& a, const Box& boxA, const Ring& b, const Box& boxB);

/// Inward offset of a counter-clockwise ring by delta with mitred vertices. Returns an error
/// text when delta is too large for the ring's features (the result would not be simple or
/// would not lie inside the ring).
struct ShrinkResult {
  Ring ring;
  std::optional<std::string> error;
};
ShrinkResult shrinkRing(const Ring& ring, double delta);

}  // namespace mms
