// The three-handed assembly scenarios of the paper's Further Work section, rebuilt from its
// description (the figures' geometry is not published): the static part is the obstacles, the
// movable parts are translate-only robots. `slack` is the gap left between parts and walls.
#include <cstdio>

#include "scenarios/Generators.h"

namespace mms {

namespace {

Robot part(const char* name, Ring shape, Pose start, Pose goal) {
  Robot r;
  r.name = name;
  r.shape = std::move(shape);
  r.start = start;
  r.goal = goal;
  r.motion = Motion::Translate;
  return r;
}

std::string withSlack(const char* base, double slack) {
  char name[64];
  std::snprintf(name, sizeof name, "%s-slack-%.3g", base, slack);
  return name;
}

}  // namespace

Scene assemblyOneScene(double s) {
  // Two hooked parts in a shaft one pair wide: A's tooth sits in B's slot with s of play above
  // and below, and the shaft lets them separate by only ~2s, far less than the tooth's depth.
  // So each can move up at most 2s past the other: they climb out of the shaft in alternation,
  // then unhook in the chamber above and leave through the opening in its roof.
  Scene scene;
  scene.name = withSlack("assembly-1", s);
  scene.bounds = {-5.5, -4, 8, 9.5};
  const double top = 2.2;            // the shaft's top: above it the parts can unhook
  const double right = 2.5 + 2 * s;  // the shaft's right wall
  const double ox0 = -2.5, ox1 = 5.0, oy0 = -1.2, oy1 = 5.7;  // the static part's box
  scene.obstacles = {{{ox0, oy1},
                      {ox0, oy0},
                      {ox1, oy0},
                      {ox1, oy1},
                      {2.0 + s, oy1},
                      {2.0 + s, 4.7},
                      {4.0, 4.7},
                      {4.0, top},
                      {right, top},
                      {right, -s},
                      {-s, -s},
                      {-s, top},
                      {-1.5, top},
                      {-1.5, 4.7},
                      {0.5, 4.7},
                      {0.5, oy1}}};
  // A: a 1 x 2 body with a 0.5 x 0.5 tooth pointing right. B: a 1 x 2 body with two teeth
  // pointing left that frame a slot of height 0.5 + 2s for A's tooth.
  const Ring a = {{0, 0}, {1, 0}, {1, 1}, {1.5, 1}, {1.5, 1.5}, {1, 1.5}, {1, 2}, {0, 2}};
  const Ring b = {{0, 0},       {1, 0},       {1, 2},          {-0.5, 2},   {-0.5, 1.5 + s},
                  {0, 1.5 + s}, {0, 1.0 - s}, {-0.5, 1.0 - s}, {-0.5, 0.5}, {0, 0.5}};
  scene.robots = {part("A", a, {0, 0, 0}, {-2.5, 6.5, 0}),
                  part("B", b, {1.5 + s, 0, 0}, {4.0, 6.5, 0})};
  return scene;
}

Scene assemblyTwoScene(double s, bool mPartsOnly) {
  // A corridor of height 2 + s holds a wide, short M (2 x 1.5, left) and a narrow, tall M
  // (1.5 x 2, right). The left exit, a shaft in the roof, only admits the narrow M; the right
  // exit, a tunnel in the wall, only the short M: each M must get past the other, which is
  // possible only when the wide M ducks into the pocket at the bottom-left corner. Two
  // triangles fill that pocket and a third sits under the wide M's arch (it can leave only
  // while that M is lifted: two hands).
  Scene scene;
  scene.name = withSlack(mPartsOnly ? "assembly-2-m-parts" : "assembly-2", s);
  scene.bounds = {-4.5, -6, 11.5, 7};
  const double h = 2 + s, pocketW = 2 + s, pocketD = 1.5 + s, shaftW = 1.5 + s, tunnelH = 1.5 + s;
  const double len = 7, x0 = -1, x1 = 8, y0 = -pocketD - 1, y1 = h + 1;
  scene.obstacles = {
      // left wall, floor and the pocket
      {{x0, y0},
       {x1, y0},
       {x1, 0},
       {pocketW, 0},
       {pocketW, -pocketD},
       {0, -pocketD},
       {0, y1},
       {x0, y1}},
      // roof right of the shaft and the wall above the tunnel
      {{shaftW, h}, {len, h}, {len, tunnelH}, {x1, tunnelH}, {x1, y1}, {shaftW, y1}}};
  const Ring wide = {{0, 0}, {0.5, 0}, {0.5, 0.8}, {1, 0.4}, {1.5, 0.8}, {1.5, 0},
                     {2, 0}, {2, 1.5}, {1.6, 1.5}, {1, 0.9}, {0.4, 1.5}, {0, 1.5}};
  const Ring tall = {{0, 0},   {0.4, 0}, {0.4, 1.1}, {0.75, 0.6}, {1.1, 1.1}, {1.1, 0},
                     {1.5, 0}, {1.5, 2}, {1.2, 2},   {0.75, 1.2}, {0.3, 2},   {0, 2}};
  const Pose wideStart{2.2, 0, 0}, tallStart{4.5, 0, 0};
  if (mPartsOnly) {
    scene.robots = {part("wide-M", wide, wideStart, {9, 0, 0}),
                    part("tall-M", tall, tallStart, {0, 4.8, 0})};
    return scene;
  }
  // Goals equal to starts: `mms assemble` takes such parts out of the static part's box.
  const Ring lower = {{0.5 + s, 0}, {1.5 - s, 0}, {1, 0.4 - s}};  // under the wide M's arch
  const Ring left = {{0.1, -1.4}, {1.0, -1.4}, {0.1, -0.5}};
  const Ring rightT = {{1.1, -1.4}, {1.9, -1.4}, {1.9, -0.5}};
  scene.robots = {part("pocket-left", left, {0, 0, 0}, {0, 0, 0}),
                  part("pocket-right", rightT, {0, 0, 0}, {0, 0, 0}),
                  part("lower", lower, {wideStart.x, 0, 0}, {wideStart.x, 0, 0}),
                  part("wide-M", wide, wideStart, wideStart),
                  part("tall-M", tall, tallStart, tallStart)};
  return scene;
}

}  // namespace mms
