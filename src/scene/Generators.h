#pragma once
// Deterministic scene generators (same seed, same scene).
#include <cstdint>

#include "scene/Scene.h"
#include "util/Random.h"

namespace mms {

/// A star-shaped (hence simple) polygon around `center`: `n` vertices at increasing angles,
/// radii uniform in [rmin, rmax]. Counter-clockwise.
Ring randomStarPolygon(Random& rng, Vec2 center, double rmin, double rmax, int n);

struct RandomPolygonsSettings {
  uint64_t seed = 1;
  int obstacles = 20;
  int obstacleVertices = 8;
  int robotVertices = 10;
  double extent = 50;  // bounds are [-extent, extent]^2
};

/// Random non-convex obstacles and one random non-convex robot whose start and goal are free
/// (found by the caller's validation: this only places them where the generator left room).
Scene randomPolygonsScene(const RandomPolygonsSettings& settings);

}  // namespace mms
