#pragma once
// A horizontal slice of the C-space of one robot: the robot's angle is fixed, its reference
// point moves. The free space of the reference point is computed exactly (CGAL, Epeck): the
// bounds' inner region minus the union of the Minkowski sums O (+) (-R_theta) of every
// obstacle with the rotated, reflected robot. Its connected faces are the slice's free-space
// cells (FSCs): polygons with holes.
//
// Salzman, Hemmer, Raveh, Halperin: "Motion planning via manifold samples", Algorithmica 2013;
// Salzman, Hemmer, Halperin: "On the power of manifold samples in exploring configuration
// spaces and the dimensionality of narrow passages" (the paper in ../shared/paper).
#include <memory>
#include <optional>
#include <vector>

#include "geometry/Exact.h"
#include "mms/Scene.h"

namespace mms {

/// Point-location strategies of CGAL's arrangement package (microbench/bench_manifolds.cpp
/// measures them). Auto first tries the cells in doubles (decided only away from their edges),
/// then walks (no preprocessing) until a slice has answered enough queries to pay for a
/// trapezoidal map (~5 ms to build, ~10x faster per query on large slices).
enum class PointLocation { Auto, Walk, Trapezoid, Landmarks };

/// What every slice of one robot shares: the obstacles and the robot in exact form.
class SliceWorld {
 public:
  SliceWorld(const Scene& scene, size_t robot, std::vector<Ring> extraObstacles = {});
  ~SliceWorld();
  SliceWorld(const SliceWorld&) = delete;
  SliceWorld& operator=(const SliceWorld&) = delete;

  struct Impl;
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

/// An obstacle that is a shape turned about its origin, then moved by `offset`: a held robot.
/// Overlays keep the Minkowski sum of `turned` on their base slice, per (shape, angle), and
/// translate it: fixings of a robot at one angle share one sum. The sum is always formed this
/// way, so whether it was cached does not change the slice.
struct MovedShape {
  size_t shape = 0;  // with `angle`, names `turned`: equal names, equal rings
  double angle = 0;
  Ring turned;
  Vec2 offset;
  Ring placed() const;  // turned + offset, in doubles
};

class Slice {
 public:
  Slice(const SliceWorld& world, const exact::RationalAngle& angle,
        PointLocation strategy = PointLocation::Auto);
  /// The same slice with more obstacles (e.g. another robot held fixed): an overlay that only
  /// subtracts the new Minkowski sums from `base`'s free space. Shares `base`'s cells when the
  /// new obstacles cannot reach it. Overlays of one base may be built from several threads.
  Slice(const Slice& base, const std::vector<MovedShape>& extraObstacles,
        PointLocation strategy = PointLocation::Auto);
  /// The same, the obstacles shared by the overlays that keep them to rebuild from (a
  /// subspace's overlays all hold the same robots).
  Slice(const Slice& base, std::shared_ptr<const std::vector<MovedShape>> extraObstacles,
        PointLocation strategy = PointLocation::Auto);
  /// A compound of two robots in a fixed relative pose translating as one: where the first
  /// robot's reference point may be so that it is free in `carrier` (its slice) and the second,
  /// at `offset` in the first's frame, is free in `attached` (its slice, at its own angle).
  /// The free space of `carrier` intersected with that of `attached` moved by -R(angle) offset,
  /// exactly (the carrier's rational rotation).
  Slice(const Slice& carrier, const Slice& attached, Vec2 offset,
        PointLocation strategy = PointLocation::Auto);
  ~Slice();
  Slice(Slice&&) noexcept;
  Slice& operator=(Slice&&) noexcept;

  const exact::RationalAngle& angle() const { return angle_; }
  double theta() const { return theta_; }
  size_t fscCount() const;
  /// The FSC whose interior contains p, or -1 (p forbidden or on a cell's boundary).
  /// Safe to call from several threads. Exact: decided in doubles when p is clearly away from
  /// every edge of the cells near it, by CGAL's point location otherwise. An overlay that
  /// dropped its arrangement rebuilds it then, so this can throw Stopped under a StopScope.
  int locate(Vec2 p) const;
  /// FSC i as rings in doubles: its outer boundary (counter-clockwise) then its holes.
  const std::vector<Ring>& cell(size_t i) const;
  /// Area of FSC i (doubles), e.g. to sample points in proportion to it.
  double area(size_t i) const;

 private:
  struct Impl;
  /// Indexes the arrangement's cells; those equal to a cell of `base` share its storage.
  void index(PointLocation strategy, const Impl* base = nullptr);
  static void rebuildExact(Impl& im);
  std::optional<int> locateInDoubles(Vec2 p) const;
  std::shared_ptr<Impl> impl_;
  exact::RationalAngle angle_;
  double theta_ = 0;
};

}  // namespace mms
