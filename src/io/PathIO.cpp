#include "io/PathIO.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "io/Json.h"
#include "mms/Errors.h"
#include "util/AtomicFile.h"
#include "util/Number.h"

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
  robots.arraySize(0, kMaxWaypoints);
  if (robots.json().size() != scene.robots.size()) {
    // Both lists named (their first names: hundreds of robots stay one readable line), so that
    // a path for another scene is seen at once.
    auto names = [](auto&& list) {
      constexpr size_t kShown = 8;
      std::string out;
      for (size_t i = 0; i < list.size() && i < kShown; ++i)
        out += (out.empty() ? "" : ", ") + list[i];
      if (list.size() > kShown) out += ", and " + std::to_string(list.size() - kShown) + " more";
      return "[" + out + "]";
    };
    std::vector<std::string> mine, theirs;
    for (const auto& n : robots.json())
      mine.push_back(n.is_string() ? n.get<std::string>() : n.dump());
    for (const Robot& r : scene.robots) theirs.push_back(r.name);
    robots.fail("the path moves " + std::to_string(mine.size()) + " robot(s) " + names(mine) +
                ", the scene has " + std::to_string(theirs.size()) + " " + names(theirs));
  }
  const size_t k = scene.robots.size();
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

std::vector<Config> parseOmplPath(const std::string& text, const std::string& source,
                                  const Scene& scene) {
  size_t rigid = 0;
  for (const Robot& r : scene.robots) rigid += r.motion != Motion::Translate;
  const size_t full = 3 * scene.robots.size(), compact = full - (scene.robots.size() - rigid);
  std::vector<Config> w;
  std::istringstream lines(text);
  size_t lineNo = 0;
  for (std::string line; std::getline(lines, line);) {
    ++lineNo;
    const std::string where = source + ": line " + std::to_string(lineNo) + ": ";
    std::istringstream in(line);
    in.imbue(std::locale::classic());
    std::vector<double> v;
    std::string token;
    while (in >> token) {
      const std::optional<double> x = wholeNumber(token);
      if (!x || !std::isfinite(*x)) throw InputError(where + "'" + token + "' is not a number");
      v.push_back(*x);
    }
    if (v.empty()) continue;
    if (v.size() != full && v.size() != compact)
      throw InputError(where + "expected " + std::to_string(compact) + " numbers (x y theta per " +
                       "robot, x y for one that translates), found " + std::to_string(v.size()));
    if (w.size() >= kMaxWaypoints) throw InputError(where + "more than 10^7 waypoints");
    Config q(full);
    for (size_t i = 0, k = 0; i < scene.robots.size(); ++i) {
      q[3 * i] = v[k++];
      q[3 * i + 1] = v[k++];
      const bool angle = v.size() == full || scene.robots[i].motion != Motion::Translate;
      q[3 * i + 2] = angle ? v[k++] : scene.robots[i].start.theta;
      if (!w.empty() && scene.robots[i].motion != Motion::Translate) {
        const double prev = w.back()[3 * i + 2];
        q[3 * i + 2] = prev + std::remainder(q[3 * i + 2] - prev, 2 * M_PI);
      }
    }
    w.push_back(std::move(q));
  }
  if (w.empty())
    throw InputError(source + ": (file): no waypoints (an OMPL.app path has one line per state)");
  return w;
}

namespace {
bool startsAsJson(const std::string& text) {
  for (const char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) return c == '{';
  return false;
}
}  // namespace

Path loadPath(const std::string& file, const Scene& scene) {
  const std::string text = json_in::readFile(file);
  // OMPL.app's .path files are numbers, one line per state; ours are JSON (also when a user
  // names one FILE.path: `mms plan -o x.path` writes JSON).
  if (std::filesystem::path(file).extension() != ".path" || startsAsJson(text))
    return parsePath(json_in::parseText(text, file), file, scene);
  Path p;
  p.waypoints = parseOmplPath(text, file, scene);
  return p;
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
