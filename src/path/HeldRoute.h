#pragma once
// Routes of one robot held at an angle: found on a grid with the collision checker where they
// can be (GridRoute.h), else through the exact free space at that angle (a slice).
// The optimiser needs them where a turn made the other way round also changes how the robot
// travels before and after it: a key that went down a slot bit last and turned three quarters
// in its chamber turns one quarter only if it goes down bit first, which the path's positions,
// fitted to the other way round, do not let it (the keyhole scenes).
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/CollisionChecker.h"
#include "mms/Geometry.h"
#include "mms/Scene.h"
#include "mms/Termination.h"
#include "path/GridRoute.h"

namespace mms {

class Slice;
class SliceWorld;

class HeldRoutes {
 public:
  /// For the one robot of `scene` (a scene of several robots, or with discs, routes nothing);
  /// at most `maxSlices` slices are built, the rest answer only from the grid.
  HeldRoutes(const Scene& scene, const CollisionChecker& checker, size_t maxSlices);
  ~HeldRoutes();
  HeldRoutes(const HeldRoutes&) = delete;
  HeldRoutes& operator=(const HeldRoutes&) = delete;

  /// The reference point's way from `a` to `b` (both included) with the robot at `theta`:
  /// a grid's walk pulled tight by the certifier, or where the grid finds none, a way pulled
  /// tight through a triangulation of the slice's free cell holding both (CellRoute.h). The
  /// optimiser takes a route only if it is short enough. Nothing if the grid finds none and
  /// `a` and `b` lie in different cells, on a boundary, or the slices are spent; nothing too
  /// once `stop` holds, which ends a slice being built.
  std::optional<std::vector<Vec2>> route(double theta, Vec2 a, Vec2 b, const Termination& stop);
  /// Whether any route can be asked for (one robot, no discs).
  bool routes() const { return maxSlices_ > 0; }
  size_t slicesBuilt() const { return slices_.size(); }
  size_t gridRoutes() const { return gridRoutes_; }

 private:
  const Slice* sliceAt(double theta);
  // Grid cells per the robot's radius: passages at a fixed angle that a cell this size misses
  // are left to the slices.
  static constexpr double kCellsPerRadius = 6;
  const Scene& scene_;
  const CollisionChecker& checker_;
  size_t maxSlices_;
  GridRouteSettings grid_;
  size_t gridRoutes_ = 0;
  std::unique_ptr<SliceWorld> world_;                      // made on first use
  std::map<double, std::unique_ptr<const Slice>> slices_;  // by the angle asked for; null: failed
};

}  // namespace mms
