#include "manifolds/Slice.h"

#include <CGAL/Arr_landmarks_point_location.h>
#include <CGAL/Arr_trapezoid_ric_point_location.h>
#include <CGAL/Arr_walk_along_line_point_location.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/minkowski_sum_2.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <utility>
#include <variant>

#include "geometry/PolygonOps.h"
#include "mms/Termination.h"
#include "util/Deferred.h"

namespace mms {

using exact::ExactFT;
using exact::exactPoint;
using exact::FT;
using exact::Kernel;
using exact::Point;
using exact::Polygon;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using PolygonSet = CGAL::Polygon_set_2<Kernel>;
using Arrangement = PolygonSet::Arrangement_2;

struct SliceWorld::Impl {
  Box bounds;
  Polygon robot;                   // exact, counter-clockwise, robot frame
  bool robotConvex = false;        // so is the robot turned: rotations keep convexity exactly
  std::vector<Polygon> obstacles;  // exact, counter-clockwise
  std::vector<Box> obstacleBoxes;
  std::vector<char> obstacleConvex;
};

namespace {

// The Minkowski sum a (+) b. Of two convex polygons: their edges merged in order of angle
// (exact::convexMinkowskiSum). Exact like CGAL's reduced convolution, and several times cheaper
// for the few-vertex convex pieces most scenes are made of.
PolygonWithHoles minkowskiSum(const Polygon& a, bool aConvex, const Polygon& b, bool bConvex) {
  if (aConvex && bConvex) {
    Polygon sum = exact::convexMinkowskiSum(a, b);
    if (!sum.is_empty()) return PolygonWithHoles(std::move(sum));
  }
  return CGAL::minkowski_sum_2(a, b);
}

}  // namespace

SliceWorld::SliceWorld(const Scene& scene, size_t robot, std::vector<Ring> extraObstacles)
    : impl_(std::make_unique<Impl>()) {
  impl_->bounds = scene.bounds;
  impl_->robot = exact::toExact(scene.robots[robot].shape);
  impl_->robotConvex = impl_->robot.is_convex();
  auto add = [&](const Ring& r) {
    impl_->obstacles.push_back(exact::toExact(r));
    if (impl_->obstacles.back().is_clockwise_oriented())
      impl_->obstacles.back().reverse_orientation();
    impl_->obstacleBoxes.push_back(boundingBox(r));
    impl_->obstacleConvex.push_back(impl_->obstacles.back().is_convex());
  };
  for (const Ring& o : scene.obstacles) add(o);
  for (const Ring& o : extraObstacles) add(o);
}
SliceWorld::~SliceWorld() = default;

namespace {

using Walk = CGAL::Arr_walk_along_line_point_location<Arrangement>;
using Trapezoid = CGAL::Arr_trapezoid_ric_point_location<Arrangement>;
using Landmarks = CGAL::Arr_landmarks_point_location<Arrangement>;

Ring ccbRing(Arrangement::Ccb_halfedge_const_circulator first) {
  Ring r;
  r.reserve(size_t(CGAL::circulator_size(first)));  // exact: cells are most of a slice's memory
  auto c = first;
  do {
    r.push_back(exact::toDouble(c->source()->point()));
  } while (++c != first);
  return r;
}

double ringsArea(const std::vector<Ring>& rings) {
  double a = 0;
  for (const Ring& r : rings) a += 0.5 * signedArea2(r);  // holes are clockwise: negative
  return a;
}

}  // namespace

struct Slice::Impl {
  Polygon neg;  // -R_theta
  bool negConvex = false;
  // Auto: located in doubles first; the walk answers until kUpgradeAfter exact queries, then a
  // trapezoidal map takes over.
  bool autoUpgrade = false;
  static constexpr size_t kUpgradeAfter = 600;
  Box negBox;     // of neg, in doubles (for culling)
  Box regionBox;  // reference points keeping the robot inside the bounds (doubles, for culling)
  struct Cell {
    std::vector<Ring> rings;  // outer boundary first
    std::vector<Box> boxes;   // per ring
    double area = 0;
  };
  // Shared with the base slice where an overlay's cell is the base's unchanged: two thirds of
  // the cells on a two-robot run (42 % of their vertices).
  std::vector<std::shared_ptr<const Cell>> cells;

