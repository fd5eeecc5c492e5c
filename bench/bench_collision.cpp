// Cost of the collision checker the baselines plan with, and of the clearance query the path
// checker uses. Scene: the reference, a 10-vertex non-convex robot among 20
// non-convex obstacles of 8 vertices.
#include <benchmark/benchmark.h>

#include <cmath>

#include "geometry/CollisionChecker.h"
#include "scenarios/Generators.h"
#include "io/SceneIO.h"

using namespace mms;

namespace {

struct Fixture {
  Scene scene;
  std::vector<Pose> poses;
  Fixture() {
    RandomPolygonsSettings st;
    st.seed = 7;
    scene = parseScene(sceneToJson(randomPolygonsScene(st)), "generated");
    Random rng(1);
    const Box& b = scene.bounds;
    for (int i = 0; i < 4096; ++i)
      poses.push_back(
          {rng.uniform(b.xmin, b.xmax), rng.uniform(b.ymin, b.ymax), rng.uniform(-M_PI, M_PI)});
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

}  // namespace
