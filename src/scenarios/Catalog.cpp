#include "scenarios/Catalog.h"

#include <algorithm>
#include <stdexcept>

#include "io/SceneIO.h"
#include "mms/Errors.h"
#include "scenarios/Generators.h"
#include "scenarios/RandomScene.h"
#include "util/Number.h"
#include "util/Suggest.h"

namespace mms {

const std::vector<ScenarioInfo>& scenarios() {
  static const std::vector<ScenarioInfo> all{
      {"pacman", {"tightness"}, "the paper's Pacman and the square in its mouth", false},
      {"viking-helmet", {}, "the paper's Viking helmet", false},
      {"random-polygons", {}, "the paper's two robots among random polygons"},
      {"assembly-1", {"slack"}, "the paper's assembly 1: two hooked parts in a shaft", false},
      {"assembly-2",
       {"slack", "m-parts-only"},
       "the paper's assembly 2: two M parts and three triangles",
       false},
      {"random", {"robots", "obstacles"}, "a random test scene of 1 or 2 robots"},
      {"carry-turn", {"slack"}, "a gripper and the part it holds turn together in a chamber"},
      {"niche-swap", {"slack"}, "two robots swap the ends of a corridor with a niche"},
      {"niche-three", {}, "two robots cross a corridor in which a third waits in a niche"},
      {"discs-swap", {}, "4-5 discs round a block to each other's places"},
      {"discs-room", {"robots"}, "discs cross an open room among obstacles"},
      {"open-clutter", {}, "one or two L-shaped robots cross random convex clutter"},
      {"bend", {}, "a plank turns the corner of an L-shaped corridor"},
      {"doors", {}, "a long robot lines up with the doors of 1-3 thin walls"},
      {"keyhole",
       {"slack"},
       "a key passes a keyhole, turns a quarter in a chamber barely larger than its turn, and "
       "leaves through a side slot"},
      {"swallow",
       {"slack"},
       "a U takes a part into its mouth and turns half round about it in a bay barely larger "
       "than that turn"},
      {"swallow-two",
       {"slack"},
       "the swallow with the part a robot too, which waits while the U turns about it and then "
       "leaves the other way"},
      {"disc-grid", {"robots", "spacing"}, "unit discs on a grid go to the same grid moved aside"},
      {"disc-triangles", {"robots"}, "unit discs among random triangles"},
      {"disc-box", {"robots"}, "discs of radius 0.5 packed touching in a walled box, shuffled"},
      {"warehouse", {"robots"}, "rectangular carts among shelves turn where there is room"},
      {"round-room",
       {"robots"},
       "3-5 discs that nearly fill a round room go round to each other's places"}};
  return all;
}

const std::vector<std::string>& scenarioNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const ScenarioInfo& s : scenarios()) out.push_back(s.name);
    return out;
  }();
  return names;
}

namespace {
void requireRange(const std::string& prefix, const char* setting, double v, double lo, double hi) {
  if (!(v >= lo && v <= hi))
    throw InputError(prefix + setting + ": " + formatNumber(v) + " is not in [" + formatNumber(lo) +
                     ", " + formatNumber(hi) + "]");
}

const ScenarioInfo& infoOf(const std::string& name) {
  for (const ScenarioInfo& s : scenarios())
    if (s.name == name) return s;
  throw std::logic_error("no scenario " + name);
}

// The robots r.translate names made translation-only, the scene named apart: before its seed
// when it ends with one ("niche-three-oncoming-translates-3"), so that the name without
// "-SEED" still names the family; at the end otherwise ("pacman-0-square-translates", whose
// "-0" is the tightness).
void translateOnly(Scene& s, const ScenarioRequest& r, const std::string& prefix) {
  const std::string scene = s.name;
  std::string seed(1, '-');  // appended, not "-" + ...: GCC 12 warns (-Wrestrict) on that here
  seed += std::to_string(r.seed);
  const bool seeded = infoOf(r.name).seeded && scene.size() > seed.size() &&
                      scene.compare(scene.size() - seed.size(), seed.size(), seed) == 0;
  const size_t at = seeded ? scene.size() - seed.size() : scene.size();
  std::string suffix;
  for (auto it = r.translate.begin(); it != r.translate.end(); ++it) {
    const std::string& name = *it;
    if (std::find(r.translate.begin(), it, name) != it) continue;  // named twice: once is enough
    std::string robots;
    Robot* robot = nullptr;
    for (Robot& candidate : s.robots) {
      robots += (robots.empty() ? "" : ", ") + candidate.name;
      if (candidate.name == name) robot = &candidate;
    }
    const std::string what = prefix + "translate: robot '" + name + "' of " + scene;
    if (!robot)
      throw InputError(prefix + "translate: no robot '" + name + "' in " + scene +
                       " (robots: " + robots + ")");
    if (robot->motion == Motion::Translate) throw InputError(what + " translates already");
    if (robot->goal.theta != robot->start.theta)
      throw InputError(what + " turns from start to goal (" + formatNumber(robot->start.theta) +
                       " to " + formatNumber(robot->goal.theta) +
                       " rad); only a robot that keeps its angle can translate");
    robot->motion = Motion::Translate;
    suffix += "-" + name + "-translates";
  }
  s.name = scene.substr(0, at) + suffix + scene.substr(at);
}

// A family added here is declared in scenarios() too.
Scene generate(const ScenarioRequest& r) {
  const std::string& n = r.name;
  if (n == "pacman") return pacmanScene(r.tightness);
  if (n == "viking-helmet") return vikingHelmetScene();
  if (n == "assembly-1") return assemblyOneScene(r.slack);
  if (n == "assembly-2") return assemblyTwoScene(r.slack, r.mPartsOnly);
  if (n == "random") return randomScene({r.seed, r.robots, r.obstacles});
  if (n == "carry-turn") return carryTurnScene(r.seed, r.slackGiven ? r.slack : -1);
  if (n == "keyhole") return keyholeScene(r.seed, r.slackGiven ? r.slack : -1);
  if (n == "swallow") return swallowScene(r.seed, r.slackGiven ? r.slack : -1);
  if (n == "swallow-two") return swallowScene(r.seed, r.slackGiven ? r.slack : -1, true);
  if (n == "niche-swap") return nicheSwapScene(r.seed, r.slackGiven ? r.slack : -1);
  if (n == "niche-three") return nicheThreeScene(r.seed);
  if (n == "discs-swap") return discsSwapScene(r.seed);
  if (n == "discs-room") return discsRoomScene(r.seed, r.robots > 0 ? size_t(r.robots) : 10);
  if (n == "round-room") return roundRoomScene(r.seed, size_t(r.robots));
  if (n == "open-clutter") return openClutterScene(r.seed);
  if (n == "disc-grid")
    return discGridScene(r.seed, r.robots > 0 ? size_t(r.robots) : 20, r.spacing);
  if (n == "disc-triangles")
    return discTrianglesScene(r.seed, r.robots > 0 ? size_t(r.robots) : 20);
  if (n == "disc-box") return discBoxScene(r.seed, r.robots > 0 ? size_t(r.robots) : 29);
  if (n == "warehouse") return warehouseScene(r.seed, r.robots > 0 ? size_t(r.robots) : 20);
  if (n == "bend") return bendScene(r.seed);
  if (n == "doors") return doorsScene(r.seed);
  return randomPolygonsTwoRobots(r.seed);
}
}  // namespace

