#include "io/AnyScene.h"

#include <filesystem>

#include "io/Discopygal.h"
#include "io/Json.h"
#include "io/SceneIO.h"

namespace mms {

Scene loadAnyScene(const std::string& file, ImportNotes& notes) {
  const std::filesystem::path ext = std::filesystem::path(file).extension();
  if (ext == ".cfg") return importOmplApp(file, notes);
  // Parsed once, whichever format it turns out to be.
  const json_in::Json doc = json_in::parseFile(file);
  if (ext == ".json" && isDiscopygal(doc)) return importDiscopygal(doc, file, notes);
  return parseScene(doc, file);
}

}  // namespace mms