  // The exact arrangement and what answers on it. An overlay drops all of it once its cells are
  // indexed: the arrangement is most of its memory (a two-robot run: 728 MB with it, 155 MB
  // without, same slices), and the point location in doubles answers most queries. An exact
  // query rebuilds it from `rebuild`.
  struct Exact {
    PolygonSet free;
    // The larger locators apart: a trapezoidal map's object alone is ~230 bytes.
    std::variant<std::monostate, Walk, std::unique_ptr<Trapezoid>, std::unique_ptr<Landmarks>>
        locator;
    std::unordered_map<const void*, int> faceIndex;
    std::atomic<size_t> queries{0};
    std::once_flag upgradeOnce;
    std::unique_ptr<Trapezoid> upgraded;
    std::atomic<bool> upgradedReady{false};
    // On a base slice: sums of moved shapes with neg at the origin, by (shape, angle) (see
    // movedSum()).
    using SumKey = std::pair<size_t, double>;
    std::mutex sumsMutex;
    std::map<SumKey, std::shared_ptr<const PolygonWithHoles>> movedSums;
    static constexpr size_t kConvexSumsKept = 32;
    std::vector<std::pair<SumKey, std::shared_ptr<const PolygonWithHoles>>> convexSums;
    size_t convexReplaced = 0;  // the oldest of convexSums once it is full
  };
  std::unique_ptr<Exact> exactPart;  // none where the robot does not fit, or dropped
  struct Rebuild {
    std::shared_ptr<Impl> base;
    std::shared_ptr<const std::vector<MovedShape>> obstacles;
    std::mutex mutex;
  };
  std::unique_ptr<Rebuild> rebuild;  // on an overlay that dropped `exactPart`
  std::atomic<bool> exactReady{true};

  std::vector<PolygonWithHoles> heldSums(const std::vector<MovedShape>& shapes);
  // An overlay's exact part: this (base) slice's free space minus `sums`. The constructor and
  // the rebuild both make it here, so the rebuild's faces come out as the constructor's did.
  std::unique_ptr<Exact> exactWithout(const std::vector<PolygonWithHoles>& sums) const;

