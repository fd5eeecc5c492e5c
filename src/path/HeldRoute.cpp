#include "path/HeldRoute.h"

#include <cmath>

#include "manifolds/CellRoute.h"
#include "manifolds/Slice.h"

namespace mms {

HeldRoutes::HeldRoutes(const Scene& scene, const CollisionChecker& checker, size_t maxSlices)
    : scene_(scene),
      checker_(checker),
      maxSlices_(scene.robots.size() == 1 && !scene.hasDiscs() ? maxSlices : 0),
      grid_{maxSlices_ > 0 ? checker.radius(0) / kCellsPerRadius : 0} {}

HeldRoutes::~HeldRoutes() = default;

const Slice* HeldRoutes::sliceAt(double theta) {
  const double key = std::remainder(theta, 2 * M_PI);
  if (const auto it = slices_.find(key); it != slices_.end()) return it->second.get();
  if (slices_.size() >= maxSlices_) return nullptr;
  std::unique_ptr<const Slice> slice;
  try {
    if (!world_) world_ = std::make_unique<SliceWorld>(scene_, 0);
    slice = std::make_unique<const Slice>(*world_, exact::rationalAngleNear(key));
  } catch (const Stopped&) {
  }
  return slices_.emplace(key, std::move(slice)).first->second.get();
}

std::optional<std::vector<Vec2>> HeldRoutes::route(double theta, Vec2 a, Vec2 b,
                                                   const Termination& stop) {
  const StopScope scope(stop);
  if (stop()) return std::nullopt;
  if (auto walked = gridRoute(checker_, scene_.bounds, theta, a, b, grid_, stop)) {
    ++gridRoutes_;
    return walked;
  }
  const Slice* slice = sliceAt(theta);
  if (!slice) return std::nullopt;
  try {
    const int cell = slice->locate(a);
    if (cell < 0 || slice->locate(b) != cell) return std::nullopt;
    return routeInCell(
        slice->cell(size_t(cell)), [&](Vec2 p) { return slice->locate(p) == cell; }, a, b,
        RouteShape::Pulled);
  } catch (const Stopped&) {
    return std::nullopt;
  }
}

}  // namespace mms
