#include "io/Discopygal.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <vector>

#include "geometry/PolygonOps.h"
#include "io/Json.h"
#include "io/SceneIO.h"
#include "util/Number.h"

namespace mms {

namespace {

using json_in::Node;

/// The name of the walls the export puts round the bounds, by which the import knows them.
constexpr const char* kBoundsWall = "bounds";

Ring polygon(const Node& n) {
  Ring r = n.ring(json_in::kMaxCoordinate, json_in::kMaxVertices);
  // discopygal drops repeated points on load; so do we.
  Ring out;
  for (Vec2 v : r)
    if (out.empty() || v.x != out.back().x || v.y != out.back().y) out.push_back(v);
  if (out.size() > 1 && out.front().x == out.back().x && out.front().y == out.back().y)
    out.pop_back();
  return out;
}

double positive(const Node& n) {
  double v = n.number(json_in::kMaxCoordinate);
  if (!(v > 0)) n.fail("must be positive");
  return v;
}

// discopygal plans in the open plane. The box around obstacles and robots (at start and goal)
// grown by the largest robot's diameter, with 10 % to spare, leaves a ring round everything in
// which any robot passes: nobody is walled in where the plane would have let them by.
Box openPlaneBounds(const Scene& scene) {
  std::vector<Vec2> points;
  for (const Ring& o : scene.obstacles) points.insert(points.end(), o.begin(), o.end());
  double diameter = 0;
  for (const Robot& r : scene.robots) {
    diameter = std::max(diameter, 2 * radius(r.shape));
    for (const Pose& p : {r.start, r.goal}) {
      const Ring placed = placedRing(r.shape, p);
      points.insert(points.end(), placed.begin(), placed.end());
    }
  }
  const Box b = boundingBox(points);
  const double margin = 1.1 * diameter;
  return b.grown(margin);
}

/// Whether an obstacle is one of the walls mms's export puts round the bounds.
bool namedBounds(const Node& o) {
  if (!o.has("data") || !o["data"].json().is_object() || !o["data"].has("name")) return false;
  const nlohmann::json& name = o["data"]["name"].json();
  return name.is_string() && name.get<std::string>() == kBoundsWall;
}

/// The box four walls enclose, as discopygalJson() writes them (each the width of the box
/// inside, touching the others at the corners), or nothing if they are not such walls.
std::optional<Box> boundsOfWalls(const std::vector<Ring>& walls) {
  if (walls.size() != 4) return std::nullopt;
  std::vector<Box> boxes;
  for (const Ring& w : walls) {
    if (w.size() != 4) return std::nullopt;
    boxes.push_back(boundingBox(w));
  }
  // Below, above, left, right of the box inside, in the order written.
  const Box inside{boxes[2].xmax, boxes[0].ymax, boxes[3].xmin, boxes[1].ymin};
  if (!(inside.xmin < inside.xmax && inside.ymin < inside.ymax)) return std::nullopt;
  return inside;
}

}  // namespace

bool isDiscopygal(const nlohmann::json& doc) {
  if (!doc.is_object() || doc.contains("format")) return false;
  if (doc.contains("__class__")) return true;
  for (const char* key : {"obstacles", "robots"})
    if (doc.contains(key) && doc[key].is_array())
      for (const auto& e : doc[key])
        if (e.is_object() && e.contains("__class__")) return true;
  return false;
}

Scene importDiscopygal(const std::string& file, ImportNotes& notes) {
  return importDiscopygal(json_in::parseFile(file), file, notes);
}

Scene importDiscopygal(const nlohmann::json& doc, const std::string& file, ImportNotes& notes) {
  const Node root(doc, file, "(root)");
  root.requireObject();
  if (root.has("__class__") && root["__class__"].string() != "Scene")
    root["__class__"].fail("expected \"Scene\"");
  Scene scene;
  scene.name = std::filesystem::path(file).stem().string();
  const Node obstacles = root["obstacles"];
  std::vector<Ring> walls;  // the bounds of a scene mms exported, as four walls
  for (size_t i = 0; i < obstacles.arraySize(0, json_in::kMaxVertices); ++i) {
    const Node o = obstacles[i];
    o.requireObject();
    const std::string cls = o["__class__"].string();
    if (cls == "ObstaclePolygon") {
      (namedBounds(o) ? walls : scene.obstacles).push_back(polygon(o["poly"]));
    } else if (cls == "ObstacleDisc") {
      scene.addObstacleDisc({o["location"].point(json_in::kMaxCoordinate), positive(o["radius"])});
    } else {
      o["__class__"].fail("unknown obstacle class '" + cls +
                          "' (expected ObstaclePolygon or ObstacleDisc)");
    }
  }
  const Node robots = root["robots"];
  const size_t count = robots.arraySize(1, kMaxRobots);
  for (size_t i = 0; i < count; ++i) {
    const Node r = robots[i];
    r.requireObject();
    const std::string cls = r["__class__"].string();
    Robot robot;
    robot.name = "robot" + std::to_string(i);
    if (r.has("data") && r["data"].has("name") && r["data"]["name"].json().is_string() &&
        !r["data"]["name"].string().empty())
      robot.name = r["data"]["name"].string();
    if (cls == "RobotPolygon" || cls == "RobotDisc") {
      robot.motion = Motion::Translate;
      if (cls == "RobotPolygon") {
        robot.shape = polygon(r["poly"]);
      } else {
        robot.disc = positive(r["radius"]);
        robot.shape = discStandIn({{0, 0}, robot.disc});
      }
      const Vec2 s = r["start"].point(json_in::kMaxCoordinate),
                 e = r["end"].point(json_in::kMaxCoordinate);
      robot.start = {s.x, s.y, 0};
      robot.goal = {e.x, e.y, 0};
    } else if (cls == "RobotRod") {
      const double len = positive(r["length"]);
      const double w = len / 100;
      robot.shape = {{0, -w / 2}, {len, -w / 2}, {len, w / 2}, {0, w / 2}};
      for (const char* key : {"start", "end"}) {
        const Node p = r[key];
        p.arraySize(2, 2);
        const Vec2 at = p[size_t(0)].point(json_in::kMaxCoordinate);
        const double theta = p[size_t(1)].number(json_in::kMaxAngle);
        (std::string(key) == "start" ? robot.start : robot.goal) = {at.x, at.y, theta};
      }
      notes.warnings.push_back(robot.name + ": rod of length " + formatNumber(len) +
                               " as a rigid rectangle " + formatNumber(w) +
                               " wide around it (conservative)");
    } else {
      r["__class__"].fail("unknown robot class '" + cls +
                          "' (expected RobotPolygon, RobotDisc or RobotRod)");
    }
    scene.robots.push_back(robot);
  }
  if (const std::optional<Box> inside = boundsOfWalls(walls)) {
    scene.bounds = *inside;  // as exported: the round trip keeps the bounds
    return parseScene(sceneToJson(scene), file);
  }
  scene.obstacles.insert(scene.obstacles.end(), walls.begin(), walls.end());
  scene.bounds = openPlaneBounds(scene);
  notes.warnings.push_back(
      "bounds: none in discopygal; the box around obstacles and robots, grown on every side by "
      "the largest robot's diameter and 10 % more, so that every robot can pass round "
      "everything");
  return parseScene(sceneToJson(scene), file);
}

std::string discopygalJson(const Scene& scene, ImportNotes& notes) {
  using nlohmann::json;
  json obstacles = json::array();
  for (size_t i = 0; i < scene.obstacles.size(); ++i) {
    const Disc* d = scene.obstacleDisc(i);
    obstacles.push_back(d ? json{{"__class__", "ObstacleDisc"},
                                 {"location", {d->center.x, d->center.y}},
                                 {"radius", d->radius},
                                 {"data", json::object()}}
                          : json{{"__class__", "ObstaclePolygon"},
                                 {"poly", ringToJson(scene.obstacles[i])},
                                 {"data", json::object()}});
  }
  // The bounds as four walls, 5 % of the scene's size thick, overlapping at the corners.
  const Box& b = scene.bounds;
  const double t = 0.05 * std::max(b.width(), b.height());
  for (const Box& w :
       {Box{b.xmin - t, b.ymin - t, b.xmax + t, b.ymin},
        Box{b.xmin - t, b.ymax, b.xmax + t, b.ymax + t}, Box{b.xmin - t, b.ymin, b.xmin, b.ymax},
        Box{b.xmax, b.ymin, b.xmax + t, b.ymax}})
    obstacles.push_back(
        {{"__class__", "ObstaclePolygon"},
         {"poly",
          ringToJson({{w.xmin, w.ymin}, {w.xmax, w.ymin}, {w.xmax, w.ymax}, {w.xmin, w.ymax}})},
         {"data", {{"name", kBoundsWall}}}});
  notes.warnings.push_back("bounds written as four walls (discopygal scenes have none)");
  json robots = json::array();
  for (const Robot& r : scene.robots) {
    if (r.disc > 0) {
      robots.push_back({{"__class__", "RobotDisc"},
                        {"radius", r.disc},
                        {"start", {r.start.x, r.start.y}},
                        {"end", {r.goal.x, r.goal.y}},
                        {"data", {{"name", r.name}}}});
      continue;
    }
    Ring shape = r.shape;
    if (r.motion == Motion::Rigid) {
      shape = placedRing(r.shape, {0, 0, r.start.theta});
      notes.warnings.push_back(r.name +
                               ": rotating robot written as a translating RobotPolygon at its "
                               "start angle (discopygal's polygon robots do not rotate)");
    }
    robots.push_back({{"__class__", "RobotPolygon"},
                      {"poly", ringToJson(shape)},
                      {"start", {r.start.x, r.start.y}},
                      {"end", {r.goal.x, r.goal.y}},
                      {"data", {{"name", r.name}}}});
  }
  json doc = {{"__class__", "Scene"},
              {"obstacles", obstacles},
              {"robots", robots},
              {"metadata", {{"details", scene.name}, {"solvers", ""}, {"exported_by", "mms"}}}};
  return doc.dump(2) + "\n";
}

}  // namespace mms
