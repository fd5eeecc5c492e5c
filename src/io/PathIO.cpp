#include "io/PathIO.h"

#include "io/Json.h"
#include "util/AtomicFile.h"

namespace mms {

using json_in::Node;

Path parsePath(const nlohmann::json& doc, const std::string& source, const Scene& scene) {
  const Node root(doc, source, "");
  root.requireObject();
  const std::string format = root["format"].string();
  if (format != kPathFormat)
    root["format"].fail("unsupported format '" + format + "' (expected " + kPathFormat + ")");
  if (root.has("scene")) {
    const std::string name = root["scene"].string();
    if (!scene.name.empty() && name != scene.name)
      root["scene"].fail("path is for scene '" + name + "', not '" + scene.name + "'");
  }
  const Node robots = root["robots"];
  const size_t k = robots.arraySize(scene.robots.size(), scene.robots.size());
  for (size_t i = 0; i < k; ++i)
    if (robots[i].string() != scene.robots[i].name)
      robots[i].fail("expected robot '" + scene.robots[i].name + "' (scene order), found '" +
                     robots[i].string() + "'");

  Path path;
  const Node wps = root["waypoints"];
  const size_t n = wps.arraySize(1, kMaxWaypoints);
  path.waypoints.reserve(n);
  for (size_t w = 0; w < n; ++w) {
    const Node wp = wps[w];
    wp.arraySize(scene.dof(), scene.dof());
    Config q(scene.dof());
    for (size_t c = 0; c < q.size(); ++c)
      q[c] = wp[c].number(c % 3 == 2 ? json_in::kMaxAngle : json_in::kMaxCoordinate);
    path.waypoints.push_back(std::move(q));
  }
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (it.key() != "format" && it.key() != "scene" && it.key() != "robots" &&
        it.key() != "waypoints")
      path.extra[it.key()] = it.value();
  return path;
}

Path loadPath(const std::string& file, const Scene& scene) {
  return parsePath(json_in::parseFile(file), file, scene);
}

nlohmann::json pathToJson(const Path& path, const Scene& scene) {
  nlohmann::json j = path.extra.is_object() ? path.extra : nlohmann::json::object();
  j["format"] = kPathFormat;
  if (!scene.name.empty()) j["scene"] = scene.name;
  j["robots"] = nlohmann::json::array();
  for (const Robot& r : scene.robots) j["robots"].push_back(r.name);
  j["waypoints"] = path.waypoints;
  return j;
}

void savePath(const Path& path, const Scene& scene, const std::string& file) {
  writeFileAtomically(file, pathToJson(path, scene).dump() + "\n");
}

}  // namespace mms