  // The sum of a moved shape with neg at the origin, kept for the next overlay that holds the
  // shape at that angle. Sums by the reduced convolution (a non-convex shape) are all kept. A
  // convex pair's sum, a hull of vertex sums, costs a few microseconds to redo: only the last
  // kConvexSumsKept are kept. Keeping every one made most of the memory of runs with three
  // robots, whose base slices meet the others' held poses at hundreds of angles (0.73 KB a slice
  // against 0.53 KB; at 32, 9 % more time per overlay there, and nothing on two-robot scenes,
  // whose first rounds hold fewer angles).
  std::shared_ptr<const PolygonWithHoles> movedSum(const MovedShape& m) {
    Exact& ex = *exactPart;
    const Exact::SumKey key{m.shape, m.angle};
    auto kept = [&]() -> std::shared_ptr<const PolygonWithHoles> {
      if (auto it = ex.movedSums.find(key); it != ex.movedSums.end()) return it->second;
      for (const auto& [k, sum] : ex.convexSums)
        if (k == key) return sum;
      return nullptr;
    };
    {
      std::lock_guard lock(ex.sumsMutex);
      if (auto sum = kept()) return sum;
    }
    // Built outside the lock: two threads may both build it; the first one stored is kept.
    Polygon turned = exact::toExact(m.turned);
    if (turned.is_clockwise_oriented()) turned.reverse_orientation();
    const bool convex = turned.is_convex();
    auto sum =
        std::make_shared<const PolygonWithHoles>(minkowskiSum(turned, convex, neg, negConvex));
    std::lock_guard lock(ex.sumsMutex);
    if (auto first = kept()) return first;
    if (!convex || !negConvex)
      ex.movedSums.emplace(key, sum);
    else if (ex.convexSums.size() < Exact::kConvexSumsKept)
      ex.convexSums.emplace_back(key, sum);
    else
      ex.convexSums[std::exchange(ex.convexReplaced,
                                  (ex.convexReplaced + 1) % Exact::kConvexSumsKept)] = {key, sum};
    return sum;
  }
};

Ring MovedShape::placed() const {
  Ring r = turned;
  for (Vec2& v : r) v = v + offset;
  return r;
}

namespace {

// Whether the sum of an obstacle with box `o` and -R_theta (box `negBox`) can reach the region
// (boxes in doubles, with a margin for their rounding).
bool sumReaches(const Box& o, const Box& negBox, const Box& regionBox) {
  const double m =
      1e-9 * (1 + std::fabs(o.xmax) + std::fabs(o.ymax) + std::fabs(o.xmin) + std::fabs(o.ymin));
  const Box sumBox{o.xmin + negBox.xmin - m, o.ymin + negBox.ymin - m, o.xmax + negBox.xmax + m,
                   o.ymax + negBox.ymax + m};
  return sumBox.overlaps(regionBox);
}

// Sums of `obstacles` with -R_theta that can reach the region (boxes in doubles, with a margin).
void reachingSums(const SliceWorld::Impl& w, const Polygon& neg, bool negConvex, const Box& negBox,
                  const Box& regionBox, std::vector<PolygonWithHoles>& sums) {
  for (size_t i = 0; i < w.obstacles.size(); ++i) {
    if (!sumReaches(w.obstacleBoxes[i], negBox, regionBox)) continue;
    checkpoint();
    sums.push_back(minkowskiSum(w.obstacles[i], w.obstacleConvex[i], neg, negConvex));
  }
}

// free minus the union of the sums. Among thousands of obstacles one union takes seconds, so
// it is built in groups, joined pairwise, with a checkpoint between steps. The last steps
// overlay arrangements of the whole union (~0.1 s at 3000 obstacles): before each, the step's
// cost is estimated from the seconds per edge of the steps so far, and a step that cannot end
// before the limit is not begun, so the planner's time limit holds closely.
void subtractUnion(PolygonSet& free, const std::vector<PolygonWithHoles>& sums) {
  constexpr size_t kGroup = 32;
  if (sums.size() <= kGroup) {
    // free - U(sums) = complement(complement(free) + U(sums)): one aggregated sweep over free's
    // edges and the sums' instead of a sweep for the union and an overlay for the difference.
    // A complement only flips the faces' flags.
    free.complement();
    free.join(sums.begin(), sums.end());
    free.complement();
    return;
  }
  double secondsPerEdge = 0;
  auto timed = [&](size_t edges, auto&& step) {
    // Twice the rate so far: an overlay's cost per edge grows with its size (log factor), and
    // indexing the cells follows the last step.
    checkpoint(2 * secondsPerEdge * double(edges));
    Stopwatch watch;
    step();
    if (edges > 0) secondsPerEdge = std::max(secondsPerEdge, watch.seconds() / double(edges));
  };
  auto edges = [](const PolygonSet& p) { return p.arrangement().number_of_edges(); };
  // Pointers: a PolygonSet has no move constructor, and copying one copies its arrangement.
  std::vector<std::unique_ptr<PolygonSet>> sets, next;
  try {
    for (size_t i = 0; i < sums.size(); i += kGroup) {
      checkpoint();
      sets.push_back(std::make_unique<PolygonSet>());
      sets.back()->join(sums.begin() + i, sums.begin() + std::min(sums.size(), i + kGroup));
    }
    while (sets.size() > 1) {
      for (size_t i = 0; i + 1 < sets.size(); i += 2) {
        timed(edges(*sets[i]) + edges(*sets[i + 1]), [&] { sets[i]->join(*sets[i + 1]); });
        next.push_back(std::move(sets[i]));
      }
      if (sets.size() % 2) next.push_back(std::move(sets.back()));
      sets = std::move(next);
      next.clear();
    }
    timed(edges(free) + edges(*sets.front()), [&] { free.difference(*sets.front()); });
  } catch (const Stopped&) {
    // Freeing the partial unions would take tens of ms past the limit (util/Deferred.h).
    freeLaterMoved(sets);
    freeLaterMoved(next);
    throw;
  }
}

// `p` translated by the exact (dx, dy), point by point from exact coordinates rather than by
// lazy translations: the overlay's predicates then fall back on exact values at hand instead
// of evaluating a construction per point.
template <class ExactNumber>
PolygonWithHoles translated(const PolygonWithHoles& p, const ExactNumber& dx,
                            const ExactNumber& dy) {
  auto move = [&](const Polygon& poly) {
    Polygon out;
    for (const Point& v : poly.vertices()) {
      const auto& e = CGAL::exact(v);
      out.push_back(exactPoint(e.x() + dx, e.y() + dy));
    }
    return out;
  };
  PolygonWithHoles moved(move(p.outer_boundary()));
  for (auto h = p.holes_begin(); h != p.holes_end(); ++h) moved.add_hole(move(*h));
  return moved;
}

}  // namespace

std::unique_ptr<Slice::Impl::Exact> Slice::Impl::exactWithout(
    const std::vector<PolygonWithHoles>& sums) const {
  auto ex = std::make_unique<Exact>();
  ex->free = exactPart->free;
  subtractUnion(ex->free, sums);
  return ex;
}

// Cells are the arrangement's contained faces; the locator answers queries on them.
void Slice::index(PointLocation strategy, const Impl* base) {
  Impl& im = *impl_;
  Impl::Exact& ex = *im.exactPart;
  const Arrangement& arr = ex.free.arrangement();
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (!f->contained() || f->is_unbounded()) continue;
    std::vector<Ring> rings;
    rings.reserve(1 + f->number_of_inner_ccbs());
    rings.push_back(ccbRing(f->outer_ccb()));
    for (auto h = f->inner_ccbs_begin(); h != f->inner_ccbs_end(); ++h)
      rings.push_back(ccbRing(*h));
    ex.faceIndex[&*f] = int(im.cells.size());
    std::shared_ptr<const Impl::Cell> same;
    if (base)
      for (const auto& c : base->cells)
        if (c->rings == rings) {
          same = c;
          break;
        }
    if (!same) {
      Impl::Cell cell;
      cell.area = ringsArea(rings);
      cell.boxes.reserve(rings.size());
      for (const Ring& r : rings) cell.boxes.push_back(boundingBox(r));
      cell.rings = std::move(rings);
      same = std::make_shared<const Impl::Cell>(std::move(cell));
    }
    im.cells.push_back(std::move(same));
  }
  im.cells.shrink_to_fit();
  switch (strategy) {
    case PointLocation::Auto:
      im.autoUpgrade = true;
      ex.locator.emplace<Walk>(arr);
      break;
    case PointLocation::Walk:
      ex.locator.emplace<Walk>(arr);
      break;
    case PointLocation::Trapezoid:
      ex.locator = std::make_unique<Trapezoid>(arr);
      break;
    case PointLocation::Landmarks:
      ex.locator = std::make_unique<Landmarks>(arr);
      break;
  }
}

