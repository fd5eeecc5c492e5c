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

const std::vector<std::string>& scenarioNames() {
  static const std::vector<std::string> names{
      "pacman",      "viking-helmet", "random-polygons", "assembly-1",
      "assembly-2",  "random",        "carry-turn",      "niche-swap",
      "niche-three", "discs-swap",    "discs-room",      "open-clutter",
      "bend",        "doors",         "keyhole",         "swallow",
      "swallow-two", "disc-grid",     "disc-triangles",  "disc-box",
      "warehouse",   "round-room"};
  return names;
}

namespace {
void requireRange(const std::string& prefix, const char* setting, double v, double lo, double hi) {
  if (!(v >= lo && v <= hi))
    throw InputError(prefix + setting + ": " + formatNumber(v) + " is not in [" + formatNumber(lo) +
                     ", " + formatNumber(hi) + "]");
}

// Whether the family's scene depends on --seed: all but the paper's fixed scenes (generate()).
bool usesSeed(const std::string& n) {
  return n != "pacman" && n != "viking-helmet" && n != "assembly-1" && n != "assembly-2";
}

// The robots r.translate names made translation-only, the scene named apart: before its seed
// when it ends with one ("niche-three-oncoming-translates-3"), so that the name without
// "-SEED" still names the family; at the end otherwise ("pacman-0-square-translates", whose
// "-0" is the tightness).
void translateOnly(Scene& s, const ScenarioRequest& r, const std::string& prefix) {
  const std::string scene = s.name;
  std::string seed(1, '-');  // appended, not "-" + ...: GCC 12 warns (-Wrestrict) on that here
  seed += std::to_string(r.seed);
  const bool seeded = usesSeed(r.name) && scene.size() > seed.size() &&
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

// A family added here without a seed belongs in usesSeed() too.
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
  const bool slack = n == "assembly-1" || n == "assembly-2" || n == "carry-turn" ||
                     n == "niche-swap" || n == "keyhole" || n == "swallow" || n == "swallow-two";
  const bool robots = n == "random" || n == "discs-room" || n == "round-room" || n == "disc-grid" ||
                      n == "disc-triangles" || n == "disc-box" || n == "warehouse";
  const std::pair<bool, const char*> given[] = {
      {r.tightness != 0 && n != "pacman", "tightness"},
      {r.slackGiven && !slack, "slack"},
      {r.robots != 0 && !robots, "robots"},
      {r.obstacles != -1 && n != "random", "obstacles"},
      {r.spacing != 0 && n != "disc-grid", "spacing"},
      {r.mPartsOnly && n != "assembly-2", "m-parts-only"}};
  for (const auto& [refused, setting] : given)
    if (refused)
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
