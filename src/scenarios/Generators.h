#pragma once
// Deterministic scene generators (same seed, same scene).
#include <cstdint>

#include "mms/Scene.h"
#include "util/Random.h"

namespace mms {

/// A star-shaped (hence simple) polygon around `center`: `n` vertices at increasing angles,
/// radii uniform in [rmin, rmax]. Counter-clockwise.
Ring randomStarPolygon(Random& rng, Vec2 center, double rmin, double rmax, int n);

struct RandomPolygonsSettings {
  uint64_t seed = 1;
  int obstacles = 20;
  int obstacleVertices = 8;
  int robotVertices = 10;
  double extent = 50;  // bounds are [-extent, extent]^2
  int robots = 1;
};

/// Random non-convex obstacles on a jittered grid and `robots` random non-convex robots placed
/// at grid corners (where the generator leaves room): the first robot crosses the scene from
/// bottom-left to top-right, the second from bottom-right to top-left.
Scene randomPolygonsScene(const RandomPolygonsSettings& settings);

/// The paper's two-robot "random polygons" scenario rebuilt from a seed (bounds +-55 as in
/// OMPL.app's RandomPolygons_planar): easy, little coordination.
Scene randomPolygonsTwoRobots(uint64_t seed = 1);

/// Carry and turn: a U-shaped gripper (robot 0) holds a rectangular part (robot 1) in its
/// pocket (anywhere in its play, at the start and independently at the goal), at the end of a
/// dead-end corridor too narrow for either to turn in; a round chamber at the corridor's mouth,
/// just larger than the pair's circumscribed circle, is the only place to turn, and the goal is the
/// pair turned half round, back in the corridor. The part can pass neither the gripper in the
/// corridor nor wait beside it in the chamber, so the two turn together, their angles within the
/// pocket's play of each other. Random per seed: the part's size and aspect, the play (0.04-0.1 of
/// the part's size), the gripper's walls, the corridor's length and slack, the chamber's slack, the
/// direction of the corridor (a quarter turn) and of the turn. The chamber is centred at the
/// origin. `play` >= 0 sets the play (a share of the part's size) instead of the seed.
Scene carryTurnScene(uint64_t seed, double play = -1);

/// A key through a keyhole: a key (a bow and a shaft, 1.4-2.2 long) stands upright in a room
/// below a thick wall, passes a keyhole slot barely wider than its bow into an octagonal
/// chamber whose inscribed circle clears the key's smallest turning circle by `slack` (0.03-0.12
/// from the seed unless given), turns a quarter there (the one place between the slots with room
/// to turn) and leaves lying down through a slot in the side wall. Random per seed: the key's
/// proportions, the slots' places along the chamber's sides, the walls' thickness, which way the
/// key points, a quarter turn and a mirror image of the whole.
Scene keyholeScene(uint64_t seed, double slack = -1);

/// Swallow and turn: a U-shaped robot (its reference point the middle of its back) goes from a
/// corridor on the left to one on the right, both too narrow for it to turn in, mouth first at
/// the start and mouth last at the goal. Between them, centred on the origin, a round bay (a
/// regular 16-24-gon) whose inscribed circle clears the U's turning circle about its centre by
/// `slack` (0.03-0.12 from the seed unless given); a part fixed at that centre (a bar, a T or an
/// L inside a circle a little smaller than the U's mouth) bars the way. The U takes the part
/// into its mouth, turns half round about it (its reference point on a circle) and leaves it
/// behind. Random per seed: the part's shape, size and angle, the U's arms, back, reach and play
/// round the part, the corridor's slack, the bay's sides, the sense of the turn and a quarter
/// turn of the whole.
/// `partMoves`: the part is a robot instead of an obstacle (swallow-two): it waits at the bay's
/// centre while the U turns about it, then leaves for the corridor the U came from.
Scene swallowScene(uint64_t seed, double slack = -1, bool partMoves = false);

/// The way through a swallow scene its generator built it for (uncertified: the path checker
/// says whether it is free): the U goes straight to the part, turns half round about the part's
/// centre in 180 steps, and goes straight to its goal.
std::vector<Config> swallowWitness(const Scene& scene);

/// Niche swap: two robots of random blocky shapes swap the ends of a corridor too narrow for
/// them to pass each other; a niche in one wall, at a random place, fits either robot at angle 0
/// with `play` (a share of the robots' size) to spare in width and depth, so one waits tucked in
/// while the other passes. Random per seed: the shapes, the corridor's width (room for either
/// robot, not for both side by side) and length, the niche's place, and the play (0.04-0.1,
/// unless `play` >= 0 is given; 0.5 makes a roomy niche that sampling planners find at once).
/// Robot 0 starts at the left end.
Scene nicheSwapScene(uint64_t seed, double play = -1);

/// Three robots and a niche (9-D): a dead-end corridor, too narrow for any two robots side by
/// side and for any robot to turn in; robots 0 and 1 go from its left end to its right end, robot
/// 2 the other way, so one must wait in a niche in the upper wall (it fits the largest robot with
/// 0.04-0.1 of its size to spare) while the others pass. Random per seed: the three rectangles,
/// the corridor's width and length, the niche's place and play, the gaps at the ends.
Scene nicheThreeScene(uint64_t seed);

/// Discs swapping round a block: 4-5 translating discs of one radius (0.4-0.6) on a ring around
/// a central regular polygon (5-8 sides) in a square room; each goes a random number of places
/// round the ring, to where another starts. The band between the block and the walls is
/// 4.15-4.6 radii wide: two discs pass each other only just. Random per seed: all of these.
Scene discsSwapScene(uint64_t seed);

/// A round room: `count` translating discs (3-5 from the seed when 0) of one radius, a third to
/// a 3.5th of the room's, on a circle inside a ring of 16-24 blocks (a polygonal room of
/// apothem 5), each going a number of places round (half round with even odds when `count` is
/// even: discopygal's four discs in a circular room). The discs nearly fill the room, which
/// they can always cross by turning round together. Random per seed: the radius, the
/// blocks' count, width and angle, the discs' circle, phase and shift.
Scene roundRoomScene(uint64_t seed, size_t count = 0);

/// `count` translating discs (radii 0.3-0.5) in an open square room sized for them, with 3-6
/// random convex obstacles, apart from each other and from the walls by more than a disc's
/// width; starts and goals at random, clear of each other and the obstacles.
Scene discsRoomScene(uint64_t seed, size_t count = 10);

/// Open clutter: one or two L-shaped robots (count, arm lengths and thickness from the seed)
/// cross a square room among 20-30 random convex obstacles (3-7 vertices, placed uniformly,
/// overlaps allowed). Robot 0 goes from the left edge to the right, robot 1 the other way;
/// starts and goals keep the robots' circumscribed discs clear of every obstacle's and of each
/// other's, so they are free. Every scene has a solution: obstacles that leave the grid witness
/// (`Witness.h`) no way are drawn again (2 seeds of 1-300). Wide passages: what sampling planners
/// do well.
Scene openClutterScene(uint64_t seed);

/// A bend: a plank (a thin rectangle) goes from one arm of an L-shaped corridor to the other.
/// Random per seed: the arms' widths and lengths, the plank's thickness and its length, 0.8-0.95
/// of the longest that turns the corner (the ladder problem, with its thickness taken off the
/// widths), which way the corridor turns, and a quarter turn of the whole.
Scene bendScene(uint64_t seed);

/// Doors: a long robot (a rectangle with random corners cut) crosses rooms divided by 1-3 thin
/// walls, each with a door 5-30 % wider than the robot, so it must line up with each door to
/// pass. Random per seed: the robot's length, width and corners, the rooms' size, the walls'
/// count, each door's height and slack, the start and goal angles.
Scene doorsScene(uint64_t seed);

/// The paper's Pacman scenario: a C-shaped robot and a square swap ends of a corridor too
/// narrow to pass; the Pacman must swallow the square, turn around it and release it.
/// tightness in [0, 1): the square grows from the base size (0) towards exactly the width of
/// the Pacman's mouth (1, unsolvable).
Scene pacmanScene(double tightness);

/// The paper's Viking helmet scenario: each robot goes down its own narrow passage from a horn
/// of the helmet into the lower chamber, where they exchange sides past a pillar that leaves
/// room for one robot at a time.
Scene vikingHelmetScene();

/// Three-handed assembly 1 (the paper's Further Work): two hooked parts in a tight shaft that
/// must climb out in alternation; neither can leave while the other stays put. Parts translate
/// only; their goals lie outside the static part. `slack` in (0, 0.15]: the play between parts
/// and walls.
Scene assemblyOneScene(double slack);

/// Three-handed assembly 2: two M-shaped parts and three triangles in a corridor. Once the
/// triangles are out, the left M must duck into the bottom-left corner so the right one can
/// leave. Goals equal starts (for `mms assemble`: take every part out of the static part's
/// box). With `mPartsOnly`, the triangles are left out and the M parts get goals outside: the
/// 4-D problem of the last step, for `mms plan` and `mms bench`. `slack` in (0, 0.15].
Scene assemblyTwoScene(double slack, bool mPartsOnly = false);

/// A disc robot's shape: the regular 16-gon whose inscribed circle is the disc, about its centre.
Ring discShape(double radius);
/// Translating disc robot "disc-<i>" (its shape discShape(radius)) from start to goal.
Robot discRobot(size_t i, double radius, Vec2 start, Vec2 goal);
/// The same robot as an exact disc (Robot::disc), with the stand-in planners use.
Robot exactDiscRobot(size_t i, double radius, Vec2 start, Vec2 goal);
/// The axis-aligned rectangle [x0, x1] x [y0, y1], counter-clockwise from (x0, y0).
Ring rect(double x0, double y0, double x1, double y1);

/// Discs on a grid going to the same grid moved along one of eight directions (one to three
/// spacings clear of it), each disc to its own place there: `count` unit discs, `spacing` between
/// neighbours' centres in radii (3: dense, a disc cannot pass between two; 10: sparse; 0: 3, 5
/// or 10 from the seed). Random per seed: the grid's aspect, the direction, the gap and a turn of
/// the whole.
Scene discGridScene(uint64_t seed, size_t count, double spacing = 0);

/// `count` unit discs among random triangles (a quarter to 0.85 of `count`, kept a diameter
/// apart so the free space is one piece), in a square of 70-150 area per disc (more where the
/// draws do not fit); every start and
/// goal in a free disc of radius 2 holding no other start or goal (revolving areas), so that
/// the discs can go one at a time.
Scene discTrianglesScene(uint64_t seed, size_t count);

/// `count` exact discs of radius 0.5 packed in a walled box of cells one diameter wide (two
/// to a fifth more cells than discs, an aspect and a turn of the box from the seed), touching
/// their neighbours and the walls; starts and goals are random cells, so the discs must shuffle
/// (as multi-agent path finding benchmarks place them).
Scene discBoxScene(uint64_t seed, size_t count);

/// `count` rigid rectangular carts in a warehouse: rows of shelves, aisles between them too
/// narrow for a cart to turn in but wide enough to pass a parked one, and cross-aisles where it
/// can turn. Carts park along one side, lengthwise in the aisles or crosswise in the
/// cross-aisles, facing either way; starts and goals are random places. Random per seed: the
/// cart, the widths, the shelves.
Scene warehouseScene(uint64_t seed, size_t count);

}  // namespace mms
