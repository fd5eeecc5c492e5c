#pragma once
// SVG pictures of scenes and paths in the style of the paper's figures: obstacles in blue,
// robots at their start in green and at their goal in red; with a path, faint poses along it,
// each robot's trace, and a robot that moves along the path (SMIL animation; renderers without
// animation show it at its start).
#include <string>

#include "io/PathIO.h"

namespace mms {

struct SvgOptions {
  double widthPx = 800;  // the height follows the bounds' aspect ratio
  int ghosts = 24;       // faint poses drawn along a path
  bool animate = true;
  double secondsPerExtent = 4;  // animation speed: time to sweep the bounds' larger side
  /// Planner internals to show: regions (e.g. free-space cells of slices: an outer ring and
  /// its holes each) and markers (e.g. the points of lines), drawn faintly under the robots.
  std::vector<std::vector<Ring>> regions;
  std::vector<Vec2> markers;
};

std::string renderSvg(const Scene& scene, const Path* path, const SvgOptions& options = {});

}  // namespace mms
