// libFuzzer target: discopygal JSON scenes (the importer, and the scene it makes validated as
// any scene is). Same rules as FuzzScene.cpp: only a one-line InputError naming the file.
#include <cstdint>
#include <string>

#include "FuzzSupport.h"
#include "io/Discopygal.h"
#include "io/Json.h"
#include "io/SceneIO.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace mms;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    ImportNotes notes;
    const Scene scene = importDiscopygal(json_in::parseText(text, "fuzz.json"), "fuzz.json", notes);
    fuzz::require(!scene.robots.empty(), "a discopygal scene without robots was accepted");
    ImportNotes exportNotes;
    (void)discopygalJson(scene, exportNotes);  // the exporter takes whatever the importer gives
  } catch (const InputError& e) {
    fuzz::requireOneLine(e, "fuzz.json: ");
  }
  return 0;
}
