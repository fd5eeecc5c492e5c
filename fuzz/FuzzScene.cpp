// libFuzzer target: scene files (parse, validate) and the round trip through the writer.
// Any exception other than InputError, a message that is not one line naming the file, or a
// scene that does not read back as written is a bug: the target aborts and libFuzzer keeps the
// input. Run: scripts/fuzz.sh (docs/robustness.md).
#include <cstdint>
#include <cstdlib>
#include <string>

#include "FuzzSupport.h"
#include "io/Json.h"
#include "io/SceneIO.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace mms;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Scene scene = parseScene(json_in::parseText(text, "fuzz.json"), "fuzz.json");
    const nlohmann::json written = sceneToJson(scene);
    const Scene again = parseScene(written, "written.json");
    fuzz::require(sceneToJson(again) == written, "scene does not read back as written");
  } catch (const InputError& e) {
    fuzz::requireOneLine(e, "fuzz.json: ");
  }
  return 0;
}
