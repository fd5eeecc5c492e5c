#include "io/SceneIO.h"

#include <algorithm>
#include <set>

#include "geometry/CollisionChecker.h"
#include "geometry/PolygonOps.h"
#include "geometry/Predicates.h"
#include "io/Json.h"
#include "util/AtomicFile.h"
#include "util/Number.h"

namespace mms {

using json_in::Node;

Config startConfig(const Scene& scene) {
  Config q;
  for (const Robot& r : scene.robots) q.insert(q.end(), {r.start.x, r.start.y, r.start.theta});
  return q;
}

Config goalConfig(const Scene& scene) {
  Config q;
  for (const Robot& r : scene.robots) q.insert(q.end(), {r.goal.x, r.goal.y, r.goal.theta});
  return q;
}

void Scene::addObstacleDisc(const Disc& d) {
  if (obstacleDiscs.size() < obstacles.size()) obstacleDiscs.resize(obstacles.size());
  obstacles.push_back(discStandIn(d));
  obstacleDiscs.push_back(d);
}

bool Scene::hasDiscs() const {
  return std::any_of(robots.begin(), robots.end(), [](const Robot& r) { return r.disc > 0; }) ||
         std::any_of(obstacleDiscs.begin(), obstacleDiscs.end(),
                     [](const std::optional<Disc>& d) { return d.has_value(); });
}

namespace {

/// A disc's radius: finite and positive, and above the contact tolerance (a disc shrunk by it
/// must keep some room).
double readRadius(const Node& node, double tolerance) {
  const double r = node.number(json_in::kMaxCoordinate);
  if (!(r > 0)) node.fail("radius must be positive (got " + formatNumber(r) + ")");
  if (!(r > 2 * tolerance))
    node.fail("radius " + std::to_string(r) + " is not above twice the contact tolerance " +
              std::to_string(tolerance));
  return r;
}

/// A simple polygon with positive area, returned counter-clockwise.
Ring readPolygon(const Node& node) {
  Ring ring = node.ring(json_in::kMaxCoordinate, json_in::kMaxVertices);
  // A closed ring (GeoJSON, shapely) repeats its first vertex last: the same polygon.
  if (ring.size() >= 4 && ring.front().x == ring.back().x && ring.front().y == ring.back().y)
    ring.pop_back();
  if (auto rep = findRepeatedVertex(ring))
    node.fail("repeated vertex (vertices " + std::to_string(rep->first) + " and " +
              std::to_string(rep->second) + " coincide)");
  if (allCollinear(ring)) node.fail("polygon has zero area (all vertices on one line)");
  if (auto hit = findSelfIntersection(ring)) {
    if (hit->first == ring.size()) node.fail("polygon self-intersects");
    node.fail("polygon self-intersects (edges " + std::to_string(hit->first) + " and " +
              std::to_string(hit->second) + ")");
  }
  if (!isCounterClockwise(ring)) std::reverse(ring.begin(), ring.end());
  return ring;
}

/// A polygon (array of points) or a disc ({"center": [x, y], "radius": r}).
void readObstacle(const Node& node, Scene& scene) {
  if (node.json().is_object()) {
    node.allowOnly({"center", "radius"});
    scene.addObstacleDisc({node["center"].point(json_in::kMaxCoordinate),
                           readRadius(node["radius"], scene.tolerance())});
    return;
  }
  scene.obstacles.push_back(readPolygon(node));
}

Pose readPose(const Node& node) {
  node.arraySize(3, 3);
  return {node[size_t(0)].number(json_in::kMaxCoordinate),
          node[size_t(1)].number(json_in::kMaxCoordinate),
          node[size_t(2)].number(json_in::kMaxAngle)};
}

Robot readRobot(const Node& node, size_t index, double tolerance) {
  node.allowOnly({"name", "shape", "disc", "start", "goal", "motion"});
  Robot r;
  r.name = node.has("name") ? node["name"].string() : "robot" + std::to_string(index);
  if (r.name.empty()) node["name"].fail("robot name is empty");
  if (node.has("disc") && node.has("shape")) node.fail("a robot has a shape or a disc, not both");
  if (node.has("disc")) {
    // Turning a disc changes nothing: it translates unless told otherwise.
    r.disc = readRadius(node["disc"], tolerance);
    r.shape = discStandIn({{0, 0}, r.disc});
    r.motion = Motion::Translate;
  } else {
    r.shape = readPolygon(node["shape"]);
  }
  r.start = readPose(node["start"]);
  r.goal = readPose(node["goal"]);
  if (node.has("motion")) {
    const std::string m = node["motion"].string();
    if (m == "rigid")
      r.motion = Motion::Rigid;
    else if (m == "translate")
      r.motion = Motion::Translate;
    else
      node["motion"].fail("unknown motion kind '" + m + "' (expected rigid or translate)");
  }
  if (r.motion == Motion::Translate && r.goal.theta != r.start.theta)
    node["goal"][size_t(2)].fail("a translate robot keeps its angle: goal angle " +
                                 std::to_string(r.goal.theta) + " differs from start angle " +
                                 std::to_string(r.start.theta));
  return r;
}

// Start and goal must be free placements: inside the bounds, clear of obstacles and of the
// other robots at the same end.
void checkEndpoints(const Scene& scene, const Node& robots) {
  const CollisionChecker checker(scene);
  for (const char* end : {"start", "goal"}) {
    const Config q = std::string(end) == "start" ? startConfig(scene) : goalConfig(scene);
    for (size_t i = 0; i < scene.robots.size(); ++i) {
      const Contact c = checker.robotContact(i, poseOf(q, i));
      const std::string who = "robot '" + scene.robots[i].name + "'";
      if (c.kind == Contact::Kind::Bounds) {
        // A shape written where the robot stands in the world lands far from its pose.
        const Box b = boundingBox(scene.robots[i].shape);
        const double size = std::max(b.width(), b.height());
        const bool offOrigin = b.distance(Box{0, 0, 0, 0}) > size;
        robots[i][end].fail(who + " is not inside the bounds" +
                            (offOrigin ? std::string(" (its shape is given in the robot's own "
                                                     "frame and placed at the pose, but its points "
                                                     "lie far from that frame's origin)")
                                       : ""));
      }
      if (c.kind == Contact::Kind::Obstacle)
        robots[i][end].fail(who + " collides with " + c.describe(scene));
    }
    // Every robot is clear of the bounds and obstacles here: a contact is two robots, the
    // first pair in order (the checker's broad phase keeps hundreds of robots linear).
    if (const auto hit = checker.firstContact(q)) {
      const size_t i = hit->first, j = hit->second.index;
      robots[j][end].fail("robot '" + scene.robots[j].name + "' collides with robot '" +
                          scene.robots[i].name + "'");
    }
  }
}

}  // namespace

Scene parseScene(const nlohmann::json& doc, const std::string& source) {
  const Node root(doc, source, "");
  root.allowOnly({"format", "name", "bounds", "obstacles", "robots"});
  const std::string format = root["format"].string();
  if (format != kSceneFormat)
    root["format"].fail("unsupported format '" + format + "' (expected " + kSceneFormat + ")");

  Scene scene;
  if (root.has("name")) scene.name = root["name"].string();

  const Node b = root["bounds"];
  b.arraySize(4, 4);
  scene.bounds = {
      b[size_t(0)].number(json_in::kMaxCoordinate), b[size_t(1)].number(json_in::kMaxCoordinate),
      b[size_t(2)].number(json_in::kMaxCoordinate), b[size_t(3)].number(json_in::kMaxCoordinate)};
  if (!(scene.bounds.xmin < scene.bounds.xmax) || !(scene.bounds.ymin < scene.bounds.ymax))
    b.fail("bounds are inverted or empty (need xmin < xmax and ymin < ymax)");

  const Node obstacles = root["obstacles"];
  const size_t nObstacles = obstacles.arraySize(0, kMaxObstacles);
  size_t totalVertices = 0;
  for (size_t i = 0; i < nObstacles; ++i) {
    readObstacle(obstacles[i], scene);
    totalVertices += scene.obstacles.back().size();
    if (totalVertices > 10 * json_in::kMaxVertices)
      obstacles[i].fail("too many obstacle vertices in total (at most " +
                        std::to_string(10 * json_in::kMaxVertices) + ")");
  }

  const Node robots = root["robots"];
  const size_t nRobots = robots.arraySize(1, kMaxRobots);
  std::set<std::string> names;
  for (size_t i = 0; i < nRobots; ++i) {
    scene.robots.push_back(readRobot(robots[i], i, scene.tolerance()));
    if (!names.insert(scene.robots.back().name).second)
      (robots[i].has("name") ? robots[i]["name"] : robots[i])
          .fail("duplicate robot name '" + scene.robots.back().name + "'");
  }
  for (size_t i = 0; i < nRobots; ++i) {
    if (scene.robots[i].disc > 0) continue;
    ShrunkShape s = shrinkForContacts(scene.robots[i].shape, scene.tolerance());
    if (s.error) robots[i]["shape"].fail(*s.error);
  }
  checkEndpoints(scene, robots);
  return scene;
}

Scene loadScene(const std::string& file) { return parseScene(json_in::parseFile(file), file); }

nlohmann::json ringToJson(const Ring& ring) {
  nlohmann::json a = nlohmann::json::array();
  for (Vec2 v : ring) a.push_back({v.x, v.y});
  return a;
}

nlohmann::json sceneToJson(const Scene& scene) {
  nlohmann::json j;
  j["format"] = kSceneFormat;
  if (!scene.name.empty()) j["name"] = scene.name;
  j["bounds"] = {scene.bounds.xmin, scene.bounds.ymin, scene.bounds.xmax, scene.bounds.ymax};
  j["obstacles"] = nlohmann::json::array();
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    const Disc* d = scene.obstacleDisc(i);
    j["obstacles"].push_back(
        d ? nlohmann::json{{"center", {d->center.x, d->center.y}}, {"radius", d->radius}}
          : ringToJson(scene.obstacles[i]));
  }
  j["robots"] = nlohmann::json::array();
  for (const Robot& r : scene.robots) {
    nlohmann::json robot = {{"name", r.name}};
    if (r.disc > 0)
      robot["disc"] = r.disc;
    else
      robot["shape"] = ringToJson(r.shape);
    robot["start"] = {r.start.x, r.start.y, r.start.theta};
    robot["goal"] = {r.goal.x, r.goal.y, r.goal.theta};
    robot["motion"] = r.motion == Motion::Rigid ? "rigid" : "translate";
    j["robots"].push_back(std::move(robot));
  }
  return j;
}

void saveScene(const Scene& scene, const std::string& file) {
  writeFileAtomically(file, sceneToJson(scene).dump(1) + "\n");
}

}  // namespace mms
