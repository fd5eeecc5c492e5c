#pragma once
// The viewer's record layer (`mms view --record`): a second slider over the planning's time,
// under which the page draws what the planner had built by then, beneath the scene:
//   - slice cells, coloured by component (the start's green, the goal's red, both purple,
//     neither grey), at every angle, one chosen angle, or (one robot, by default) the slice
//     nearest the robot's angle at the motion's moment, in every subspace or one (its held
//     robots drawn dashed);
//   - lines as points (pivot lines as rings), coloured alike;
//   - a sampler's tree or graph, projected on one robot's position;
//   - the path's manifolds outlined;
// with a chart of the run's phases and counts, and one of what was built against time (with its
// axes). The page's hash sets them: #rt=0.5 (half-way through the planning),
// #layers=cells,lines,tree,path, #sub=N, #angle=X (the slice nearest X rad; all; near: the
// robot's angle now), #rrobot=N; for one robot, #cspace=1 opens a 3-D view of its C-space
// beside the scene (slices stacked by angle, lines' arcs upright, the path), which turns with
// the mouse.
#include <string>

#include "io/RecordIO.h"

namespace mms {

/// The controls and charts below the player's.
std::string recordControls(const RecordFile& record);
/// Beside the scene's picture: the 3-D view's place (one robot), or nothing.
std::string cspaceStage(const RecordFile& record);
/// The phases as bars, the counts as text.
std::string phaseChart(const PlanStatistics& stats);
/// The script, run after the player's.
const char* recordScript();
/// For one robot, three.js and OrbitControls (read from Debian's libjs-three) and the 3-D view of
/// its C-space, run after recordScript(); without libjs-three, a note saying so.
std::string cspaceScripts(const RecordFile& record);

}  // namespace mms
