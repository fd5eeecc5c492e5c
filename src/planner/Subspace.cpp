#include "planner/Subspace.h"

#include <algorithm>
#include <optional>

#include "mms/Termination.h"
#include "util/Deferred.h"
#include "util/Parallel.h"

namespace mms {

namespace {
// Held robots as turned shapes moved to their positions: overlays then share one Minkowski sum
// per robot and angle.
std::vector<MovedShape> movedShapes(const Scene& scene,
                                    const std::vector<std::pair<size_t, Pose>>& held) {
  std::vector<MovedShape> out;
  for (const auto& [robot, pose] : held) out.push_back(heldShape(scene, robot, pose));
  return out;
}
std::vector<Ring> placedRings(const std::vector<MovedShape>& shapes) {
  std::vector<Ring> out;
  for (const MovedShape& m : shapes) out.push_back(m.placed());
  return out;
}
}  // namespace

void buildSlices(const SliceWorld& world, const std::vector<double>& thetas, unsigned threads,
                 PointLocation strategy, double& seconds, const std::function<void(Slice&&)>& add) {
  const size_t batch = std::max(1u, threads);
  for (size_t done = 0; done < thetas.size();) {
    checkpoint();  // the limit, between batches
    const size_t n = std::min(batch, thetas.size() - done);
    std::vector<std::optional<Slice>> built(n);
    std::vector<std::exception_ptr> errors;
    {
      const TimeCharge charge(seconds);
      errors = parallelFor(n, threads, [&](size_t i) {
        built[i].emplace(world, exact::rationalAngleNear(thetas[done + i], 30), strategy);
      });
    }
    for (size_t i = 0; i < n; ++i) {
      if (errors[i]) rethrowDeferring(errors[i], built);
      add(std::move(*built[i]));
    }
    done += n;
  }
}

MovedShape heldShape(const Scene& scene, size_t robot, const Pose& pose) {
  return {robot,
          pose.theta,
          placedRing(scene.robots[robot].shape, {0, 0, pose.theta}),
          {pose.x, pose.y}};
}

bool cutsNoPassage(const Slice& base, const MovedShape& held) {
  return Slice(base, {held}).fscCount() <= base.fscCount();
}

Vec2 subspaceLinePoint(const std::vector<Slice>& base, const Box& b, Random& rng) {
  if (rng.uniform() < 0.5)
    for (int attempt = 0; attempt < 20; ++attempt) {
      const Vec2 p = rng.uniformIn(b);
      if (base[rng.below(base.size())].locate(p) >= 0) return p;
    }
  return rng.uniformIn(b);
}

std::vector<double> narrowArcMiddles(std::span<const Line> lines, const LineWorld& alone,
                                     const PoseTest& amongObstacles, std::vector<double> met,
                                     double spacing, size_t limit) {
  std::vector<double> middles;
  for (const Line& line : lines) {
    std::optional<Line> bare;  // the line among the obstacles alone, made for its first arc
    for (const Arc& a : line.arcs()) {
      if (middles.size() >= limit) return middles;
      if (a.full() || a.hi - a.lo >= spacing) continue;
      if (std::any_of(met.begin(), met.end(), [&](double t) { return a.contains(t); })) continue;
      const double middle = 0.5 * (a.lo + a.hi);
      if (!bare) bare.emplace(alone, amongObstacles, line.point());
      const int k = bare->arcContaining(middle);
      if (k < 0) continue;  // within a hair of a contact the two tests disagree: nothing to open
      const Arc& own = bare->arcs()[size_t(k)];
      // The obstacles' own arc: as narrow, or within one doubling of the shared angles of it.
      if (!own.full() && own.hi - own.lo < std::min(spacing, 2 * (a.hi - a.lo))) continue;
      middles.push_back(middle);
      met.push_back(middle);
    }
  }
  return middles;
}

Scene withContactShapes(const Scene& scene, const CollisionChecker& checker) {
  Scene out = scene;
  for (Robot& r : out.robots) {
    ShrunkShape s = shrinkForContacts(r.shape, checker.tolerance() / 2);
    if (!s.error) r.shape = std::move(s.ring);  // shrinking by delta worked, so half does too
  }
  return out;
}

Subspace::Subspace(uint32_t id, const Scene& scene, const CollisionChecker& checker, size_t moving,
                   std::vector<std::pair<size_t, Pose>> held, Roadmap& roadmap,
                   SubspaceStats& stats)
    : frame_{id, scene.robots.size(), moving, std::move(held)},
      checker_(checker),
      heldShapes_(std::make_shared<const std::vector<MovedShape>>(movedShapes(scene, frame_.held))),
      heldRings_(placedRings(*heldShapes_)),
      lineWorld_(scene, moving, heldRings_),
      roadmap_(roadmap),
      stats_(stats),
      weave_(roadmap.addWeave()) {}

bool Subspace::free(const Pose& q) const {
  if (!checker_.robotFree(frame_.moving, q)) return false;
  for (const auto& [robot, pose] : frame_.held)
    if (!checker_.robotsDisjoint(frame_.moving, q, robot, pose)) return false;
  return true;
}

// `index` names the slice in `store` (localIndex for a local slice).
uint32_t Subspace::addSliceManifold(const std::vector<Slice>& store, uint32_t index) {
  return addJoinedSlice(roadmap_, stats_,
                        std::make_unique<SliceManifold>(frame_, store, positionOf(index)),
                        frame_.id, index, weave_);
}

void Subspace::addLocalOverlay(Slice slice) {
  localSlices_.push_back(std::move(slice));
  addSliceManifold(localSlices_, localIndex(localSlices_.size() - 1));
  ++stats_.localSlices;
}

Slice Subspace::overlay(const Slice& base) const { return Slice(base, heldShapes_); }

size_t Subspace::addSlice(const Slice& base) {
  std::optional<Slice> slice;
  {
    const TimeCharge charge(stats_.sliceSeconds);
    slice.emplace(overlay(base));
  }
  return addOverlay(std::move(*slice));
}

size_t Subspace::addOverlay(Slice slice) {
  slices_.push_back(std::move(slice));
  const size_t k = slices_.size() - 1;
  sliceIds_.push_back(addSliceManifold(slices_, uint32_t(k)));
  return k;
}

size_t Subspace::addLine(Vec2 p) {
  lineIds_.push_back(addJoinedLine(
      roadmap_, stats_, lines_, lineWorld_, [this](const Pose& q) { return free(q); }, p, frame_.id,
      [this](size_t l) { return std::make_unique<LineManifold>(frame_, lines_, l); }, weave_));
  return lines_.size() - 1;
}

uint32_t Subspace::addWovenLine(std::unique_ptr<Manifold> line, uint32_t index) {
  const uint32_t id = roadmap_.add(std::move(line), frame_.id, index);
  const TimeCharge connect(stats_.connectSeconds);
  roadmap_.weave(weave_, 0, id);
  return id;
}

long Subspace::sliceNodeAt(size_t k, Vec2 p, bool knownFree) const {
  if (k >= slices_.size()) return -1;  // a subspace cut short by the time limit
  if (knownFree && slices_[k].fscCount() == 1) return long(roadmap_.node(sliceIds_[k], 0));
  const int f = slices_[k].locate(p);
  return f < 0 ? -1 : long(roadmap_.node(sliceIds_[k], size_t(f)));
}

long Subspace::lineNodeAt(size_t l, double theta) const {
  if (l >= lines_.size()) return -1;
  const int a = lines_[l].arcContaining(theta);
  return a < 0 ? -1 : long(roadmap_.node(lineIds_[l], size_t(a)));
}

}  // namespace mms
