#pragma once
#include <cstddef>
// `mms view`: one self-contained HTML file (inline script and data, nothing fetched) that draws
// the scene on a canvas and plays the path: play/pause, a time slider, speed, each robot's
// trace, and the planner's free-space cells and line points when the path file holds them
// ("roadmap", written by `mms plan --save-roadmap`). The page's hash sets the slider:
// FILE.html#t=0.5 shows the motion half-way (by duration) and paused; #fit=0 keeps the drawing
// at its own size instead of fitting it to the window.
//
// Layout, fixed so pictures can be checked: the canvas sits at the page's top-left corner,
// kCanvasWidth pixels wide, with the bounds scaled to fit inside a kPad margin, y upwards.
// A segment's duration is proportional to how far any robot point moves on it:
// max over robots of |dp| + radius * |dtheta|.
#include <string>

#include "io/PathIO.h"
#include "io/RecordIO.h"

namespace mms {

inline constexpr double kViewerCanvasWidth = 800, kViewerPad = 10;
/// Up to this many robots the legend shows every name; beyond, it is folded.
inline constexpr size_t kViewerLegendUnfolded = 20;

/// With `record` (mms plan --record), a second slider steps through the planning: what the
/// planner had built at each moment, drawn under the scene (render/RecordLayer.h).
std::string renderHtmlViewer(const Scene& scene, const Path* path,
                             const RecordFile* record = nullptr);

/// Where the viewer draws scene point p (CSS pixels from the canvas's top-left corner).
Vec2 viewerPixel(const Scene& scene, Vec2 p);

}  // namespace mms
