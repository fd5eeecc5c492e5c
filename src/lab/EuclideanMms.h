#pragma once
// MMS in R^d (Salzman, Hemmer, Halperin, "On the power of manifold samples in exploring
// configuration spaces and the dimensionality of narrow passages", Section III): manifolds are
// axis-aligned affine subspaces drawn from families (each family fixes the same axes, at
// uniform random values); each manifold is decomposed exactly into FSCs; FSCs of two manifolds
// that intersect are joined in the connectivity graph. The query is answered when start and
// goal FSCs connect.
#include <cstdint>
#include <optional>
#include <vector>

#include "lab/BoxSpace.h"
#include "lab/SubspaceCells.h"

namespace mms::lab {

struct EuclideanMmsSettings {
  /// Each family: the axes its manifolds fix. Manifolds are drawn from the families in turn,
  /// so after n rounds every family has n.
  std::vector<std::vector<int>> families;
  /// Families whose manifold through the start and through the goal is added first (the
  /// theorem's m(p_A) and m(q_A)).
  std::vector<int> queryFamilies{0};
  size_t maxRounds = 200;
  uint64_t seed = 1;
};

struct EuclideanMmsResult {
  /// Rounds (manifolds per family) after which start and goal were connected; none when they
  /// were not within maxRounds.
  std::optional<size_t> rounds;
  size_t manifolds = 0, cells = 0;
  double seconds = 0;
};

/// Throws std::invalid_argument when start or goal is not free, a family fixes an axis out of
/// range or no family is given.
EuclideanMmsResult solveEuclideanMms(const BoxSpace& space, const Point& start, const Point& goal,
                                     const EuclideanMmsSettings& settings);

/// The theorem's two perpendicular families in R^d: A fixes the first k axes, B the other d - k.
std::vector<std::vector<int>> perpendicularFamilies(int d, int k);
/// Lines and planes in R^3 in every axis direction: planes fixing x_i and lines along x_i (the
/// pairs that meet in a point), in the order planes x, y, z, lines x, y, z.
std::vector<std::vector<int>> linesAndPlanes3d();

}  // namespace mms::lab
