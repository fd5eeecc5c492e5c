#pragma once
// The planner seam. Every planner — MMS for one or two robots, each of OMPL's samplers, the
// ones to come — is made by name from one registry and answers one call, solve(stop, progress)
// -> PlanResult, as OMPL's Planner::solve(PlannerTerminationCondition) does. Its parameters are
// declared once (ParamSpec): the command line's options, `mms plan --help`, `mms bench --param`,
// the statistics file and docs/architecture.md's recipe all read that one list.
//
// Only the standard library and mms's public headers are included here: exact arithmetic,
// graphs and OMPL stay behind this seam.
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mms/Certificate.h"
#include "mms/Record.h"
#include "mms/Scene.h"
#include "mms/Termination.h"

namespace mms {

/// One tunable parameter of a planner.
struct ParamSpec {
  enum class Type { Integer, Real, Flag };
  std::string name;  // as on the command line without "--", e.g. "n-theta"
  Type type = Type::Real;
  double min = 0, max = 0;  // accepted values, inclusive (a flag: 0 or 1)
  double value = 0;         // the default, read from the planner's settings struct
  std::string help;         // one sentence; the default is appended where shown
  /// Named values (an Integer parameter's value is the index): "length", "clearance".
  std::vector<std::string> choices{};

  /// The name in statistics and path files: "n-theta" -> "n_theta".
  std::string key() const;
  /// "" when `v` is acceptable, else why not (one phrase: "not in [1, 1000000]").
  std::string problem(double v) const;
  /// The value of `text` (a number, or one of the choices) in `v`; else why not (one phrase).
  std::string parse(const std::string& text, double& v) const;
};

/// "%g" of a parameter's value, for help texts and messages.
std::string formatNumber(double v);

/// What a caller asks of a planner beyond the scene: the parameters it gives (by name; those
/// not given keep their defaults) and how the run is used.
struct PlannerParams {
  uint64_t seed = 1;
  std::map<std::string, double> values;
  bool roadmapPicture = false;  // fill PlanResult::roadmap where the planner can
  /// The process exits right after the run: a planner may leave its memory for the OS to take
  /// back (freeing a million OMPL states would overrun the time limit by seconds).
  bool exitsAfterRun = false;
  bool record = false;  // fill PlanResult::record (every planner)
};

/// Where a run's time went and what it built: one struct for every planner. The command line
/// writes it to --stats-json and path files, `mms bench` reads it back.
struct PlanStatistics {
  double seconds = 0;  // planning time, as the planner measures it
  size_t rounds = 0;
  /// MMS: the share (0 to 1) of its last round's growth targets met when it ended; the
  /// default planner's allowance reads it (docs/planner.md, "The default: a portfolio").
  double roundShare = 0;
  size_t graphNodes = 0, graphEdges = 0;         // roadmap or tree (OMPL: its states)
  size_t manifoldsBuilt = 0, manifoldsUsed = 0;  // MMS: slices and lines, built / on the path
  size_t pathCells = 0;                          // free-space cells on the graph path
  size_t rejectedPaths = 0;                      // candidate motions the certifier refused
  /// Robot tests and distances made while solving, where the planner counts them (OMPL's
  /// planners; 0 otherwise): the work the optimiser's shortcut rounds are measured against.
  size_t checks = 0;
  std::vector<std::pair<std::string, size_t>> counts;  // what was built, by name, in order
  /// Seconds by phase, in order. They sum to `seconds`, but for the phases that improve a
  /// path already found (afterFirstPath: "optimize", OMPL's "simplify"), which come after it.
  std::vector<std::pair<std::string, double>> phases;
  std::string solvedBy;  // a portfolio's member whose path this is ("" otherwise)
  /// Why no path exists, when the planner proved it ("" otherwise): a robot that cannot reach
  /// its goal even alone among the obstacles (docs/planner.md, "no path exists").
  std::string noPath;
};

/// Whether a phase improves a path already found (not part of PlanStatistics::seconds).
bool afterFirstPath(const std::string& phase);

enum class PlanStatus { Found, NotFound, Uncertified, Cancelled };
/// "found", "not_found", "uncertified", "cancelled".
const char* toString(PlanStatus status);

/// Drawing aids for a found path (one-robot MMS): the free-space cells it crosses and the
/// points of the lines built.
struct RoadmapPicture {
  std::vector<std::vector<Ring>> cells;
  std::vector<Vec2> points;
};

struct PlanResult {
  PlanStatus status = PlanStatus::NotFound;
  std::vector<Config> waypoints;  // every robot's (x, y, theta); certified when Found
  PathCheckResult certificate;    // of the waypoints; why they were refused when Uncertified
  PlanStatistics stats;
  /// Every declared parameter's value in force (defaults included), by ParamSpec::key().
  std::map<std::string, double> parameters;
  /// The planner's declarations of them: how each reads in files and in Python (a whole
  /// number, a flag, a named choice such as objective "length").
  std::vector<ParamSpec> parameterSpecs;
  RoadmapPicture roadmap;  // when asked for and the planner has one
  /// What was built and when (PlannerParams::record); shared, not copied, as results pass
  /// through the optimiser and the portfolio.
  std::shared_ptr<const PlanRecord> record;
  bool found() const { return status == PlanStatus::Found; }
};

class Planner {
 public:
  using Progress = std::function<void(const PlanStatistics&)>;
  virtual ~Planner() = default;

  /// Plans until a certified path is found or `stop` holds; `progress`, when set, is called
  /// between steps (MMS: after each round). A path is reported Found only once the continuous
  /// path checker has certified it.
  virtual PlanResult solve(const Termination& stop, const Progress& progress = {}) = 0;

  /// Returns once what the last solve() left running has stopped: the portfolio ("auto")
  /// returns its sampler's path at once and leaves MMS to stop at its next check (an exact
  /// step: 0.1-2 ms) on the other core. The next solve(), setQuery() and the destructor wait
  /// for it too; a program that exits without destroying its planner calls this first.
  virtual void finishBackgroundWork() {}

  /// A new start and goal for every robot, keeping what was built (multi-query planners);
  /// false when the planner answers one query only.
  virtual bool setQuery(const Config& start, const Config& goal) {
    (void)start;
    (void)goal;
    return false;
  }
};

/// What the registry knows of a planner.
struct PlannerInfo {
  std::string name;
  std::string summary;            // one line, for --help and the docs
  std::vector<ParamSpec> params;  // every parameter it takes
  bool multiQuery = false;        // setQuery keeps the roadmap (for some scenes)
  /// Makes the planner for `scene`; throws InputError "SOURCE: robots: ..." when it cannot
  /// take the scene, or "SOURCE: (--NAME): ..." for a parameter out of range.
  std::function<std::unique_ptr<Planner>(const Scene& scene, const PlannerParams& params,
                                         const std::string& source)>
      make;
};

/// The planner `mms plan` and programs that do not choose one use.
inline constexpr const char* kDefaultPlanner = "auto";

/// The registry: "auto" (the default) first, then "mms", then OMPL's planners.
const std::vector<PlannerInfo>& planners();
/// nullptr when no planner has that name.
const PlannerInfo* findPlanner(const std::string& name);
/// The planner `name` for `scene`; throws InputError for an unknown name, a parameter it does
/// not declare or out of range, or a scene it cannot take. `source` names the scene in
/// messages (its file name).
std::unique_ptr<Planner> makePlanner(const std::string& name, const Scene& scene,
                                     const PlannerParams& params = {},
                                     const std::string& source = "scene");

}  // namespace mms
