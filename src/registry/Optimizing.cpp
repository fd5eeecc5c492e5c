// Certified path optimisation behind the planner seam, for every planner alike: the planner
// finds its first certified path, then the optimiser (path/Optimize.h) shortens it under what is
// left of the time limit. The planner's time (PlanStatistics::seconds) stays the time to its
// first certified path, as OMPL's benchmarks report time apart from simplification; the
// optimisation is the phase "optimize".
//
// The optimiser is local: it keeps the path's homotopy class. With --restarts N the planner then
// runs N more times from seeds drawn from the run's seed (a fresh planner each, so a different
// roadmap and often a different way round the obstacles), each path is optimised too, and the
// best is kept (phase "restarts"): anytime improvement that stays the same for the same seed, as
// long as the time limit does not cut it.
#include <algorithm>
#include <functional>
#include <memory>

#include "check/PathChecker.h"
#include "path/Optimize.h"
#include "path/Schedule.h"
#include "registry/Adapters.h"
#include "util/Deferred.h"
#include "util/Number.h"

namespace mms {

namespace {

using Type = ParamSpec::Type;

/// The shortcut rounds' tests per test of the sampler's planning (--optimize-effort), and at
/// least. On open clutter's tuning seeds, with the sampler's leaning angles: 1.5 times the
/// planning's kept paths as short and turning as little as twice did, for 0.85x the
/// optimiser's time; once, 0.7x the time, left them 4 % longer and the 90th percentile of
/// rotation beyond the short way 1.1 rad more (docs/planner.md, "Path optimisation").
constexpr double kEffort = 1.5;
constexpr size_t kLeastRoundsWork = 1000;

using Factory = std::function<std::unique_ptr<Planner>(const Scene& scene, uint64_t seed)>;

class Optimizing final : public Planner {
 public:
  Optimizing(Factory make, const Scene& scene, uint64_t seed, OptimizeSettings settings,
             std::map<std::string, double> parameters, std::vector<ParamSpec> specs)
      : make_(std::move(make)),
        inner_(make_(scene, seed)),
        scene_(scene),
        seed_(seed),
        settings_(settings),
        parameters_(std::move(parameters)),
        specs_(std::move(specs)) {}
  // What a time limit cut is freed here, once no planner runs (util/Deferred.h).
  ~Optimizing() override {
    inner_->finishBackgroundWork();  // what a lost race's MMS cuts is freed here too
    freeDeferredIfIdle();
  }

  PlanResult solve(const Termination& stop, const Progress& progress) override {
    const RunningSolve running;
    // What earlier runs' limits cut (this planner's last query, another thread's run) is freed
    // at the start of this one, out of its budget instead of past it (util/Deferred.h); the last
    // race's MMS first stops cutting.
    inner_->finishBackgroundWork();
    freeDeferred();
    PlanResult r = inner_->solve(stop, progress);
    for (const auto& [k, v] : parameters_) r.parameters[k] = v;
    // This planner's declarations, and the inner planner's for what only it declares (the
    // portfolio's sampler's switches): each parameter keeps the one type it is declared with.
    std::vector<ParamSpec> specs = specs_;
    for (const ParamSpec& inner : r.parameterSpecs)
      if (std::none_of(specs.begin(), specs.end(),
                       [&](const ParamSpec& s) { return s.key() == inner.key(); }))
        specs.push_back(inner);
    r.parameterSpecs = std::move(specs);
    if (!r.found()) return r;
    const CollisionChecker checker(scene_);
    if (parameters_.at("optimize") != 0) optimizeFound(r, checker, stop);
    if (parameters_.at("concurrent") != 0 && scene_.robots.size() >= 2)
      moveAtOnce(r, checker, stop);
    measureFleet(scene_, checker, r.waypoints, r.certificate);
    return r;
  }

  void finishBackgroundWork() override { inner_->finishBackgroundWork(); }

  bool setQuery(const Config& start, const Config& goal) override {
    if (!inner_->setQuery(start, goal)) return false;
    for (size_t i = 0; i < scene_.robots.size(); ++i) {
      scene_.robots[i].start = poseOf(start, i);
      scene_.robots[i].goal = poseOf(goal, i);
    }
    return true;
  }

