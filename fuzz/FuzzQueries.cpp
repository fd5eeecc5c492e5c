// libFuzzer target: mms-queries/1 files (several queries on one roadmap) against a fixed
// one-robot scene. Same rules as FuzzScene.cpp; every accepted pose is free.
#include <cstdint>
#include <string>

#include "FuzzSupport.h"
#include "geometry/CollisionChecker.h"
#include "io/Json.h"
#include "io/QueriesIO.h"
#include "io/SceneIO.h"

namespace {

const mms::Scene& fixedScene() {
  static const mms::Scene scene = mms::parseScene(mms::json_in::parseText(R"({
    "format": "mms-scene/1", "name": "fuzz", "bounds": [0, 0, 10, 10],
    "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]],
    "robots": [{"name": "a", "shape": [[0, 0], [1, 0], [0, 1]], "start": [1, 1, 0],
                "goal": [8, 8, 1]}]})",
                                                                          "fixed"),
                                                  "fixed");
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace mms;
  const Scene& scene = fixedScene();
  static const CollisionChecker checker(scene);
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto queries = parseQueries(json_in::parseText(text, "fuzz.json"), "fuzz.json", scene);
    fuzz::require(!queries.empty(), "a queries file without queries was accepted");
    for (const Query& q : queries)
      fuzz::require(checker.isFree({q.start.x, q.start.y, q.start.theta}) &&
                        checker.isFree({q.goal.x, q.goal.y, q.goal.theta}),
                    "a query pose that is not free was accepted");
  } catch (const InputError& e) {
    fuzz::requireOneLine(e, "fuzz.json: ");
  }
  return 0;
}
