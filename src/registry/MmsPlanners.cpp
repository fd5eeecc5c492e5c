// "mms" behind the planner seam: OneRobotPlanner for one robot, TwoRobotPlanner for two,
// KRobotPlanner for three and more, chosen by the scene. Parameters are declared here once, with
// the defaults of the settings structs.
#include <algorithm>
#include <memory>
#include <type_traits>

#include "graph/RoadmapRecord.h"
#include "mms/Errors.h"
#include "planner/KRobotPlanner.h"
#include "planner/OneRobotPlanner.h"
#include "planner/OrderedPlanner.h"
#include "planner/Rounds.h"
#include "planner/TwoRobotPlanner.h"
#include "registry/Adapters.h"
#include "util/Parallel.h"

namespace mms {

namespace {

using Type = ParamSpec::Type;

// What both MMS planners report alike: the sizes, the manifolds' cells and arcs (`m`), and the
// phases from connect on. `building` are the phases before those (how manifolds are built).
template <class Stats>
PlanStatistics commonStatistics(const Stats& s, const SubspaceStats& m,
                                std::vector<std::pair<std::string, double>> building) {
  PlanStatistics p;
  p.seconds = s.totalSeconds;
  p.rounds = s.rounds;
  p.roundShare = s.roundShare;
  p.graphNodes = s.graphNodes;
  p.graphEdges = s.graphEdges;
  p.manifoldsBuilt = m.slices + m.lines;
  p.manifoldsUsed = s.pathManifolds;
  p.pathCells = s.pathCells;
  p.rejectedPaths = s.rejectedPaths;
  p.noPath = s.noPath;
  p.counts = {{"slices", m.slices},
              {"slice_cells", m.sliceCells},
              {"lines", m.lines},
              {"line_arcs", m.lineArcs}};
  p.phases = std::move(building);
  for (const auto& phase : {std::pair<const char*, double>{"connect", m.connectSeconds},
                            {"search", s.searchSeconds},
                            {"motion", s.motionSeconds},
                            {"certify", s.certifySeconds}})
    p.phases.emplace_back(phase);
  return p;
}

// `phase` placed right after the phase named `before`.
void insertAfter(std::vector<std::pair<std::string, double>>& phases, const std::string& before,
                 std::pair<std::string, double> phase) {
  const auto at =
      std::find_if(phases.begin(), phases.end(), [&](const auto& p) { return p.first == before; });
  phases.insert(at == phases.end() ? at : at + 1, std::move(phase));
}

PlanStatistics statisticsOf(const OneRobotStats& s) {
  const SubspaceStats& m = s.manifolds;
  PlanStatistics p = commonStatistics(s, m, {{"slices", m.sliceSeconds}, {"lines", m.lineSeconds}});
  if (s.pivotLines > 0) p.counts.emplace_back("pivot_lines", s.pivotLines);
  return p;
}

PlanStatistics statisticsOf(const TwoRobotStats& s) {
  const SubspaceStats &one = s.manifolds, &pair = s.compound;
  SubspaceStats all = one;  // counts over both kinds of subspace
  all.slices += pair.slices;
  all.lines += pair.lines;
  all.sliceCells += pair.sliceCells;
  all.lineArcs += pair.lineArcs;
  all.connectSeconds += pair.connectSeconds;
  PlanStatistics p = commonStatistics(s, all,
                                      {{"base_slices", s.baseSliceSeconds},
                                       {"overlays", one.sliceSeconds},
                                       {"lines", one.lineSeconds},
                                       {"compound_slices", pair.sliceSeconds},
                                       {"compound_lines", pair.lineSeconds}});
  p.counts.insert(p.counts.begin(), {{"subspaces", s.subspaces},
                                     {"fixings_0", s.fixings[0]},
                                     {"fixings_1", s.fixings[1]},
                                     {"expanded_fixings", s.expandedFixings},
                                     {"screened_poses", s.screenedPoses},
                                     {"narrow_arc_slices", one.localSlices},
                                     {"compound_slices", pair.slices},
                                     {"compound_lines", pair.lines},
                                     {"cross_edges", s.crossEdges},
                                     {"path_subspaces", s.pathSubspaces}});
  insertAfter(p.phases, "connect", {"cross", s.crossSeconds});
  return p;
}

PlanStatistics statisticsOf(const KRobotStats& s) {
  const SubspaceStats& m = s.manifolds;
  PlanStatistics p = commonStatistics(s, m,
                                      {{"base_slices", s.baseSliceSeconds},
                                       {"overlays", m.sliceSeconds},
                                       {"lines", m.lineSeconds}});
  p.counts.insert(p.counts.begin(), {{"subspaces", s.subspaces},
                                     {"tuples", s.tuples},
                                     {"greedy_moves", s.greedyMoves},
                                     {"screened_poses", s.screenedPoses},
                                     {"narrow_arc_slices", m.localSlices},
                                     {"cross_edges", s.crossEdges},
                                     {"path_subspaces", s.pathSubspaces}});
  insertAfter(p.phases, "connect", {"cross", s.crossSeconds});
  return p;
}

PlanStatistics statisticsOf(const OrderedStats& s) {
  PlanStatistics p;
  p.seconds = s.totalSeconds;
  p.rounds = s.passes;
  p.manifoldsBuilt = s.baseSlices + s.regionSlices;
  p.noPath = s.noPath;
  p.counts = {{"passes", s.passes},
              {"moves", s.moves},
              {"straight_moves", s.straightMoves},
              {"route_moves", s.routeMoves},
              {"region_moves", s.regionMoves},
              {"turn_moves", s.turnMoves},
              {"base_slices", s.baseSlices},
              {"region_slices", s.regionSlices},
              {"pebble_vertices", s.pebbles.vertices},
              {"pebble_edges", s.pebbles.edges},
              {"pebble_states", s.pebbles.states},
              {"pebble_moves", s.pebbles.moves},
              {"joint_robots", s.jointRobots}};
  p.phases = {{"base_slices", s.baseSliceSeconds}, {"routes", s.routeSeconds},
              {"regions", s.regionSeconds},        {"turns", s.turnSeconds},
              {"pebbles", s.pebbleSeconds},        {"joint", s.jointSeconds},
              {"certify", s.certifySeconds}};
  return p;
}

// An MMS result (OneRobotResult, TwoRobotResult, KRobotResult) as the seam's result.
template <class Result>
PlanResult planResultOf(const Result& r, const std::map<std::string, double>& parameters) {
  PlanResult out;
  out.status = r.status;
  out.waypoints = r.waypoints;
  out.certificate = r.certificate;
  out.stats = statisticsOf(r.stats);
  out.parameters = parameters;
  return out;
}

// A record of an MMS run (PlannerParams::record): its roadmap, stamped as it was built.
std::shared_ptr<const PlanRecord> recordOf(const Roadmap* roadmap, size_t robots, double seconds) {
  const Stopwatch recording;
  auto record = std::make_shared<PlanRecord>();
  record->planner = "mms";
  record->robots = robots;
  if (roadmap) appendRoadmap(*roadmap, RecordBudget{}, *record);
  record->seconds = seconds;
  record->recordSeconds = recording.seconds();
  return record;
}

// The roadmap a planner records: the one-robot and held-robot planners have one.
template <class P>
const Roadmap* roadmapOf(const P& planner) {
  if constexpr (std::is_base_of_v<HeldRobotPlanner, P>)
    return &static_cast<const HeldRobotPlanner&>(planner).roadmap();
  else
    return nullptr;
}

// The seam's progress callback as an MMS planner's.
template <class Stats>
std::function<void(const Stats&)> progressOf(const Planner::Progress& progress) {
  if (!progress) return {};
  return [&progress](const Stats& s) { progress(statisticsOf(s)); };
}

// The declared parameters, in the order --help shows them.
enum Param { kThreads, kNTheta, kNLines, kNFixings, kExpandShare, kCoupled };

std::vector<ParamSpec> mmsParams() {
  const OneRobotSettings one;
  const TwoRobotSettings two;
  const KRobotSettings many;
  // The defaults for one robot, two, and three or more, said once where they agree.
  auto each = [](double a, double b, double c) {
    if (a == b && b == c) return formatNumber(a);
    if (b == c) return formatNumber(a) + " for one robot, " + formatNumber(b) + " for two or more";
    return formatNumber(a) + " for one robot, " + formatNumber(b) + " for two, " + formatNumber(c) +
           " for three or more";
  };
  return {
      {"threads", Type::Integer, 0, 256, double(one.threads),
       "Threads that build slices (0: all cores); same seed, same path whatever the number "
       "(default " +
           formatNumber(one.threads) + ")"},
      {"n-theta", Type::Integer, 1, 1e6, double(one.nTheta),
       "Angles sampled per robot (n_theta). One robot: slices in the first round, doubling each "
       "round. Two robots or more: each robot's angle set besides its start and goal angles, "
       "doubling each round (default " +
           each(double(one.nTheta), double(two.nTheta), double(many.nTheta)) + ")"},
      {"n-lines", Type::Integer, 1, 1e7, double(one.nLines),
       "Lines (fixed positions, n_l). One robot: in the first round, doubling each round. Two "
       "robots or more: per subspace (two robots: the subspaces holding a robot at its start or "
       "goal double theirs each round) (default " +
           each(double(one.nLines), double(two.nLines), double(many.nLines)) + ")"},
      {"n-fixings", Type::Integer, 1, 1e6, double(two.nFixings),
       "Two robots only: fixings per robot in the first round (n_f), doubling each round once "
       "each robot has " +
           formatNumber(double(kAnglesBeforeFixingsGrow)) + " angles (default " +
           formatNumber(double(two.nFixings)) + ")"},
      {"expand-share", Type::Real, 0, 1, two.expandShare,
       "Two robots only: share of fixings drawn from free-space cells already reached from the "
       "start or goal; the rest are uniform (default " +
           formatNumber(two.expandShare) + ")"},
      {"coupled", Type::Integer, 0, 1, two.coupled ? 1.0 : 0.0,
       "Two robots only: 1 builds compound slices and lines in which the pair keeps its start "
       "relative pose and moves as one rigid body (carry and turn together), when start and goal "
       "share it; 0 does not (default " +
           formatNumber(two.coupled ? 1.0 : 0.0) + ")"},
  };
}

unsigned threadsOf(double v) { return v == 0 ? hardwareThreads() : unsigned(v); }

class OneRobotMms : public Planner {
 public:
  OneRobotMms(const Scene& scene, const OneRobotSettings& settings, bool picture,
              std::map<std::string, double> parameters)
      : planner_(scene, 0, settings),
        start_(scene.robots[0].start),
        goal_(scene.robots[0].goal),
        picture_(picture),
        record_(settings.record),
        parameters_(std::move(parameters)) {}

