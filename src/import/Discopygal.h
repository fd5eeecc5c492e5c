#pragma once
// discopygal (TAU's planning toolkit) JSON scenes: {"__class__": "Scene", "obstacles": [...],
// "robots": [...], "metadata": {...}} with ObstaclePolygon, ObstacleDisc, RobotPolygon,
// RobotDisc and RobotRod entries. Conversions are conservative: a path for the converted scene
// is valid for the original one.
#include <string>

#include "import/OmplApp.h"
#include "scene/Scene.h"

namespace mms {

/// A JSON file whose top level holds "obstacles" and "robots" arrays of "__class__" objects.
bool looksLikeDiscopygal(const std::string& file);

/// Discs (obstacles and robots) become regular 32-gons around them; polygon and disc robots
/// translate only; a rod becomes a rigid rectangle 1/100 of its length wide around the segment
/// (its reference point is the rod's first end, as in discopygal). No bounds in the format:
/// the box around everything, grown by 5 %.
Scene importDiscopygal(const std::string& file, ImportNotes& notes);

/// The scene as discopygal JSON: obstacles as ObstaclePolygon, the bounds as four walls, each
/// robot as a RobotPolygon (discopygal's polygon robots only translate: a rotating robot is
/// written at its start angle, and the note says so).
std::string discopygalJson(const Scene& scene, ImportNotes& notes);

}  // namespace mms