// The Minkowski sums of held shapes that can reach this (base) slice's region, from its cache.
std::vector<PolygonWithHoles> Slice::Impl::heldSums(const std::vector<MovedShape>& shapes) {
  std::vector<PolygonWithHoles> sums;
  for (const MovedShape& m : shapes) {
    if (!sumReaches(boundingBox(m.placed()), negBox, regionBox)) continue;
    checkpoint();
    const std::shared_ptr<const PolygonWithHoles> sum = movedSum(m);
    sums.push_back(translated(*sum, CGAL::exact(FT(m.offset.x)), CGAL::exact(FT(m.offset.y))));
  }
  return sums;
}

Slice::Slice(const Slice& base, const std::vector<MovedShape>& extraObstacles,
             PointLocation strategy)
    : Slice(base, std::make_shared<const std::vector<MovedShape>>(extraObstacles), strategy) {}

Slice::Slice(const Slice& base, std::shared_ptr<const std::vector<MovedShape>> extraObstacles,
             PointLocation strategy)
    : impl_(base.impl_), angle_(base.angle_), theta_(base.theta_) {
  if (base.impl_->cells.empty() || !extraObstacles || extraObstacles->empty()) return;
  Impl& b = *base.impl_;
  rebuildExact(b);  // a base keeps its arrangement; this only guards the assumption
  std::vector<PolygonWithHoles> sums = b.heldSums(*extraObstacles);
  if (sums.empty()) return;  // nothing changes: share the base's cells
  auto im = std::make_shared<Impl>();
  im->neg = b.neg;
  im->negConvex = b.negConvex;
  im->negBox = b.negBox;
  im->regionBox = b.regionBox;
  im->exactPart = b.exactWithout(sums);
  impl_ = std::move(im);
  index(strategy, &b);
  if (strategy != PointLocation::Auto) return;  // the other strategies answer exactly only
  Impl& o = *impl_;
  o.rebuild = std::make_unique<Impl::Rebuild>();
  o.rebuild->base = base.impl_;
  o.rebuild->obstacles = std::move(extraObstacles);
  o.exactPart.reset();
  o.exactReady.store(false, std::memory_order_release);
}

