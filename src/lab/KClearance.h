#pragma once
// k-clearance (Definition 4.2 of Salzman, Hemmer, Halperin): the largest rho such that a path
// exists along which, at every point, some k-dimensional disk of radius rho centred there
// lies in the free space. Estimated numerically: the disk radius at a point is the shortest
// free ray over sampled directions of the disk's plane (an upper bound that tightens with
// more directions), maximised over disk orientations (coordinate planes, random ones, then a
// random local search from the best: a lower bound on the maximum); the k-clearance of the
// passage is the bottleneck (maximin) path value over a grid of points.
#include <cstdint>
#include <functional>
#include <vector>

#include "lab/BoxSpace.h"

namespace mms::lab {

/// How far the free space reaches from x along the unit vector u, at most cap (0 when x is
/// not free).
using RayFunction = std::function<double(const Point& x, const Point& u, double cap)>;

struct DiskSearch {
  size_t randomFrames = 24;  // random orientations after the coordinate ones
  size_t refineSteps = 24;   // local perturbations of the best orientation
  size_t directions = 48;    // sampled directions in a disk's plane (k >= 2)
  double cap = 1;            // radii are capped here
  uint64_t seed = 1;
};

/// Estimated largest radius of a k-disk centred at x (any orientation) in the free space.
double diskRadius(int d, int k, const Point& x, const RayFunction& ray, const DiskSearch& s);

/// The estimated k-clearance for k = d, d - 1, ..., 1 (entry i is k = d - i) of the passage
/// between start and goal in a box space: bottleneck paths over the centres of the free
/// arrangement cells, each split `split` times per axis (odd: the centres of thin cells are
/// sampled). The cube's faces do not bound the disks; radii are capped at s.cap.
std::vector<double> kClearanceSequence(const BoxSpace& space, const Point& start, const Point& goal,
                                       int split, const DiskSearch& s);

/// A (k-1)-disk fits wherever a k-disk does: raises each entry (k = d, d - 1, ...) to at least
/// the one before, where the search for orientations fell short.
void makeMonotone(std::vector<double>& sequence);

/// A passage's dimension from its sequence: the largest k < d whose k-clearance is at least
/// `factor` times the d-clearance ("significantly larger", which the paper leaves informal);
/// 0 when none is. (The paper's Definition 4.3 writes d - k + 1, which contradicts its own
/// examples: the tunnel, whose 1-clearance alone is large, would be 3-dimensional; its
/// Discussion and examples read "k-dimensional", as here.)
int passageDimension(const std::vector<double>& sequence, double factor);

}  // namespace mms::lab
