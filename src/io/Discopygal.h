#pragma once
// discopygal (TAU's planning toolkit) JSON scenes: {"__class__": "Scene", "obstacles": [...],
// "robots": [...], "metadata": {...}} with ObstaclePolygon, ObstacleDisc, RobotPolygon,
// RobotDisc and RobotRod entries. Conversions are conservative: a path for the converted scene
// is valid for the original one.
#include <nlohmann/json.hpp>
#include <string>

#include "io/OmplApp.h"
#include "mms/Scene.h"

namespace mms {

/// A JSON document without mms's "format" whose top level, or an entry of its "obstacles" or
/// "robots", carries discopygal's "__class__".
bool isDiscopygal(const nlohmann::json& doc);

/// Discs (obstacles and robots) become regular 32-gons around them; polygon and disc robots
/// translate only; a rod becomes a rigid rectangle 1/100 of its length wide around the segment
/// (its reference point is the rod's first end, as in discopygal). No bounds in the format:
/// the box around everything, grown by 5 %.
Scene importDiscopygal(const std::string& file, ImportNotes& notes);
/// The same for a document already parsed (`source` names it in messages).
Scene importDiscopygal(const nlohmann::json& doc, const std::string& source, ImportNotes& notes);

/// The scene as discopygal JSON: obstacles as ObstaclePolygon, the bounds as four walls, each
/// robot as a RobotPolygon (discopygal's polygon robots only translate: a rotating robot is
/// written at its start angle, and the note says so).
std::string discopygalJson(const Scene& scene, ImportNotes& notes);

}  // namespace mms
