// Cost of optimising a path of many robots moved one at a time (the ordered planner's paths:
// a waypoint per move, every robot in every waypoint). An attempt must cost what its stretch
// does, not a copy of the path: time per k should grow about linearly, not as k^2 or k^3.
#include <benchmark/benchmark.h>

#include <map>

#include "mms/Planner.h"
#include "path/Optimize.h"
#include "scenarios/Generators.h"

using namespace mms;

namespace {

struct Planned {
  Scene scene;
  std::vector<Config> path;
};

// Unit discs on a grid (spacing 5 radii) moved to the grid beside it, planned once per k.
const Planned& planned(size_t k) {
  static std::map<size_t, Planned> cache;
  auto [it, added] = cache.try_emplace(k);
  if (added) {
    it->second.scene = discGridScene(1, k, 5);
    PlannerParams params;
    params.values["optimize"] = 0;
    const PlanResult r =
        makePlanner("mms-ordered", it->second.scene, params)->solve(Termination(60));
    it->second.path = r.waypoints;
  }
  return it->second;
}

void BM_OptimizeOneAtATime(benchmark::State& state) {
  const Planned& p = planned(size_t(state.range(0)));
  if (p.path.empty()) {
    state.SkipWithError("no path planned");
    return;
  }
  const CollisionChecker checker(p.scene);
  for (auto _ : state) {
    std::vector<Config> w = p.path;
    Random rng(1);
    benchmark::DoNotOptimize(
        optimizePath(p.scene, checker, rng, OptimizeSettings{}, Termination(60), w));
  }
  state.counters["waypoints"] = double(p.path.size());
}
BENCHMARK(BM_OptimizeOneAtATime)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->Arg(800)
    ->Unit(benchmark::kMillisecond);

}  // namespace