// The overlay's arrangement again, as the constructor made it: the same operations on the
// same exact input give the same faces in the same order, which is checked against the cells.
void Slice::rebuildExact(Impl& im) {
  if (im.exactReady.load(std::memory_order_acquire)) return;
  const std::lock_guard lock(im.rebuild->mutex);
  if (im.exactReady.load(std::memory_order_relaxed)) return;
  Impl& b = *im.rebuild->base;
  rebuildExact(b);  // kept once rebuilt for an overlay of it
  const std::vector<PolygonWithHoles> sums = b.heldSums(*im.rebuild->obstacles);
  std::unique_ptr<Impl::Exact> ex = b.exactWithout(sums);
  const Arrangement& arr = ex->free.arrangement();
  std::unordered_map<const void*, int>& faceIndex = ex->faceIndex;
  size_t k = 0;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (!f->contained() || f->is_unbounded()) continue;
    // A face that is not the cell indexed in its place is left out: locate() then answers -1
    // there (no cell), which planners treat as a point to skip, never as a wrong cell.
    if (k < im.cells.size() && ccbRing(f->outer_ccb()) == im.cells[k]->rings.front())
      faceIndex[&*f] = int(k);
    ++k;
  }
  ex->locator.emplace<Walk>(arr);
  im.exactPart = std::move(ex);
  im.exactReady.store(true, std::memory_order_release);
}

