#include "import/AnyScene.h"

#include <filesystem>

#include "import/Discopygal.h"
#include "scene/Json.h"
#include "scene/SceneIO.h"

namespace mms {

SceneFormat detectSceneFormat(const std::string& file) {
  if (std::filesystem::path(file).extension() == ".cfg") return SceneFormat::OmplApp;
  if (std::filesystem::path(file).extension() == ".json" && looksLikeDiscopygal(file))
    return SceneFormat::Discopygal;
  return SceneFormat::Mms;
}

Scene loadAnyScene(const std::string& file, ImportNotes& notes) {
  switch (detectSceneFormat(file)) {
    case SceneFormat::OmplApp:
      return importOmplApp(file, notes);
    case SceneFormat::Discopygal:
      return importDiscopygal(file, notes);
    case SceneFormat::Mms:
      break;
  }
  return loadScene(file);
}

}  // namespace mms
