#pragma once
// The manifold seam: what the roadmap, the search and the path stage need of a manifold
// family, and nothing else. MMS samples low-dimensional manifolds of the C-space, decomposes
// each exactly into free-space cells (FSCs) and joins cells of manifolds that meet (the
// paper, Section III). A family (fixed-angle slices, fixed-position lines, ...) is one class
// implementing Manifold plus its rows in the meeting table (Meets.cpp); the graph, the search
// and the motion along a graph path work on any family through this interface.
#include <optional>
#include <vector>

#include "mms/Record.h"
#include "mms/Scene.h"

namespace mms {

/// A family's identity: one static object per family, compared by address.
struct ManifoldFamily {
  const char* name;
};

/// A manifold of the C-space of all the scene's robots (configurations of every robot, as
/// Config), decomposed into cells numbered 0 .. cellCount() - 1.
class Manifold {
 public:
  virtual ~Manifold() = default;
  virtual const ManifoldFamily& family() const = 0;
  virtual size_t cellCount() const = 0;
  /// The cell whose interior holds q (a configuration on this manifold), or -1.
  virtual long locate(const Config& q) const = 0;
  /// A motion inside cell `cell` from `from` to `to`, both in the cell: the waypoints after
  /// `from`, the last at `to` (angles up to whole turns: the motion unwinds them so the path
  /// stays continuous). Nothing if no route is found.
  virtual std::optional<std::vector<Config>> motion(size_t cell, const Config& from,
                                                    const Config& to) const = 0;
  /// What a record of the planning shows of it (mms/Record.h): its family's name and, when
  /// `geometry`, its shape (a slice's angle and cells, a line's point and arcs). A family
  /// that overrides nothing is recorded by name and cell count alone.
  virtual void sketch(RecordManifold& out, bool geometry) const {
    (void)geometry;
    out.family = family().name;
    out.cells = cellCount();
  }
  /// Which robot moves on it and where the others are held.
  virtual void sketchFrame(RecordSubspace& out) const { (void)out; }
};

/// A manifold in a frame (which robots move and which are held, or which carries which) that
/// fixes some coordinates of the robot it moves: which (bits kX | kY | kTheta) and their values
/// (the other fields 0). Slices fix the angle, lines the position.
template <class Frame>
class FramedManifold : public Manifold {
 public:
  enum : unsigned { kX = 1, kY = 2, kTheta = 4 };
  explicit FramedManifold(const Frame& frame) : frame_(&frame) {}
  const Frame& frame() const { return *frame_; }
  void sketchFrame(RecordSubspace& out) const override { frame_->describe(out); }
  virtual unsigned fixes() const = 0;
  virtual Pose fixedAt() const = 0;

 private:
  const Frame* frame_;
};

/// Where two manifolds of one frame that fix complementary coordinates of its moving body (a
/// slice's angle, a line's position) meet: the body's pose; false if they do not fix them
/// between them, or both fix some (two slices or two lines share no single point).
template <class Frame>
bool jointPose(const FramedManifold<Frame>& a, const FramedManifold<Frame>& b, Pose& out) {
  using F = FramedManifold<Frame>;
  if ((a.fixes() | b.fixes()) != (F::kX | F::kY | F::kTheta) || (a.fixes() & b.fixes()) != 0)
    return false;
  const Pose pa = a.fixedAt(), pb = b.fixedAt();
  out = {a.fixes() & F::kX ? pa.x : pb.x, a.fixes() & F::kY ? pa.y : pb.y,
         a.fixes() & F::kTheta ? pa.theta : pb.theta};
  return true;
}

/// A manifold that is a view of item `index` of a vector its planner keeps (the vector may grow;
/// the index stays): Base is the family's frame-holding base class.
template <class Base, class Item>
class StoredView : public Base {
 public:
  template <class Frame>
  StoredView(const Frame& frame, const std::vector<Item>& store, size_t index)
      : Base(frame), store_(&store), index_(index) {}
  const Item& item() const { return (*store_)[index_]; }

 private:
  const std::vector<Item>* store_;
  size_t index_;
};

/// A rule for one pair of families: whether two manifolds meet, and where (`at`, a
/// configuration on both, written in place: joins run once per pair of manifolds, the
/// roadmap's hottest loop, and allocate nothing). Every family here meets another in at most
/// one point, so one configuration names the meeting; the cells that meet are the ones that
/// locate it.
using MeetRule = bool (*)(const Manifold& a, const Manifold& b, Config& at);
struct MeetEntry {
  const ManifoldFamily* a;
  const ManifoldFamily* b;
  MeetRule rule;  // called as rule(manifold of a, manifold of b, at)
};

/// The table of rules (Meets.cpp): one row per pair of families that meet, either order.
const std::vector<MeetEntry>& meetRules();
/// Adds a row for a family defined outside the library (or a test's). Not thread-safe: add
/// rows before planning starts.
void addMeetRule(const MeetEntry& entry);

/// Whether a and b meet by the table's rule for their families, and where (`at`); false if
/// they do not or no rule covers the pair.
bool meet(const Manifold& a, const Manifold& b, Config& at);
/// The same, returning the meeting point.
std::optional<Config> meetingPoint(const Manifold& a, const Manifold& b);

}  // namespace mms
