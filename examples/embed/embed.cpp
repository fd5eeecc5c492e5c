// embed SCENE OUT.json: loads a scene (any format mms reads), plans with the default planner and
// writes the certified path. Exit 0 path written, 1 no path within the time limit, 2 bad input.
#include <mms/mms.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: embed SCENE OUT.json\n");
    return 2;
  }
  try {
    const mms::Scene scene = mms::readSceneFile(argv[1]);
    mms::PlannerParams params;
    params.seed = 1;
    const auto planner = mms::makePlanner(mms::kDefaultPlanner, scene, params, argv[1]);
    const mms::PlanResult result = planner->solve(mms::Termination(60.0));
    if (!result.found()) {
      std::printf("%s: no path found (%s)\n", argv[1], mms::toString(result.status));
      return 1;
    }
    // Found paths come certified; a program may check again, as any path can be.
    const mms::PathCheckResult check = mms::certify(scene, result.waypoints);
    if (!check.ok) {
      std::fprintf(stderr, "%s: the path failed certification: %s\n", argv[1],
                   check.reason.c_str());
      return 3;
    }
    mms::writePathFile(scene, result, mms::kDefaultPlanner, params.seed, argv[2]);
    std::printf("%s: %zu waypoints, %.3f s, mms %s\n", argv[2], result.waypoints.size(),
                result.stats.seconds, mms::version());
    return 0;
  } catch (const mms::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
}
