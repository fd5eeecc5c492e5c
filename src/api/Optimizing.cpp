// Certified path optimisation behind the planner seam, for every planner alike: the planner
// finds its first certified path, then the optimiser (path/Optimize.h) shortens it under what is
// left of the time limit. The planner's time (PlanStatistics::seconds) stays the time to its
// first certified path, as OMPL's benchmarks report time apart from simplification; the
// optimisation is the phase "optimize".
#include <memory>

#include "api/Adapters.h"
#include "check/PathChecker.h"
#include "path/Optimize.h"

namespace mms {

namespace {

using Type = ParamSpec::Type;

class Optimizing final : public Planner {
 public:
  Optimizing(std::unique_ptr<Planner> inner, const Scene& scene, uint64_t seed,
             OptimizeSettings settings, std::map<std::string, double> parameters)
      : inner_(std::move(inner)),
        scene_(scene),
        seed_(seed),
        settings_(settings),
        parameters_(std::move(parameters)) {}

  PlanResult solve(const Termination& stop, const Progress& progress) override {
    PlanResult r = inner_->solve(stop, progress);
    for (const auto& [k, v] : parameters_) r.parameters[k] = v;
    if (!r.found() || parameters_.at("optimize") == 0) return r;
    const CollisionChecker checker(scene_);
    Random rng(seed_ ^ 0x6f7074696d697a65ull);  // its own stream: the planner's is not touched
    std::vector<Config> w = r.waypoints;
    const OptimizeStats s = optimizePath(scene_, checker, rng, settings_, stop, w);
    Stopwatch certify;
    PathCheckResult c = checkPath(scene_, checker, w);
    // The steps certified every change; a refusal here would be a bug, and the planner's own
    // certified path is kept.
    if (c.ok) {
      r.waypoints = std::move(w);
      r.certificate = c;
    }
    r.stats.phases.emplace_back("optimize", s.seconds + certify.seconds());
    r.stats.counts.emplace_back("optimize_changes", s.accepted);
    r.stats.counts.emplace_back("optimize_evaluations", s.evaluations);
    return r;
  }

  bool setQuery(const Config& start, const Config& goal) override {
    if (!inner_->setQuery(start, goal)) return false;
    for (size_t i = 0; i < scene_.robots.size(); ++i) {
      scene_.robots[i].start = poseOf(start, i);
      scene_.robots[i].goal = poseOf(goal, i);
    }
    return true;
  }

 private:
  std::unique_ptr<Planner> inner_;
  Scene scene_;
  uint64_t seed_;
  OptimizeSettings settings_;
  std::map<std::string, double> parameters_;
};

}  // namespace

PlannerInfo withPathOptimization(PlannerInfo info, bool onByDefault) {
  const ParamSpec optimize{
      "optimize",
      Type::Integer,
      0,
      1,
      onByDefault ? 1.0 : 0.0,
      "1: shorten the first certified path (shortcuts, one robot's translation or rotation "
      "straightened, turns the short way), every change certified, within the time limit; 0: "
      "the planner's path as found (default " +
          std::string(onByDefault ? "1" : "0") + ")"};
  ParamSpec objective{"objective",
                      Type::Integer,
                      0,
                      1,
                      0,
                      "What --optimize improves: length (the distance the robots' points "
                      "travel), or clearance (then also away from contacts) (default length)"};
  objective.choices = {"length", "clearance"};
  info.params.push_back(optimize);
  info.params.push_back(objective);
  info.make = [make = info.make, optimize, objective](
                  const Scene& scene, const PlannerParams& params, const std::string& source) {
    OptimizeSettings s;
    s.objective =
        paramValue(params, objective) == 1 ? PathObjective::Clearance : PathObjective::Length;
    return std::make_unique<Optimizing>(
        make(scene, params, source), scene, params.seed, s,
        std::map<std::string, double>{{"optimize", paramValue(params, optimize)},
                                      {"objective", paramValue(params, objective)}});
  };
  return info;
}

}  // namespace mms
