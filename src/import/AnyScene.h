#pragma once
// One entry point for scene files in any format mms reads: mms-scene/1 JSON, OMPL.app .cfg
// problems, and discopygal JSON scenes (converted on the fly, with notes on what changed).
#include <string>

#include "import/OmplApp.h"
#include "scene/Scene.h"

namespace mms {

enum class SceneFormat { Mms, OmplApp, Discopygal };

/// By extension (.cfg) and, for JSON, by content (discopygal's "obstacles"/"robots" with
/// "__class__" entries).
SceneFormat detectSceneFormat(const std::string& file);

Scene loadAnyScene(const std::string& file, ImportNotes& notes);

}  // namespace mms