  // The roadmap lives on from query to query; its statistics count its whole life. Each query
  // reports the time it took, its phases adding up to it, beside what the roadmap holds.
  PlanResult solve(const Termination& stop, const Progress& progress) override {
    const PlanStatistics before = spent_;
    Progress perQuery;
    if (progress) perQuery = [&](const PlanStatistics& s) { progress(since(s, before)); };
    const OneRobotResult r =
        planner_.solve(start_, goal_, stop, progressOf<OneRobotStats>(perQuery));
    PlanResult out = planResultOf(r, parameters_);
    spent_ = out.stats;
    out.stats = since(out.stats, before);
    if (record_) out.record = recordOf(&planner_.roadmap(), 1, out.stats.seconds);
    if (picture_ && out.found()) {
      for (const ConnectivityGraph::Node& n : r.cells)
        if (const auto* s =
                dynamic_cast<const SliceManifold*>(&planner_.roadmap().manifold(n.manifold)))
          out.roadmap.cells.push_back(s->slice().cell(n.cell));
      for (const Line& l : planner_.lines()) out.roadmap.points.push_back(l.point());
    }
    return out;
  }

  bool setQuery(const Config& start, const Config& goal) override {
    start_ = poseOf(start, 0);
    goal_ = poseOf(goal, 0);
    return true;
  }

