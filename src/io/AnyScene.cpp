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
        notes.warnings.push_back(w.str());
      }
}

Scene loadAnyScene(const std::string& file, ImportNotes& notes) {
  const std::filesystem::path ext = std::filesystem::path(file).extension();
  Scene scene;
  if (ext == ".cfg") {
    scene = importOmplApp(file, notes);
  } else {
    // Parsed once, whichever format it turns out to be.
    const json_in::Json doc = json_in::parseFile(file);
    scene = ext == ".json" && isDiscopygal(doc) ? importDiscopygal(doc, file, notes)
                                                : parseScene(doc, file);
  }
  noteAngles(scene, file, notes);
  return scene;
}

}  // namespace mms
