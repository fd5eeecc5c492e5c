// libFuzzer target: the planners on random scenes of 1-3 robots (polygons or discs, rigid or
// translating) among 0-4 obstacles, at any angle (0, +-pi, +-pi/2, 7.5 rad or any number in
// [-20, 20]), each planner of the registry with the options that change its sampling, for 50 ms.
// A scene the loader refuses is skipped (InputError); any other exception, an abort, a signal or
// an assertion (OMPL's own), a path reported found that the continuous checker refuses, or a
// planner that overruns its time by more than two seconds (the sanitizers' slowest exact step) is a bug: libFuzzer keeps the input.
// Run: scripts/fuzz.sh (docs/robustness.md).
#include <fuzzer/FuzzedDataProvider.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "FuzzSupport.h"
#include "io/SceneIO.h"
#include "mms/Io.h"
#include "mms/Planner.h"

namespace {

using nlohmann::json;

double angle(FuzzedDataProvider& in) {
  static const double kAngles[] = {0, M_PI, -M_PI, M_PI / 2, -M_PI / 2, 7.5};
  const size_t pick = in.ConsumeIntegralInRange<size_t>(0, 6);
  return pick < 6 ? kAngles[pick] : in.ConsumeFloatingPointInRange<double>(-20, 20);
}

json point(FuzzedDataProvider& in, double lo, double hi) {
  return {in.ConsumeFloatingPointInRange<double>(lo, hi),
          in.ConsumeFloatingPointInRange<double>(lo, hi)};
}

// A triangle or an axis-aligned rectangle about (cx, cy), at most `size` across.
json polygon(FuzzedDataProvider& in, double cx, double cy, double size) {
  const double w = in.ConsumeFloatingPointInRange<double>(0.05, size) / 2;
  const double h = in.ConsumeFloatingPointInRange<double>(0.05, size) / 2;
  if (in.ConsumeBool()) return {{cx - w, cy - h}, {cx + w, cy - h}, {cx + w, cy + h}, {cx - w, cy + h}};
  return {{cx - w, cy - h}, {cx + w, cy - h}, {cx, cy + h}};
}

json robot(FuzzedDataProvider& in) {
  json r;
  const double theta = angle(in);
  const bool disc = in.ConsumeIntegralInRange<int>(0, 3) == 0;
  if (disc) {
    r["disc"] = in.ConsumeFloatingPointInRange<double>(0.1, 1);
  } else {
    r["shape"] = polygon(in, 0, 0, 2);
  }
  const bool translate = disc || in.ConsumeIntegralInRange<int>(0, 3) == 0;
  if (!disc) r["motion"] = translate ? "translate" : "rigid";
  const json at = point(in, 0.5, 9.5), to = point(in, 0.5, 9.5);
  r["start"] = {at[0], at[1], disc ? 0.0 : theta};
  r["goal"] = {to[0], to[1], disc ? 0.0 : translate ? theta : angle(in)};
  return r;
}

json sceneDocument(FuzzedDataProvider& in) {
  json doc = {{"format", "mms-scene/1"}, {"bounds", {0, 0, 10, 10}}};
  doc["obstacles"] = json::array();
  for (int k = in.ConsumeIntegralInRange<int>(0, 4); k > 0; --k) {
    const json c = point(in, 1, 9);
    doc["obstacles"].push_back(polygon(in, c[0], c[1], 4));
  }
  doc["robots"] = json::array();
  for (int k = in.ConsumeIntegralInRange<int>(1, 3); k > 0; --k) doc["robots"].push_back(robot(in));
  return doc;
}

// The planner and, for OMPL's, the settings that change how it samples and joins states.
mms::PlannerParams settings(FuzzedDataProvider& in, const mms::PlannerInfo& planner) {
  mms::PlannerParams p;
  p.seed = in.ConsumeIntegralInRange<uint64_t>(1, 1000);
  for (const mms::ParamSpec& spec : planner.params) {
    if (!in.ConsumeBool()) continue;
    if (spec.name == "lean-angles" || spec.name == "range-share")
      p.values[spec.name] = in.ConsumeFloatingPointInRange<double>(spec.min, spec.max);
    else if (spec.name == "free-samples" || spec.name == "certified-motions")
      p.values[spec.name] = 1;
  }
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace mms;
  FuzzedDataProvider in(data, size);
  const std::vector<PlannerInfo>& all = planners();
  const PlannerInfo& planner = all[in.ConsumeIntegralInRange<size_t>(0, all.size() - 1)];
  const PlannerParams params = settings(in, planner);
  Scene scene;
  try {
    scene = parseScene(sceneDocument(in), "fuzz.json");
  } catch (const InputError& e) {
    fuzz::requireOneLine(e, "fuzz.json: ");
    return 0;  // not a scene mms plans: overlapping starts, a robot outside the bounds, ...
  }
  const auto began = std::chrono::steady_clock::now();
  try {
    std::unique_ptr<Planner> p = makePlanner(planner.name, scene, params, "fuzz.json");
    const PlanResult r = p->solve(Termination(0.05));
    p->finishBackgroundWork();
    if (r.status == PlanStatus::Found)
      fuzz::require(certify(scene, r.waypoints).ok, "a path reported found is not certified");
  } catch (const InputError& e) {
    fuzz::requireOneLine(e, "");  // a scene this planner does not take
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  fuzz::require(seconds < 2.05, "the planner overran its 50 ms by more than two seconds");
  return 0;
}
