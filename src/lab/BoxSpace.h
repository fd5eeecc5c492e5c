#pragma once
// The Euclidean configuration spaces of the paper's Sections III and IV: the open unit cube
// (0,1)^d minus closed axis-aligned boxes. Small enough to decide everything exactly, so the
// lab can measure the theory without the SE(2) geometry in the way.
#include <string>
#include <vector>

namespace mms::lab {

struct Box {
  std::vector<double> lo, hi;  // lo[i] < hi[i]
};

using Point = std::vector<double>;

class BoxSpace {
 public:
  /// Throws std::invalid_argument for d outside 1..12 or a box of the wrong dimension or with
  /// an empty extent.
  BoxSpace(int dim, std::vector<Box> obstacles, std::string name = "");

  int dim() const { return dim_; }
  const std::vector<Box>& obstacles() const { return obstacles_; }
  const std::string& name() const { return name_; }

  /// Inside the open cube and in no closed box.
  bool isFree(const double* x) const;
  bool isFree(const Point& x) const { return isFree(x.data()); }
  /// The closed segment ab misses every box (exact slab test) and stays in the open cube.
  bool segmentFree(const double* a, const double* b) const;
  /// How far x can move along the unit vector u before it meets a box or (when `cube`) the
  /// cube's boundary, at most `cap`. 0 when x is in a box, or outside the cube when `cube`.
  double rayFree(const double* x, const double* u, double cap, bool cube = true) const;

 private:
  int dim_;
  std::vector<Box> obstacles_;
  std::string name_;
};

/// A wall x_0 in [0.45, 0.55] across the cube with one cubic hole of half-width `rho` centred
/// on the axis x_i = 0.5 (i > 0), plus `clutter` random boxes that keep 2 rho away from the
/// path wallStart -> hole -> wallGoal: that path has clearance rho, and no wider way exists.
/// rho in (0, 0.19).
BoxSpace wallWithHole(int dim, double rho, int clutter, unsigned long long seed);
/// (0.2, 0.3, ..., 0.3) and (0.8, 0.3, ..., 0.3): the wall hides each from the other.
Point wallStart(int dim);
Point wallGoal(int dim);

/// The paper's Fig. 7, in the unit cube: a wall x_0 in [0.35, 0.65] whose one passage has
/// volume 0.3 eps^2, either a flume (thickness eps^2 in x_1, the whole height in x_2) or a
/// tunnel (eps by eps in x_1, x_2).
BoxSpace flume(double eps);
BoxSpace tunnel(double eps);
/// The start and goal used with flume() and tunnel(): on either side of the wall, differing
/// in every coordinate, so no manifold through one of them contains the other.
Point passageStart();
Point passageGoal();

}  // namespace mms::lab
