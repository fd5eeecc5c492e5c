// libFuzzer target: COLLADA meshes as OMPL.app's planar problems store them (XML, references
// by id, node matrices, triangles). Same rules as FuzzScene.cpp; the triangles must be finite.
#include <cmath>
#include <cstdint>
#include <string>

#include "FuzzSupport.h"
#include "io/Collada.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace mms;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const ColladaMesh m = parseColladaPlanar(text, "fuzz.dae");
    for (const auto& t : m.triangles)
      for (const Vec2& v : t)
        fuzz::require(std::isfinite(v.x) && std::isfinite(v.y), "a vertex is not finite");
  } catch (const InputError& e) {
    fuzz::requireOneLine(e, "fuzz.dae: ");
  }
  return 0;
}
