#include "io/AnyScene.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "io/Discopygal.h"
#include "io/Json.h"
#include "io/SceneIO.h"

namespace mms {

void noteAngles(const Scene& scene, const std::string& source, ImportNotes& notes) {
  for (size_t i = 0; i < scene.robots.size(); ++i)
    for (const auto& [end, pose] :
         {std::pair{"start", scene.robots[i].start}, {"goal", scene.robots[i].goal}})
      if (std::fabs(pose.theta) > 2 * M_PI) {
        std::ostringstream w;
        w << source << ": robots[" << i << "]." << end << ": angle " << pose.theta
          << " is more than a full turn; angles are in radians";
        notes.mistakes.push_back(w.str());
      }
}

void noteClosedRings(const nlohmann::json& doc, const std::string& source, ImportNotes& notes) {
  auto closed = [](const nlohmann::json& ring) {
    return ring.is_array() && ring.size() >= 4 && ring.front() == ring.back();
  };
  size_t n = 0;
  if (doc.is_object() && doc.contains("obstacles") && doc["obstacles"].is_array())
    for (const auto& o : doc["obstacles"]) n += closed(o);
  if (doc.is_object() && doc.contains("robots") && doc["robots"].is_array())
    for (const auto& r : doc["robots"])
      if (r.is_object() && r.contains("shape")) n += closed(r["shape"]);
  if (n)
    notes.warnings.push_back(source + ": " + std::to_string(n) +
                             " polygon(s) given as closed rings (the first vertex repeated "
                             "last): read without the repeat");
}

Scene loadAnyScene(const std::string& file, ImportNotes& notes) {
  const std::filesystem::path ext = std::filesystem::path(file).extension();
  Scene scene;
  if (ext == ".cfg") {
    scene = importOmplApp(file, notes);
  } else {
    // Parsed once, whichever format it turns out to be.
    const json_in::Json doc = json_in::parseFile(file);
    const bool discopygal = ext == ".json" && isDiscopygal(doc);
    if (!discopygal) noteClosedRings(doc, file, notes);
    scene = discopygal ? importDiscopygal(doc, file, notes) : parseScene(doc, file);
  }
  noteAngles(scene, file, notes);
  return scene;
}

}  // namespace mms
