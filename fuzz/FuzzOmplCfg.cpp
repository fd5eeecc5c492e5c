// libFuzzer target: the [problem] section of OMPL.app .cfg files (the meshes it names are
// COLLADA, fuzzed by FuzzCollada). Same rules as FuzzScene.cpp.
#include <cmath>
#include <cstdint>
#include <string>

#include "FuzzSupport.h"
#include "io/OmplAppCfg.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace mms;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const OmplAppProblem p = parseOmplAppProblem(text, "fuzz.cfg");
    fuzz::require(!p.robotMesh.empty() && !p.worldMesh.empty(), "a mesh name is empty");
    fuzz::require(
        std::isfinite(p.start.x) && std::isfinite(p.goal.theta) && std::isfinite(p.volume.xmax),
        "a number is not finite");
  } catch (const InputError& e) {
    fuzz::requireOneLine(e, "fuzz.cfg: ");
  }
  return 0;
}