Slice::Slice(const SliceWorld& world, const exact::RationalAngle& angle, PointLocation strategy)
    : impl_(std::make_shared<Impl>()), angle_(angle), theta_(angle.radians()) {
  const SliceWorld::Impl& w = world.impl();
  // -R_theta: the robot rotated, then reflected about its reference point (a half turn, so
  // the orientation stays counter-clockwise). Its vertices and the region's corners are made
  // from exact rationals, with their intervals at hand: every sum of them is a lazy
  // construction of two such points instead of a chain of lazy products per coordinate.
  const auto [cosine, sine] = angle.cosSin();
  const ExactFT &c = CGAL::exact(cosine), &s = CGAL::exact(sine);
  Polygon neg;
  ExactFT minX, maxX, minY, maxY;
  bool first = true;
  for (const Point& v : w.robot.vertices()) {
    const auto& e = CGAL::exact(v);
    const ExactFT x = c * e.x() - s * e.y(), y = s * e.x() + c * e.y();
    neg.push_back(exactPoint(-x, -y));
    if (first || x < minX) minX = x;
    if (first || x > maxX) maxX = x;
    if (first || y < minY) minY = y;
    if (first || y > maxY) maxY = y;
    first = false;
  }
  // Reference points that keep the rotated robot inside the bounds.
  const ExactFT xlo = ExactFT(w.bounds.xmin) - minX, xhi = ExactFT(w.bounds.xmax) - maxX;
  const ExactFT ylo = ExactFT(w.bounds.ymin) - minY, yhi = ExactFT(w.bounds.ymax) - maxY;
  if (!(xlo < xhi && ylo < yhi)) return;  // the robot does not fit at this angle
  Polygon region;
  region.push_back(exactPoint(xlo, ylo));
  region.push_back(exactPoint(xhi, ylo));
  region.push_back(exactPoint(xhi, yhi));
  region.push_back(exactPoint(xlo, yhi));

  impl_->neg = neg;
  impl_->negConvex = w.robotConvex;
  impl_->regionBox = {CGAL::to_double(region[0].x()), CGAL::to_double(region[0].y()),
                      CGAL::to_double(region[2].x()), CGAL::to_double(region[2].y())};
  impl_->negBox = boundingBox(exact::toDouble(neg));
  std::vector<PolygonWithHoles> sums;
  try {
    reachingSums(w, neg, w.robotConvex, impl_->negBox, impl_->regionBox, sums);
    impl_->exactPart = std::make_unique<Impl::Exact>();
    impl_->exactPart->free = PolygonSet(region);
    if (!sums.empty()) subtractUnion(impl_->exactPart->free, sums);
  } catch (const Stopped&) {
    freeLaterMoved(sums);
    freeLater(std::move(impl_));
    throw;
  }
  index(strategy);
}

Slice::Slice(const Slice& carrier, const Slice& attached, Vec2 offset, PointLocation strategy)
    : impl_(std::make_shared<Impl>()), angle_(carrier.angle_), theta_(carrier.theta_) {
  const Impl& c = *carrier.impl_;
  impl_->neg = c.neg;
  impl_->negConvex = c.negConvex;
  impl_->negBox = c.negBox;
  impl_->regionBox = c.regionBox;
  if (c.cells.empty() || attached.impl_->cells.empty()) return;
  rebuildExact(*carrier.impl_);
  rebuildExact(*attached.impl_);
  checkpoint();
  const auto [cs, sn] = angle_.cosSin();
  const FT ox(offset.x), oy(offset.y);
  const auto dx = CGAL::exact(-(cs * ox - sn * oy)), dy = CGAL::exact(-(sn * ox + cs * oy));
  std::vector<PolygonWithHoles> faces;
  attached.impl_->exactPart->free.polygons_with_holes(std::back_inserter(faces));
  std::vector<PolygonWithHoles> movedFaces;
  for (const PolygonWithHoles& f : faces) movedFaces.push_back(translated(f, dx, dy));
  // An aggregated join: faces of a polygon set may touch at vertices, which insert() forbids.
  PolygonSet moved;
  moved.join(movedFaces.begin(), movedFaces.end());
  impl_->exactPart = std::make_unique<Impl::Exact>();
  impl_->exactPart->free = c.exactPart->free;
  impl_->exactPart->free.intersection(moved);
  index(strategy);
}

Slice::~Slice() = default;
Slice::Slice(Slice&&) noexcept = default;
Slice& Slice::operator=(Slice&&) noexcept = default;

size_t Slice::fscCount() const { return impl_->cells.size(); }
const std::vector<Ring>& Slice::cell(size_t i) const { return impl_->cells[i]->rings; }
double Slice::area(size_t i) const { return impl_->cells[i]->area; }

