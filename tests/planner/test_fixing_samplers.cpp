// The fixing samplers through a host written here (the planner's is private): what they hold
// is free, at the robot's angles, and corner fixings find the niche a robot waits in far more
// often than uniform ones.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "geometry/CollisionChecker.h"
#include "planner/FixingSamplers.h"
#include "scenarios/Generators.h"

namespace mms {
namespace {

// A host that only records what is held: the samplers under test read the base slices, the
// bounds and the random stream.
class RecordingHost final : public FixingHost {
 public:
  RecordingHost(const Scene& scene, size_t robot, size_t angles) : scene_(scene), rng_(7) {
    world_ = std::make_unique<SliceWorld>(scene_, robot);
    for (size_t k = 0; k < angles; ++k)
      base_.emplace_back(*world_,
                         exact::rationalAngleNear(2 * M_PI * double(k) / double(angles), 30));
  }
  Random& rng() override { return rng_; }
  const Box& bounds() const override { return scene_.bounds; }
  bool translates(size_t) const override { return false; }
  const std::vector<Slice>& baseSlices(size_t) const override { return base_; }
  const Roadmap& roadmap() const override { return roadmap_; }
  long startNode() const override { return -1; }
  long goalNode() const override { return -1; }
  const std::vector<size_t>& reachedCells(size_t) override { return none_; }
  const Box& cellBox(size_t) const override { return scene_.bounds; }
  const Slice& sliceOf(size_t) const override { return base_.front(); }
  Fixing fixingAt(size_t robot, size_t angle, Vec2 p, long parent) const override {
    return {{{p.x, p.y, base_[angle].theta()}, long(angle), -1}, robot, parent};
  }
  size_t hold(const Fixing& f, const Termination&) override {
    held.push_back(f);
    return held.size() - 1;
  }
  long nodeWhereHeld(size_t, size_t) const override { return -1; }
  bool leavesRoom(const Fixing& f) override { return !blocks || !blocks(f); }
  void countExpanded() override {}

  std::function<bool(const Fixing&)> blocks;  // leavesRoom's answer, negated (none: room)

  std::vector<Fixing> held;

 private:
  Scene scene_;
  Random rng_;
  std::unique_ptr<SliceWorld> world_;
  std::vector<Slice> base_;
  Roadmap roadmap_;
  std::vector<size_t> none_;
};

TEST(FixingSamplers, CornerFixingsAreFreeAndFindTheNicheMoreOftenThanUniformOnes) {
  size_t inNiche[2] = {0, 0};  // corner, uniform
  const int draws = 200;
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const Scene s = nicheSwapScene(seed);
    const CollisionChecker checker(s);
    // The niche: above the corridor, between the two upper wall blocks.
    const double left = s.obstacles[0][1].x, right = s.obstacles[1][0].x;
    const double corridorTop = s.obstacles[0][0].y;
    for (int which = 0; which < 2; ++which) {
      RecordingHost host(s, 0, 8);
      CornerFixings corners;
      UniformFixings uniform;
      for (int i = 0; i < draws; ++i) {
        FixingSampler& sampler = which == 0 ? static_cast<FixingSampler&>(corners) : uniform;
        ASSERT_TRUE(sampler.grow(0, host, Termination(60)));
      }
      ASSERT_EQ(host.held.size(), size_t(draws));
      for (const Fixing& f : host.held) {
        EXPECT_EQ(f.robot, 0u);
        EXPECT_TRUE(checker.robotFree(0, f.pose)) << f.pose.x << " " << f.pose.y;
        inNiche[which] += f.pose.x > left && f.pose.x < right && f.pose.y > corridorTop;
      }
    }
  }
  // The niche is a few percent of the free space by area, and a third or more of its vertices.
  EXPECT_GT(inNiche[0], 2 * inNiche[1]) << inNiche[0] << " vs " << inNiche[1];
  EXPECT_GT(inNiche[0], size_t(0.1 * 3 * draws));
}

// Screened corners hold the first candidate the host says leaves the other robot room, else
// the last one drawn: with a host that calls only niche poses roomy, most fixings land in the
// niche, and none is lost when no candidate qualifies.
TEST(FixingSamplers, ScreenedCornerFixingsHoldTheFirstCandidateThatLeavesRoom) {
  const Scene s = nicheSwapScene(2);
  const double left = s.obstacles[0][1].x, right = s.obstacles[1][0].x;
  const double corridorTop = s.obstacles[0][0].y;
  auto inNiche = [&](const Fixing& f) {
    return f.pose.x > left && f.pose.x < right && f.pose.y > corridorTop;
  };
  const int draws = 200;
  size_t niche[2] = {0, 0};  // screened, unscreened
  for (int which = 0; which < 2; ++which) {
    RecordingHost host(s, 0, 8);
    host.blocks = [&](const Fixing& f) { return !inNiche(f); };
    CornerFixings corners(which == 0 ? 16 : 1);
    for (int i = 0; i < draws; ++i) ASSERT_TRUE(corners.grow(0, host, Termination(60)));
    ASSERT_EQ(host.held.size(), size_t(draws));
    for (const Fixing& f : host.held) niche[which] += inNiche(f);
  }
  EXPECT_GT(niche[0], size_t(0.5 * draws)) << niche[0];
  EXPECT_GT(niche[0], 2 * niche[1]) << niche[0] << " vs " << niche[1];
  // Nothing qualifies: every grow still holds a corner pose.
  RecordingHost none(s, 0, 8);
  none.blocks = [](const Fixing&) { return true; };
  CornerFixings corners(16);
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(corners.grow(0, none, Termination(60)));
  EXPECT_EQ(none.held.size(), 20u);
}

}  // namespace
}  // namespace mms
