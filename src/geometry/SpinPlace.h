#pragma once
// Where a robot turns the short way when where it turned does not let it. A key that turned a
// quarter the long way round in a chamber barely larger than its turning circle can turn the
// other way only about the centre of its smallest enclosing circle held at the chamber's
// centre: turned about its reference point, or off centre, it sweeps the walls (the keyhole
// scenes). The optimiser moves such a turn there: the centre of the largest empty circle near
// where the robot turned, found by climbing the distance to the walls, and a turn about it.
#include <vector>

#include "mms/Geometry.h"
#include "mms/Scene.h"

namespace mms {

/// The distance from `p` to the nearest edge of the scene's obstacles and bounds.
double wallDistance(const Scene& scene, Vec2 p);

/// From `p`, up the distance to the walls to a local maximum (a chamber's centre), or as high as
/// it gets within `reach` of `p` (in the open the maximum may be far, and a turn moved there
/// costs more than it saves): a pattern search whose step, from `step`, halves until it is a
/// thousandth of where it began.
Vec2 clearestNear(const Scene& scene, Vec2 p, double step, double reach);

/// The pose at `angle` that puts the robot's own point `local` at `at` (the world): the robot
/// turning about that point held there. Its inverse is Transform(pose)(local).
Pose poseWithPointAt(Vec2 local, Vec2 at, double angle);

/// The waypoints strictly between `a` and `b` of a motion in which `robot`, at `a`'s angle,
/// moves along its heading (its x axis) and then across it until its point `centre` (its own
/// frame) is at `at` (the world), turns there about it to `b`'s angle in steps of at most
/// `maxStep` radians, and moves across its heading and along it to `b`. The other robots move
/// from `a` to `b` evenly over the waypoints.
std::vector<Config> turnAbout(const Config& a, const Config& b, size_t robot, Vec2 centre, Vec2 at,
                              double maxStep);

}  // namespace mms