 private:
  // `now` less what `before` had spent: seconds and each phase.
  static PlanStatistics since(PlanStatistics now, const PlanStatistics& before) {
    now.seconds -= before.seconds;
    for (auto& [name, t] : now.phases)
      for (const auto& [was, spent] : before.phases)
        if (was == name) t -= spent;
    return now;
  }

  OneRobotPlanner planner_;
  Pose start_, goal_;
  bool picture_, record_;
  std::map<std::string, double> parameters_;
  PlanStatistics spent_;  // by the queries before
};

// A two- or k-robot MMS planner behind the seam (one query: its start and goal are the scene's).
// Each solve() after the first starts from a fresh planner: these planners build their base
// slices and start and goal subspaces once per query, and a run that a limit cut short there
// (or the portfolio's race, which ends MMS wherever it is) leaves them part built, so that
// resuming found no start or goal and reported "not found" at once. Same seed, same result,
// however often solve() is called.
template <class P, class Settings, class Stats>
class ManyRobotMms : public Planner {
 public:
  ManyRobotMms(const Scene& scene, const Settings& settings,
               std::map<std::string, double> parameters, bool record)
      : scene_(scene),
        settings_(settings),
        planner_(std::make_unique<P>(scene, settings)),
        record_(record),
        parameters_(std::move(parameters)) {}

  PlanResult solve(const Termination& stop, const Progress& progress) override {
    if (solved_) {
      planner_.reset();  // not two roadmaps at once
      planner_ = std::make_unique<P>(scene_, settings_);
    }
    solved_ = true;
    PlanResult out = planResultOf(planner_->solve(stop, progressOf<Stats>(progress)), parameters_);
    if (record_)
      out.record = recordOf(roadmapOf(*planner_), scene_.robots.size(), out.stats.seconds);
    return out;
  }

