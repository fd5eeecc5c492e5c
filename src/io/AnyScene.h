#pragma once
// One entry point for scene files in any format mms reads: mms-scene/1 JSON, OMPL.app .cfg
// problems, and discopygal JSON scenes (converted on the fly, with notes on what changed).
#include <string>

#include "io/OmplApp.h"
#include "mms/Scene.h"

namespace mms {

/// By extension (.cfg: OMPL.app) and, for .json, by content (discopygal's "__class__" entries
/// and no "format"); anything else is read as mms-scene/1.
Scene loadAnyScene(const std::string& file, ImportNotes& notes);

}  // namespace mms
