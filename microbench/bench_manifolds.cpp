// Cost of MMS's building blocks on the reference scene (10-vertex non-convex robot, 20
// obstacles of 8 vertices): one slice, one line, one point location per strategy, and one whole
// query on bundled scenes.
#include <benchmark/benchmark.h>

#include <cmath>

#include "geometry/Exact.h"
#include "io/SceneIO.h"
#include "manifolds/Line.h"
#include "manifolds/Slice.h"
#include "planner/OneRobotPlanner.h"
#include "scenarios/Generators.h"

using namespace mms;

namespace {
PoseTest freeTest(const CollisionChecker& c) {
  return [&c](const Pose& q) { return c.robotFree(0, q); };
}
}  // namespace

namespace {

const Scene& referenceScene() {
  static const Scene s = [] {
    RandomPolygonsSettings st;
    st.seed = 7;
    return parseScene(sceneToJson(randomPolygonsScene(st)), "generated");
  }();
  return s;
}

// Slices of robot 0 of `scene` at random angles, one an iteration; their cells a slice.
double sliceLoop(benchmark::State& state, const Scene& scene) {
  const SliceWorld world(scene, 0);
  Random rng(1);
  size_t cells = 0;
  for (auto _ : state) {
    const Slice s(world, exact::rationalAngleNear(rng.uniform(-M_PI, M_PI), 30));
    cells += s.fscCount();
  }
  return double(cells) / double(state.iterations());
}

void BM_Slice(benchmark::State& state) {
  state.counters["cells"] = sliceLoop(state, referenceScene());
}
BENCHMARK(BM_Slice)->Unit(benchmark::kMillisecond);

// A small scene (three rectangles, two 5-gons): what a slice and an overlay cost apart from the
// size of their arrangements, which is most of two-robot planning on corridors and niches.
const Scene& nicheScene() {
  static const Scene s = nicheSwapScene(1, 0.5);
  return s;
}

void BM_SliceSmall(benchmark::State& state) { sliceLoop(state, nicheScene()); }
BENCHMARK(BM_SliceSmall)->Unit(benchmark::kMicrosecond);

// The same with each robot replaced by its convex hull: what the reduced convolution of a
// non-convex robot costs over summing convex pairs directly.
void BM_SliceSmallHull(benchmark::State& state) {
  Scene sc = nicheScene();
  for (Robot& r : sc.robots) r.shape = exact::convexHull(r.shape);
  sliceLoop(state, sc);
}
BENCHMARK(BM_SliceSmallHull)->Unit(benchmark::kMicrosecond);

// Robot 0's slice with robot 1 held at its start, as a two-robot subspace builds it.
void BM_OverlaySmall(benchmark::State& state) {
  const Scene& sc = nicheScene();
  const SliceWorld world(sc, 0);
  const Slice base(world, exact::rationalAngleNear(0.3, 30));
  const Pose held = sc.robots[1].start;
  const MovedShape m{
      1, held.theta, placedRing(sc.robots[1].shape, {0, 0, held.theta}), {held.x, held.y}};
  for (auto _ : state) {
    const Slice s(base, {m});
    benchmark::DoNotOptimize(s.fscCount());
  }
}
BENCHMARK(BM_OverlaySmall)->Unit(benchmark::kMicrosecond);

void BM_Line(benchmark::State& state) {
  const Scene& s = referenceScene();
  const LineWorld world(s, 0);
  const CollisionChecker checker(s);
  Random rng(2);
  LineStats stats;
  for (auto _ : state) {
    const Line line(world, freeTest(checker), {rng.uniform(-50, 50), rng.uniform(-50, 50)}, &stats);
    benchmark::DoNotOptimize(line.arcs().size());
  }
  state.counters["candidates"] = double(stats.candidates) / double(state.iterations());
  state.counters["exact_fallbacks"] = double(stats.exactFallbacks);
}
BENCHMARK(BM_Line)->Unit(benchmark::kMicrosecond);

template <PointLocation kStrategy>
void BM_Locate(benchmark::State& state) {
  const SliceWorld world(referenceScene(), 0);
  const Slice slice(world, exact::rationalAngleNear(0.3, 30), kStrategy);
  Random rng(3);
  std::vector<Vec2> points;
  for (int i = 0; i < 1024; ++i) points.push_back({rng.uniform(-50, 50), rng.uniform(-50, 50)});
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(slice.locate(points[i++ & 1023]));
}
BENCHMARK(BM_Locate<PointLocation::Walk>)->Name("BM_Locate/walk");
BENCHMARK(BM_Locate<PointLocation::Auto>)->Name("BM_Locate/auto");
BENCHMARK(BM_Locate<PointLocation::Trapezoid>)->Name("BM_Locate/trapezoid");
BENCHMARK(BM_Locate<PointLocation::Landmarks>)->Name("BM_Locate/landmarks");

template <PointLocation kStrategy>
void BM_SliceWithLocator(benchmark::State& state) {
  const SliceWorld world(referenceScene(), 0);
  for (auto _ : state)
    benchmark::DoNotOptimize(Slice(world, exact::rationalAngleNear(0.3, 30), kStrategy).fscCount());
}
BENCHMARK(BM_SliceWithLocator<PointLocation::Walk>)
    ->Name("BM_SliceBuild/walk")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SliceWithLocator<PointLocation::Trapezoid>)
    ->Name("BM_SliceBuild/trapezoid")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SliceWithLocator<PointLocation::Landmarks>)
    ->Name("BM_SliceBuild/landmarks")
    ->Unit(benchmark::kMillisecond);

// A whole query (fresh planner each time) on a bundled scene; seeds cycle so the figure is
// a mean over seeds.
void BM_Query(benchmark::State& state, const char* file) {
  const Scene s = loadScene(std::string(MMS_SOURCE_DIR) + "/scenes/" + file);
  uint64_t seed = 0;
  for (auto _ : state) {
    OneRobotSettings st;
    st.seed = ++seed;
    OneRobotPlanner planner(s, 0, st);
    const OneRobotResult r = planner.solve(s.robots[0].start, s.robots[0].goal, Termination(60));
    if (r.status != PlanStatus::Found) state.SkipWithError("no path");
  }
}
BENCHMARK_CAPTURE(BM_Query, bar_slot, "one-robot/bar-slot.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Query, bug_trap, "one-robot/bug-trap.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Query, maze, "one-robot/maze.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Query, corridor_corner, "one-robot/corridor-corner.json")
    ->Unit(benchmark::kMillisecond);

}  // namespace