 private:
  Scene scene_;
  Settings settings_;
  std::unique_ptr<P> planner_;
  bool solved_ = false, record_;
  std::map<std::string, double> parameters_;
};
using TwoRobotMms = ManyRobotMms<TwoRobotPlanner, TwoRobotSettings, TwoRobotStats>;
using KRobotMms = ManyRobotMms<KRobotPlanner, KRobotSettings, KRobotStats>;
using OrderedMms = ManyRobotMms<OrderedPlanner, OrderedSettings, OrderedStats>;

// The settings the MMS planners share, from the parameters given (the rest keep the struct's
// defaults).
template <class Settings>
Settings settingsFrom(const PlannerParams& params, const std::vector<ParamSpec>& specs) {
  Settings s;
  auto given = [&](Param p) { return params.values.count(specs[p].name) > 0; };
  s.seed = params.seed;
  s.record = params.record;
  s.threads = threadsOf(paramValue(params, specs[kThreads]));
  if (given(kNTheta)) s.nTheta = size_t(paramValue(params, specs[kNTheta]));
  if (given(kNLines)) s.nLines = size_t(paramValue(params, specs[kNLines]));
  if constexpr (std::is_same_v<Settings, TwoRobotSettings>) {
    if (given(kNFixings)) s.nFixings = size_t(paramValue(params, specs[kNFixings]));
    if (given(kExpandShare)) s.expandShare = paramValue(params, specs[kExpandShare]);
    if (given(kCoupled)) s.coupled = paramValue(params, specs[kCoupled]) != 0;
  }
  return s;
}

std::unique_ptr<Planner> makeOrdered(const Scene& scene, const PlannerParams& params,
                                     const std::string& source) {
  if (scene.robots.empty()) throw InputError(source + ": robots: none; the mms planner needs one");
  const std::vector<ParamSpec> specs = mmsParams();
  OrderedSettings s;
  s.seed = params.seed;
  s.threads = threadsOf(paramValue(params, specs[kThreads]));
  return std::make_unique<OrderedMms>(scene, s, std::map<std::string, double>{}, params.record);
}

// Recursive MMS: one robot, two, or k robots all but one held (the paper's planners).
std::unique_ptr<Planner> makeJoint(const Scene& scene, const PlannerParams& params,
                                   const std::string& source) {
  const std::vector<ParamSpec> specs = mmsParams();
  if (scene.robots.size() == 1) {
    const auto s = settingsFrom<OneRobotSettings>(params, specs);
    return std::make_unique<OneRobotMms>(
        scene, s, params.roadmapPicture,
        std::map<std::string, double>{{"n_theta", double(s.nTheta)},
                                      {"n_lines", double(s.nLines)}});
  }
  if (scene.robots.size() == 2) {
    const auto s = settingsFrom<TwoRobotSettings>(params, specs);
    return std::make_unique<TwoRobotMms>(
        scene, s,
        std::map<std::string, double>{{"n_theta", double(s.nTheta)},
                                      {"n_lines", double(s.nLines)},
                                      {"n_fixings", double(s.nFixings)},
                                      {"expand_share", s.expandShare},
                                      {"coupled", s.coupled ? 1.0 : 0.0}},
        params.record);
  }
  if (scene.robots.empty()) throw InputError(source + ": robots: none; the mms planner needs one");
  const auto s = settingsFrom<KRobotSettings>(params, specs);
  return std::make_unique<KRobotMms>(
      scene, s,
      std::map<std::string, double>{{"n_theta", double(s.nTheta)}, {"n_lines", double(s.nLines)}},
      params.record);
}

std::unique_ptr<Planner> makeMms(const Scene& scene, const PlannerParams& params,
                                 const std::string& source) {
  if (scene.robots.size() >= kOrderedFrom) return makeOrdered(scene, params, source);
  return makeJoint(scene, params, source);
}

}  // namespace

bool mmsTakes(const Scene& scene) { return !scene.robots.empty(); }

PlannerInfo mmsPlannerInfo() {
  PlannerInfo info;
  info.name = "mms";
  info.summary =
      "Motion planning via manifold samples: exact fixed-angle slices and fixed-position lines "
      "(one robot), recursive MMS over fixings (two robots), over tuples grown from reached "
      "cells (three or more)";
  info.params = mmsParams();
  info.multiQuery = true;
  info.make = makeMms;
  return info;
}

PlannerInfo orderedPlannerInfo() {
  PlannerInfo info;
  info.name = "mms-ordered";
  info.summary =
      "MMS for many robots: one at a time, in an order, each through its exact slice among the "
      "obstacles and the robots standing near its way; robots that block each other to the "
      "k-robot MMS (mms chooses it from " +
      std::to_string(kOrderedFrom) + " robots)";
  info.params = {mmsParams()[kThreads]};
  info.make = makeOrdered;
  return info;
}

PlannerInfo jointPlannerInfo() {
  PlannerInfo info = mmsPlannerInfo();
  info.name = "mms-joint";
  info.summary =
      "Recursive MMS over all robots at once whatever their number (mms chooses it below " +
      std::to_string(kOrderedFrom) + " robots)";
  info.multiQuery = false;
  info.make = makeJoint;
  return info;
}

}  // namespace mms
