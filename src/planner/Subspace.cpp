#include "planner/Subspace.h"

#include "mms/Termination.h"
#include "util/Parallel.h"

namespace mms {

namespace {
// Held robots as turned shapes moved to their positions: overlays then share one Minkowski sum
// per robot and angle.
std::vector<MovedShape> movedShapes(const Scene& scene,
                                    const std::vector<std::pair<size_t, Pose>>& held) {
  std::vector<MovedShape> out;
  for (const auto& [robot, pose] : held)
    out.push_back({robot,
                   pose.theta,
                   placedRing(scene.robots[robot].shape, {0, 0, pose.theta}),
                   {pose.x, pose.y}});
  return out;
}
std::vector<Ring> placedRings(const std::vector<MovedShape>& shapes) {
  std::vector<Ring> out;
  for (const MovedShape& m : shapes) out.push_back(m.placed());
  return out;
}
}  // namespace

double buildSlices(const SliceWorld& world, const std::vector<double>& thetas, unsigned threads,
                   PointLocation strategy, const std::function<void(Slice&&)>& add) {
  const size_t batch = std::max(1u, threads);
  double seconds = 0;
  for (size_t done = 0; done < thetas.size();) {
    checkpoint();  // the limit, between batches
    const size_t n = std::min(batch, thetas.size() - done);
    std::vector<std::optional<Slice>> built(n);
    Stopwatch watch;
    const auto errors = parallelFor(n, threads, [&](size_t i) {
      built[i].emplace(world, exact::rationalAngleNear(thetas[done + i], 30), strategy);
    });
    seconds += watch.seconds();
    for (size_t i = 0; i < n; ++i) {
      if (errors[i]) std::rethrow_exception(errors[i]);
      add(std::move(*built[i]));
    }
    done += n;
  }
  return seconds;
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
                   std::vector<std::pair<size_t, Pose>> held, ConnectivityGraph& graph,
                   SubspaceStats& stats)
    : id_(id),
      checker_(checker),
      moving_(moving),
      held_(std::move(held)),
      heldShapes_(movedShapes(scene, held_)),
      heldRings_(placedRings(heldShapes_)),
      lineWorld_(scene, moving, heldRings_),
      graph_(graph),
      stats_(stats) {}

bool Subspace::free(const Pose& q) const {
  if (!checker_.robotFree(moving_, q)) return false;
  for (const auto& [robot, pose] : held_)
    if (!checker_.robotsDisjoint(moving_, q, robot, pose)) return false;
  return true;
}

void Subspace::connect(const Slice& slice, const std::vector<size_t>& nodes, size_t l) {
  const int a = lines_[l].arcContaining(slice.theta());
  if (a < 0) return;
  const int f = slice.locate(lines_[l].point());
  if (f >= 0) graph_.addEdge(nodes[size_t(f)], lineNodes_[l][size_t(a)]);
}

std::vector<size_t> Subspace::addCellNodes(const Slice& slice, uint32_t manifold) {
  std::vector<size_t> nodes;
  for (size_t f = 0; f < slice.fscCount(); ++f)
    nodes.push_back(
        graph_.addNode({ConnectivityGraph::Kind::SliceCell, id_, manifold, uint32_t(f)}));
  ++stats_.slices;
  stats_.sliceCells += slice.fscCount();
  return nodes;
}

void Subspace::addLocalOverlay(Slice slice) {
  localSlices_.push_back(std::move(slice));
  const size_t k = localSlices_.size() - 1;
  localNodes_.push_back(addCellNodes(localSlices_[k], kLocal | uint32_t(k)));
  ++stats_.localSlices;
  connectToLines(localSlices_[k], localNodes_[k]);
}

void Subspace::connectToLines(const Slice& slice, const std::vector<size_t>& nodes) {
  Stopwatch watchConnect;
  if (slice.fscCount() > 0)
    for (size_t l = 0; l < lines_.size(); ++l) connect(slice, nodes, l);
  stats_.connectSeconds += watchConnect.seconds();
}

Slice Subspace::overlay(const Slice& base) const { return Slice(base, heldShapes_); }

size_t Subspace::addSlice(const Slice& base) {
  Stopwatch watch;
  Slice slice = overlay(base);
  stats_.sliceSeconds += watch.seconds();
  return addOverlay(std::move(slice));
}

size_t Subspace::addOverlay(Slice slice) {
  slices_.push_back(std::move(slice));
  const size_t k = slices_.size() - 1;
  sliceNodes_.push_back(addCellNodes(slices_[k], uint32_t(k)));
  connectToLines(slices_[k], sliceNodes_[k]);
  return k;
}

size_t Subspace::addLine(Vec2 p) {
  Stopwatch watch;
  lines_.emplace_back(
      lineWorld_, [this](const Pose& q) { return free(q); }, p, &stats_.lineStats);
  stats_.lineSeconds += watch.seconds();
  const size_t l = lines_.size() - 1;
  std::vector<size_t> nodes;
  for (size_t a = 0; a < lines_[l].arcs().size(); ++a)
    nodes.push_back(
        graph_.addNode({ConnectivityGraph::Kind::LineArc, id_, uint32_t(l), uint32_t(a)}));
  lineNodes_.push_back(std::move(nodes));
  ++stats_.lines;
  stats_.lineArcs += lines_[l].arcs().size();
  Stopwatch watchConnect;
  if (!lines_[l].arcs().empty()) {
    for (size_t k = 0; k < slices_.size(); ++k) connect(slices_[k], sliceNodes_[k], l);
    for (size_t k = 0; k < localSlices_.size(); ++k) connect(localSlices_[k], localNodes_[k], l);
  }
  stats_.connectSeconds += watchConnect.seconds();
  return l;
}

long Subspace::sliceNodeAt(size_t k, Vec2 p, bool knownFree) const {
  if (k >= slices_.size()) return -1;  // a subspace cut short by the time limit
  if (knownFree && slices_[k].fscCount() == 1) return long(sliceNodes_[k][0]);
  const int f = slices_[k].locate(p);
  return f < 0 ? -1 : long(sliceNodes_[k][f]);
}

long Subspace::lineNodeAt(size_t l, double theta) const {
  if (l >= lines_.size()) return -1;
  const int a = lines_[l].arcContaining(theta);
  return a < 0 ? -1 : long(lineNodes_[l][a]);
}

}  // namespace mms