// The settings a family takes beyond its seed; one given to a family that does not take it is
// refused rather than silently ignored (keyhole --tightness 0.5 made the keyhole it always does).
void refuseSettingsNotTaken(const ScenarioRequest& r, const std::string& prefix) {
  const std::string& n = r.name;
  const std::vector<std::string>& takes = infoOf(n).settings;
  const std::pair<bool, const char*> given[] = {
      {r.tightness != 0, "tightness"}, {r.slackGiven, "slack"},
      {r.robots != 0, "robots"},       {r.obstacles != -1, "obstacles"},
      {r.spacing != 0, "spacing"},     {r.mPartsOnly, "m-parts-only"}};
  for (const auto& [refused, setting] : given)
    if (refused && std::find(takes.begin(), takes.end(), setting) == takes.end())
      throw InputError(prefix + setting + ": scenario " + n + " does not take it (mms scenario " +
                       "--help says which families take which settings)");
}

Scene makeScenario(const ScenarioRequest& r, const std::string& prefix) {
  bool known = false;
  std::string list;
  for (const std::string& name : scenarioNames()) {
    known = known || name == r.name;
    list += (list.empty() ? "" : ", ") + name;
  }
  if (!known)
    throw InputError("scenario '" + r.name + "': unknown (known: " + list + ")" +
                     didYouMean(r.name, scenarioNames()));
  refuseSettingsNotTaken(r, prefix);
  requireRange(prefix, "tightness", r.tightness, 0, 0.999);
  requireRange(prefix, "slack", r.slack, 0.001, 1);
  const bool manyDiscs = r.name == "disc-grid" || r.name == "disc-triangles" ||
                         r.name == "disc-box" || r.name == "warehouse";
  if (r.robots != 0) requireRange(prefix, "robots", r.robots, 1, manyDiscs ? 2000 : 16);
  if (r.spacing != 0) requireRange(prefix, "spacing", r.spacing, 2.05, 100);
  if (r.obstacles != -1) requireRange(prefix, "obstacles", r.obstacles, 0, 100000);
  if ((r.name == "assembly-1" || r.name == "assembly-2") && r.slack > 0.15)
    throw InputError(prefix + "slack: " + formatNumber(r.slack) + " is more than " + r.name +
                     "'s largest play, 0.15");
  if (r.name == "round-room" && r.robots == 1)
    throw InputError(prefix + "robots: 1 disc; a round room's discs go round to each other's " +
                     "places, so it takes 2 or more");
  if (r.name == "random" && r.robots > 2)
    throw InputError(prefix + "robots: " + std::to_string(r.robots) +
                     " robots; the random test scene has 1 or 2 (discs-room takes more)");
  Scene s = generate(r);
  translateOnly(s, r, prefix);
  // The generators must produce valid scenes.
  try {
    parseScene(sceneToJson(s), r.name);
  } catch (const InputError& e) {
    throw std::logic_error(std::string("generated scene is invalid: ") + e.what());
  }
  return s;
}

}  // namespace mms
