#pragma once
// One entry point for scene files in any format mms reads: mms-scene/1 JSON, OMPL.app .cfg
// problems, and discopygal JSON scenes (converted on the fly, with notes on what changed).
#include <nlohmann/json.hpp>
#include <string>

#include "io/OmplApp.h"
#include "mms/Scene.h"

namespace mms {

/// Degrees given for radians pass every check but plan something else: a note for each start or
/// goal angle beyond a full turn.
void noteAngles(const Scene& scene, const std::string& source, ImportNotes& notes);

/// Polygons written as closed rings (the first vertex repeated last, as GeoJSON and shapely
/// write them) are read without the repeat: one note says how many.
void noteClosedRings(const nlohmann::json& doc, const std::string& source, ImportNotes& notes);

/// By extension (.cfg: OMPL.app) and, for .json, by content (discopygal's "__class__" entries
/// and no "format"); anything else is read as mms-scene/1. Notes say what a conversion
/// changed and which angles look like degrees.
Scene loadAnyScene(const std::string& file, ImportNotes& notes);

}  // namespace mms
