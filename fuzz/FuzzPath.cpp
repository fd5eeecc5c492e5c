// libFuzzer target: path files against a fixed two-robot scene (one rigid robot, one
// translating part), and the round trip through the writer. Same rules as FuzzScene.cpp.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "FuzzSupport.h"
#include "io/Json.h"
#include "io/PathIO.h"
#include "io/SceneIO.h"

namespace {

const mms::Scene& fixedScene() {
  static const mms::Scene scene = mms::parseScene(mms::json_in::parseText(R"({
    "format": "mms-scene/1", "name": "fuzz",
    "bounds": [0, 0, 10, 10],
    "obstacles": [[[4, 4], [6, 4], [6, 6], [4, 6]]],
    "robots": [
      {"name": "a", "shape": [[0, 0], [1, 0], [0, 1]], "start": [1, 1, 0], "goal": [8, 8, 1]},
      {"name": "b", "motion": "translate", "shape": [[0, 0], [1, 0], [1, 1], [0, 1]],
       "start": [8, 1, 0], "goal": [1, 8, 0]}]})",
                                                                          "fixed"),
                                                  "fixed");
  return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace mms;
  const Scene& scene = fixedScene();
  const std::string text(reinterpret_cast<const char*>(data), size);
  // OMPL.app's .path text too: mms reads it wherever it reads a path (files named *.path).
  if (!text.empty() && text[0] != '{') {
    try {
      const std::vector<Config> w = parseOmplPath(text, "fuzz.path", scene);
      fuzz::require(!w.empty(), "an OMPL path without waypoints was accepted");
      for (const Config& q : w) fuzz::require(q.size() == 6, "a waypoint of the wrong size");
    } catch (const InputError& e) {
      fuzz::requireOneLine(e, "fuzz.path: ");
    }
    return 0;
  }
  try {
    const Path path =
        parsePath(json_in::parseText(text, "fuzz.path.json"), "fuzz.path.json", scene);
    fuzz::require(!path.waypoints.empty(), "a path without waypoints was accepted");
    const nlohmann::json written = pathToJson(path, scene);
    const Path again = parsePath(written, "written.path.json", scene);
    fuzz::require(again.waypoints == path.waypoints && pathToJson(again, scene) == written,
                  "path does not read back as written");
  } catch (const InputError& e) {
    fuzz::requireOneLine(e, "fuzz.path.json: ");
  }
  return 0;
}