namespace {

// Whether p is inside ring r (crossing number), or nullopt when p lies within `margin` of one
// of its edges. Away from every edge by more than the rounding of the rings' coordinates (the
// exact vertices converted to doubles), the answer is the exact one.
std::optional<bool> insideRing(const Ring& r, Vec2 p, double margin) {
  bool inside = false;
  const double margin2 = margin * margin;
  for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
    const Vec2 a = r[j], b = r[i];
    const Vec2 ab = b - a, ap = p - a;
    const double len2 = dot(ab, ab);
    const double t = len2 > 0 ? std::clamp(dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
    const Vec2 d = ap - t * ab;
    if (dot(d, d) <= margin2) return std::nullopt;
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * ab.x / ab.y) inside = !inside;
  }
  return inside;
}

}  // namespace

// Point location in doubles: planners ask millions of these (line points, fixings, cross
// tests), and CGAL's exact walk costs microseconds each. Only rings whose boxes come within the
// margin of p are scanned (a slice among many obstacles is one cell with a hole per obstacle
// group, and p lies in the boxes of few of them). Gives up (nullopt) near an edge, or once the
// rings to scan pass kMaxScanned vertices: a scan is linear, CGAL's trapezoidal map is not.
std::optional<int> Slice::locateInDoubles(Vec2 p) const {
  constexpr size_t kMaxScanned = 512;
  const Impl& im = *impl_;
  const double margin = 1e-9 * (1 + std::fabs(p.x) + std::fabs(p.y));
  const Box near{p.x - margin, p.y - margin, p.x + margin, p.y + margin};
  size_t scanned = 0;
  int found = -1;
  for (size_t i = 0; i < im.cells.size(); ++i) {
    const std::vector<Ring>& rings = im.cells[i]->rings;
    const std::vector<Box>& boxes = im.cells[i]->boxes;
    bool in = true;  // inside the outer boundary and outside the holes seen so far
    for (size_t k = 0; k < rings.size() && in; ++k) {
      if (!boxes[k].overlaps(near)) {
        in = k > 0;  // off the outer boundary's box: outside; off a hole's box: not in it
        continue;
      }
      if ((scanned += rings[k].size()) > kMaxScanned) return std::nullopt;
      const auto inside = insideRing(rings[k], p, margin);
      if (!inside) return std::nullopt;
      in = *inside == (k == 0);
    }
    if (!in) continue;
    if (found >= 0) return std::nullopt;  // two cells claim p: cannot be, ask CGAL
    found = int(i);
  }
  return found;
}

int Slice::locate(Vec2 p) const {
  if (impl_->cells.empty()) return -1;
  if (impl_->autoUpgrade)
    if (const auto fast = locateInDoubles(p)) return *fast;
  rebuildExact(*impl_);
  Impl::Exact& ex = *impl_->exactPart;
  const Point q = exact::toExact(p);
  int result = -1;
  auto answer = [&](const auto& obj) {
    if (const auto* f = boost::get<Arrangement::Face_const_handle>(&obj)) {
      auto it = ex.faceIndex.find(&**f);
      if (it != ex.faceIndex.end()) result = it->second;
    }
  };
  if (impl_->autoUpgrade) {
    if (ex.queries.fetch_add(1, std::memory_order_relaxed) + 1 >= Impl::kUpgradeAfter) {
      std::call_once(ex.upgradeOnce, [&] {
        ex.upgraded = std::make_unique<Trapezoid>(ex.free.arrangement());
        ex.upgradedReady.store(true, std::memory_order_release);
      });
    }
    if (ex.upgradedReady.load(std::memory_order_acquire)) {
      answer(ex.upgraded->locate(q));
      return result;
    }
  }
  std::visit(
      [&](const auto& pl) {
        using T = std::decay_t<decltype(pl)>;
        if constexpr (std::is_same_v<T, Walk>)
          answer(pl.locate(q));
        else if constexpr (!std::is_same_v<T, std::monostate>)
          answer(pl->locate(q));
      },
      ex.locator);
  return result;
}

}  // namespace mms
