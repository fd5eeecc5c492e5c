// mms assemble: three-handed disassembly of a scene (src/assembly/Disassembly.h) and its files.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "Commands.h"
#include "assembly/Disassembly.h"
#include "io/PathIO.h"
#include "io/SceneIO.h"
#include "mms/Errors.h"
#include "render/SvgRenderer.h"
#include "util/AtomicFile.h"
#include "util/Interrupt.h"

namespace mms::cli {

namespace {

std::string partList(const Scene& scene, const std::vector<size_t>& parts) {
  std::string out;
  for (const size_t p : parts) out += (out.empty() ? "" : ", ") + scene.robots[p].name;
  return out;
}

// "step 3: lower out; wide-M makes room (two hands, 0.436 s, 9 waypoints)"
std::string describe(const Scene& scene, size_t index, const DisassemblyStep& s) {
  std::vector<size_t> helpers;
  for (const size_t p : s.parts)
    if (std::find(s.removed.begin(), s.removed.end(), p) == s.removed.end()) helpers.push_back(p);
  char tail[96];
  std::snprintf(tail, sizeof tail, " (%s, %.3f s, %zu waypoints)",
                s.parts.size() == 1 ? "one hand" : "two hands", s.seconds, s.waypoints.size());
  return "step " + std::to_string(index + 1) + ": " + partList(scene, s.removed) + " out" +
         (helpers.empty() ? "" : "; " + partList(scene, helpers) + " makes room") + tail;
}

}  // namespace

int assemble(const AssembleArgs& a) {
  const Scene scene = readScene(a.scene, a.quiet);
  if (scene.obstacles.empty())
    throw InputError(a.scene + ": obstacles: empty; assemble needs a static part (the obstacles)");
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(a.output, ec);
  if (ec || !fs::is_directory(a.output))
    throw InputError(a.output + ": (output): cannot create the directory (" + ec.message() + ")");

  DisassemblySettings settings;
  settings.seed = a.seed;
  settings.pairs = !a.noPairs;
  DisassemblyPlanner planner(scene, settings);
  auto progress = [&](size_t index, const DisassemblyStep& step) {
    if (!a.quiet) std::fprintf(stderr, "mms assemble: %s\n", describe(scene, index, step).c_str());
  };
  const DisassemblyResult r = planner.solve(Termination(a.timeLimit, sigintFlag()), progress);
  if (interruptRequested()) throw Interrupted();

  // Files: one scene and one certified path per step, the whole motion, a summary.
  nlohmann::json summary = {
      {"format", "mms-disassembly/1"}, {"scene", a.scene},     {"seed", a.seed},
      {"complete", r.complete()},      {"seconds", r.seconds}, {"attempts", r.attempts}};
  summary["steps"] = nlohmann::json::array();
  const fs::path dir(a.output);
  for (size_t k = 0; k < r.steps.size(); ++k) {
    const DisassemblyStep& s = r.steps[k];
    const std::string stem = "step-" + std::to_string(k + 1);
    saveScene(s.scene, (dir / (stem + ".scene.json")).string());
    Path path;
    path.waypoints = s.waypoints;
    savePath(path, s.scene, (dir / (stem + ".path.json")).string());
    nlohmann::json parts = nlohmann::json::array(), removed = nlohmann::json::array();
    for (const size_t p : s.parts) parts.push_back(scene.robots[p].name);
    for (const size_t p : s.removed) removed.push_back(scene.robots[p].name);
    summary["steps"].push_back({{"parts", parts},
                                {"removed", removed},
                                {"seconds", s.seconds},
                                {"scene", stem + ".scene.json"},
                                {"path", stem + ".path.json"}});
  }
  nlohmann::json stuck = nlohmann::json::array();
  for (const size_t p : r.stuck) stuck.push_back(scene.robots[p].name);
  summary["stuck"] = stuck;
  saveScene(r.finalScene, (dir / "disassembly.scene.json").string());
  Path whole;
  whole.waypoints = r.path;
  whole.extra = {{"planner", "mms assemble"}, {"seed", a.seed}};
  savePath(whole, r.finalScene, (dir / "disassembly.path.json").string());
  writeFileAtomically((dir / "disassembly.json").string(), summary.dump(1) + "\n");
  if (!a.svg.empty()) writeFileAtomically(a.svg, renderSvg(r.finalScene, &whole));

  for (size_t k = 0; k < r.steps.size(); ++k)
    std::printf("%s\n", describe(scene, k, r.steps[k]).c_str());
  std::printf("%s: %zu step%s, %zu planner run%s, %.3f s; files in %s\n", a.scene.c_str(),
              r.steps.size(), r.steps.size() == 1 ? "" : "s", r.attempts,
              r.attempts == 1 ? "" : "s", r.seconds, a.output.c_str());
  if (!r.complete()) {
    std::printf("%s: stuck: %s (%s)\n", a.scene.c_str(), partList(scene, r.stuck).c_str(),
                r.stuckBecause.c_str());
    return 1;
  }
  std::printf("%s: every part removed; the whole motion is certified (%s)\n", a.scene.c_str(),
              (dir / "disassembly.path.json").c_str());
  return 0;
}

}  // namespace mms::cli