 private:
  /// The optimiser on a found path, and with --restarts the best of more runs.
  void optimizeFound(PlanResult& r, const CollisionChecker& checker, const Termination& stop) {
    OptimizeStats total;
    improve(r, checker, seed_, stop, total);
    r.stats.phases.emplace_back("optimize", total.seconds);
    const size_t restarts = size_t(parameters_.at("restarts"));
    if (restarts > 0) {
      inner_->finishBackgroundWork();  // a restart's race gets both cores
      Stopwatch watch;
      size_t run = 0, improved = 0;
      Random seeds(seed_ ^ 0x7265737461727473ull);
      for (; run < restarts && !stop(); ++run) {
        const uint64_t seed = seeds.bits();
        freeDeferred();  // the last restart's race may have cut a slice: not one kept per run
        PlanResult other = make_(scene_, seed)->solve(stop);
        if (!other.found()) continue;
        OptimizeStats s;
        improve(other, checker, seed, stop, s);
        if (better(other, r, checker)) {
          r.waypoints = std::move(other.waypoints);
          r.certificate = other.certificate;
          r.stats.solvedBy = other.stats.solvedBy;  // the portfolio member whose path it is
          ++improved;
        }
      }
      r.stats.phases.emplace_back("restarts", watch.seconds());
      r.stats.counts.emplace_back("restarts_run", run);
      r.stats.counts.emplace_back("restarts_improved", improved);
    }
    r.stats.counts.emplace_back("optimize_changes", total.accepted);
    r.stats.counts.emplace_back("optimize_rounds", total.rounds);
    r.stats.counts.emplace_back("optimize_evaluations", total.evaluations);
    r.stats.counts.emplace_back("optimize_rounds_checks", total.roundsWork);
    if (total.slices > 0) r.stats.counts.emplace_back("optimize_slices", total.slices);
    if (total.gridRoutes > 0) r.stats.counts.emplace_back("optimize_grid_routes", total.gridRoutes);
  }

  /// `w` in place of the path once the continuous checker certifies it. A last guard, and a path
  /// along contacts takes it seconds: the limit holds, and a refusal (a bug) or the limit keeps
  /// the path as it was.
  void takeIfCertified(PlanResult& r, const CollisionChecker& checker, std::vector<Config> w,
                       const Termination& stop) const {
    const StopScope scope(stop);
    try {
      const PathCheckResult c = checkPath(scene_, checker, w);
      if (c.ok) {
        r.waypoints = std::move(w);
        r.certificate = c;
      }
    } catch (const Stopped&) {
    }
  }

  /// Robots moving at once where they can (path/Schedule.h), certified again. Phase "schedule".
  void moveAtOnce(PlanResult& r, const CollisionChecker& checker, const Termination& stop) const {
    Stopwatch watch;
    ScheduleStats s;
    std::vector<Config> w = concurrentSchedule(scene_, checker, r.waypoints, &s);
    if (s.makespanAfter < s.makespanBefore) takeIfCertified(r, checker, std::move(w), stop);
    r.stats.phases.emplace_back("schedule", watch.seconds());
    r.stats.counts.emplace_back("schedule_actions", s.actions);
    r.stats.counts.emplace_back("schedule_dependencies", s.dependencies);
  }

  /// Optimises a found path in place (certified again at the end), adding to `stats`.
  void improve(PlanResult& r, const CollisionChecker& checker, uint64_t seed,
               const Termination& stop, OptimizeStats& stats) const {
    Stopwatch watch;
    Random rng(seed ^ 0x6f7074696d697a65ull);  // its own stream: the planner's is not touched
    std::vector<Config> w = r.waypoints;
    // A sampler's path found at once is not polished for much longer than it took to find.
    OptimizeSettings settings = settings_;
    const double effort = parameters_.at("optimize_effort");
    if (effort > 0 && r.stats.checks > 0)
      settings.roundsWork = std::max(kLeastRoundsWork, size_t(effort * double(r.stats.checks)));
    const OptimizeStats s = optimizePath(scene_, checker, rng, settings, stop, w);
    // Every change was certified; this is a last guard.
    if (s.accepted > 0) takeIfCertified(r, checker, std::move(w), stop);
    stats.accepted += s.accepted;
    stats.evaluations += s.evaluations;
    stats.rounds += s.rounds;
    stats.roundsWork += s.roundsWork;
    stats.slices += s.slices;
    stats.gridRoutes += s.gridRoutes;
    stats.seconds += watch.seconds();
  }

