#include "scenarios/Catalog.h"

#include <stdexcept>

#include "io/SceneIO.h"
#include "mms/Errors.h"
#include "scenarios/Generators.h"
#include "scenarios/RandomScene.h"
#include "util/Number.h"

namespace mms {

const std::vector<std::string>& scenarioNames() {
  static const std::vector<std::string> names{
      "pacman",     "viking-helmet", "random-polygons", "assembly-1", "assembly-2", "random",
      "carry-turn", "niche-swap",    "niche-three",     "discs-swap", "discs-room", "open-clutter",
      "bend",       "doors"};
  return names;
}

namespace {
void requireRange(const std::string& prefix, const char* setting, double v, double lo, double hi) {
  if (!(v >= lo && v <= hi))
    throw InputError(prefix + setting + ": " + formatNumber(v) + " is not in [" + formatNumber(lo) +
                     ", " + formatNumber(hi) + "]");
}

Scene generate(const ScenarioRequest& r) {
  const std::string& n = r.name;
  if (n == "pacman") return pacmanScene(r.tightness);
  if (n == "viking-helmet") return vikingHelmetScene();
  if (n == "assembly-1") return assemblyOneScene(r.slack);
  if (n == "assembly-2") return assemblyTwoScene(r.slack, r.mPartsOnly);
  if (n == "random") return randomScene({r.seed, r.robots, r.obstacles});
  if (n == "carry-turn") return carryTurnScene(r.seed);
  if (n == "niche-swap") return nicheSwapScene(r.seed, r.slackGiven ? r.slack : -1);
  if (n == "niche-three") return nicheThreeScene(r.seed);
  if (n == "discs-swap") return discsSwapScene(r.seed);
  if (n == "discs-room") return discsRoomScene(r.seed, r.robots > 0 ? size_t(r.robots) : 10);
  if (n == "open-clutter") return openClutterScene(r.seed);
  if (n == "bend") return bendScene(r.seed);
  if (n == "doors") return doorsScene(r.seed);
  return randomPolygonsTwoRobots(r.seed);
}
}  // namespace

Scene makeScenario(const ScenarioRequest& r, const std::string& prefix) {
  bool known = false;
  std::string list;
  for (const std::string& name : scenarioNames()) {
    known = known || name == r.name;
    list += (list.empty() ? "" : ", ") + name;
  }
  if (!known) throw InputError("scenario '" + r.name + "': unknown (known: " + list + ")");
  requireRange(prefix, "tightness", r.tightness, 0, 0.999);
  requireRange(prefix, "slack", r.slack, 0.001, 1);
  if (r.robots != 0) requireRange(prefix, "robots", r.robots, 1, 16);
  if (r.obstacles != -1) requireRange(prefix, "obstacles", r.obstacles, 0, 100000);
  if ((r.name == "assembly-1" || r.name == "assembly-2") && r.slack > 0.15)
    throw InputError(prefix + "slack: " + formatNumber(r.slack) + " is more than " + r.name +
                     "'s largest play, 0.15");
  if (r.name == "random" && r.robots > 2)
    throw InputError(prefix + "robots: " + std::to_string(r.robots) +
                     " robots; the random test scene has 1 or 2 (discs-room takes more)");
  Scene s = generate(r);
  for (const std::string& name : r.translate) {
    std::string robots;
    Robot* robot = nullptr;
    for (Robot& candidate : s.robots) {
      robots += (robots.empty() ? "" : ", ") + candidate.name;
      if (candidate.name == name) robot = &candidate;
    }
    if (!robot)
      throw InputError(prefix + "translate: no robot '" + name + "' in " + r.name +
                       " (robots: " + robots + ")");
    if (robot->goal.theta != robot->start.theta)
      throw InputError(prefix + "translate: robot '" + name + "' of " + s.name +
                       " turns from start to goal (" + formatNumber(robot->start.theta) + " to " +
                       formatNumber(robot->goal.theta) +
                       " rad); only a robot that keeps its "
                       "angle can translate");
    if (robot->motion == Motion::Translate) continue;
    robot->motion = Motion::Translate;
    // Before a trailing seed, so that the name without "-SEED" still names the family.
    size_t at = s.name.find_last_of('-');
    if (at == std::string::npos || at + 1 == s.name.size() ||
        s.name.find_first_not_of("0123456789", at + 1) != std::string::npos)
      at = s.name.size();
    s.name.insert(at, "-" + name + "-translates");
  }
  // The generators must produce valid scenes.
  try {
    parseScene(sceneToJson(s), r.name);
  } catch (const InputError& e) {
    throw std::logic_error(std::string("generated scene is invalid: ") + e.what());
  }
  return s;
}

}  // namespace mms
