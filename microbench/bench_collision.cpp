// Cost of the collision checker the baselines plan with, of the clearance query the path
// checker uses, and of the two straight-motion tests built on it: the certifier's (with its
// report) and the one a sampler asks of every motion it adds. Scene: a 10-vertex non-convex
// robot among 20 non-convex obstacles of 8 vertices; and the certifier on several robots at
// once (five 16-gons round a block, mms scenario discs-swap), whose evaluations test every pair.
#include <benchmark/benchmark.h>

#include <cmath>

#include "check/PathChecker.h"
#include "geometry/CollisionChecker.h"
#include "io/SceneIO.h"
#include "scenarios/Generators.h"

using namespace mms;

namespace {

struct Fixture {
  Scene scene;
  std::vector<Pose> poses;
  /// Short motions from each pose, a twentieth of the box and up to half a turn: the size of
  /// a sampler's extensions.
  std::vector<Config> from, to;
  Fixture() {
    RandomPolygonsSettings st;
    st.seed = 7;
    scene = parseScene(sceneToJson(randomPolygonsScene(st)), "generated");
    Random rng(1);
    const Box& b = scene.bounds;
    for (int i = 0; i < 4096; ++i)
      poses.push_back(
          {rng.uniform(b.xmin, b.xmax), rng.uniform(b.ymin, b.ymax), rng.uniform(-M_PI, M_PI)});
    const double step = 0.05 * std::max(b.xmax - b.xmin, b.ymax - b.ymin);
    for (const Pose& p : poses) {
      from.push_back({p.x, p.y, p.theta});
      to.push_back({p.x + rng.uniform(-step, step), p.y + rng.uniform(-step, step),
                    p.theta + rng.uniform(-M_PI / 2, M_PI / 2)});
    }
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

void BM_RobotFree(benchmark::State& state) {
  const Fixture& f = fixture();
  const CollisionChecker checker(f.scene);
  size_t i = 0, free = 0;
  for (auto _ : state) {
    free += checker.robotFree(0, f.poses[i++ & 4095]);
  }
  state.counters["free_fraction"] = double(free) / double(state.iterations());
}
BENCHMARK(BM_RobotFree);

void BM_RobotClearance(benchmark::State& state) {
  const Fixture& f = fixture();
  const CollisionChecker checker(f.scene);
  size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(checker.robotClearance(0, f.poses[i++ & 4095]).distance);
}
BENCHMARK(BM_RobotClearance);

void BM_MotionFree(benchmark::State& state) {
  const Fixture& f = fixture();
  const CollisionChecker checker(f.scene);
  size_t i = 0, free = 0;
  for (auto _ : state) {
    free += motionFree(checker, f.from[i & 4095], f.to[i & 4095]);
    ++i;
  }
  state.counters["free_fraction"] = double(free) / double(state.iterations());
}
BENCHMARK(BM_MotionFree);

void BM_CheckMotion(benchmark::State& state) {
  const Fixture& f = fixture();
  const CollisionChecker checker(f.scene);
  size_t i = 0, free = 0;
  std::vector<Config> segment(2);
  for (auto _ : state) {
    segment[0] = f.from[i & 4095];
    segment[1] = f.to[i & 4095];
    free += checkMotion(f.scene, checker, segment).ok;
    ++i;
  }
  state.counters["free_fraction"] = double(free) / double(state.iterations());
}
BENCHMARK(BM_CheckMotion);

// Short motions of all five at once from free placements near their starts, each robot moved
// up to a fifth of its size: every evaluation tests each robot against the block and each pair.
void BM_CheckMotionFiveRobots(benchmark::State& state) {
  const Scene scene = discsSwapScene(3);
  const CollisionChecker checker(scene);
  Config start;
  for (const Robot& r : scene.robots) start.insert(start.end(), {r.start.x, r.start.y, 0.0});
  const double step = 0.2 * checker.radius(0);
  Random rng(2);
  auto near = [&](const Config& q) {
    Config out = q;
    for (size_t c = 0; c < out.size(); c += 3)
      out[c] += rng.uniform(-step, step), out[c + 1] += rng.uniform(-step, step);
    return out;
  };
  std::vector<std::vector<Config>> pieces;
  while (pieces.size() < 256) {
    const Config a = near(start), b = near(a);
    if (checker.isFree(a) && checker.isFree(b)) pieces.push_back({a, b});
  }
  size_t i = 0, free = 0;
  for (auto _ : state) free += checkMotion(scene, checker, pieces[i++ & 255]).ok;
  state.counters["free_fraction"] = double(free) / double(state.iterations());
}
BENCHMARK(BM_CheckMotionFiveRobots);

}  // namespace