  /// Whether `a` beats `b` by the objective: shorter, or for clearance farther from contact.
  bool better(const PlanResult& a, const PlanResult& b, const CollisionChecker& checker) const {
    if (settings_.objective == PathObjective::Clearance &&
        a.certificate.minClearance != b.certificate.minClearance)
      return a.certificate.minClearance > b.certificate.minClearance;
    return pathCost(checker, a.waypoints) < pathCost(checker, b.waypoints);
  }

  Factory make_;
  std::unique_ptr<Planner> inner_;
  Scene scene_;
  uint64_t seed_;
  OptimizeSettings settings_;
  std::map<std::string, double> parameters_;
  std::vector<ParamSpec> specs_;  // every parameter of the planner, its own and these
};

/// What ends the shortcut rounds, declared once for the command line, benchmarks and docs.
struct RoundsParams {
  ParamSpec rounds, gain, effort;
};

RoundsParams roundsParams() {
  const OptimizeSettings defaults;
  const ParamSpec rounds{"optimize-rounds",
                         Type::Integer,
                         1,
                         1000,
                         double(defaults.rounds),
                         "With --optimize: at most this many rounds of " +
                             std::to_string(defaults.attempts) + " shortcut attempts (default " +
                             formatNumber(double(defaults.rounds)) + ")"};
  const ParamSpec gain{"optimize-gain",
                       Type::Real,
                       0,
                       1,
                       defaults.minGain,
                       "With --optimize: rounds end once two in a row each shorten the path by "
                       "less than this share (0: every round runs) (default " +
                           formatNumber(defaults.minGain) + ")"};
  const ParamSpec effort{
      "optimize-effort",
      Type::Real,
      0,
      1e6,
      kEffort,
      "With --optimize, for a sampler's path: its rounds of shortcuts make at most this many "
      "times the robot tests and distances the planning made (at least " +
          std::to_string(kLeastRoundsWork) +
          "), so that a path found at once is not polished for much longer than it took to "
          "find; 0: no such bound. MMS's paths, whose exact constructions these do not count, "
          "are not bounded by it (default " +
          formatNumber(kEffort) + ")"};
  return {rounds, gain, effort};
}

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
  const ParamSpec restarts{
      "restarts",
      Type::Integer,
      0,
      1000,
      0,
      "With --optimize: plan N more times from seeds drawn from --seed, optimise each path and "
      "keep the best by --objective (anytime improvement within the time limit; the optimiser "
      "alone keeps the first path's way round the obstacles) (default 0)"};
  const ParamSpec concurrent{
      "concurrent",
      Type::Integer,
      0,
      1,
      1,
      "Two robots or more: 1 moves them at once where they can, each move of the path started "
      "as soon as the moves whose swept regions it may meet are done and the result certified "
      "again (every robot's own motion as planned, the makespan shorter); 0: the path's moves "
      "in its order (default 1)"};
  const RoundsParams bounds = roundsParams();
  info.params.push_back(concurrent);
  info.params.push_back(optimize);
  info.params.push_back(objective);
  info.params.push_back(restarts);
  info.params.push_back(bounds.rounds);
  info.params.push_back(bounds.gain);
  info.params.push_back(bounds.effort);
  info.make = [make = info.make, optimize, objective, restarts, bounds, concurrent,
               specs = info.params](const Scene& scene, const PlannerParams& params,
                                    const std::string& source) {
    OptimizeSettings s;
    s.objective =
        paramValue(params, objective) == 1 ? PathObjective::Clearance : PathObjective::Length;
    // The certifier's budget grows with the rounds asked for, as each round may spend its share.
    s.maxWork = s.maxWork * size_t(paramValue(params, bounds.rounds)) / s.rounds;
    s.rounds = size_t(paramValue(params, bounds.rounds));
    s.minGain = paramValue(params, bounds.gain);
    Factory factory = [make, params, source](const Scene& sc, uint64_t seed) {
      PlannerParams p = params;
      p.seed = seed;
      return make(sc, p, source);
    };
    return std::make_unique<Optimizing>(
        std::move(factory), scene, params.seed, s,
        std::map<std::string, double>{{"optimize", paramValue(params, optimize)},
                                      {"concurrent", paramValue(params, concurrent)},
                                      {"objective", paramValue(params, objective)},
                                      {"restarts", paramValue(params, restarts)},
                                      {bounds.rounds.key(), paramValue(params, bounds.rounds)},
                                      {bounds.gain.key(), paramValue(params, bounds.gain)},
                                      {bounds.effort.key(), paramValue(params, bounds.effort)}},
        specs);
  };
  return info;
}

}  // namespace mms
