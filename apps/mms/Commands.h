#pragma once
// One function per CLI command. Each returns the process exit code: 0 success, 1 the
// answer is "no" (path rejected, no path found), 2 bad input (InputError propagates).
#include <string>
#include <vector>

#include "bench/Runner.h"
#include "mms/Certificate.h"
#include "mms/Planner.h"
#include "mms/Scene.h"
#include "scenarios/Catalog.h"

namespace mms::cli {

/// "  fleet: makespan 12.3 (1.4x its bound 8.8), sum of distances ..." for a certified path of
/// two robots or more (PathCheckResult's fleet measures), "" otherwise.
std::string fleetLine(const Scene& scene, const PathCheckResult& c);

/// A scene in any format mms reads (mms JSON, OMPL.app .cfg, discopygal JSON); what a
/// conversion changed goes to stderr as "mms: note: ..." unless quiet.
Scene readScene(const std::string& file, bool quiet = false);

struct ValidateArgs {
  std::string scene;
  bool quiet = false;
};
int validate(const ValidateArgs& a);

struct CheckArgs {
  std::string scene, path;
  size_t maxEvaluations = 20'000'000;
};
int check(const CheckArgs& a);

struct ViewArgs {
  std::string scene, path, output;
  std::string record;  // mms-record/1: the planning's growth beside the path
};
int view(const ViewArgs& a);

struct RenderArgs {
  std::string scene, path, output;
  double width = 800;
  int ghosts = 24;
  bool noAnimation = false;
};
int render(const RenderArgs& a);

}  // namespace mms::cli

namespace mms::cli {

/// What plan and assemble share: a scene in, files out, under a seed and limits.
struct RunArgs {
  std::string scene, output, svg;
  uint64_t seed = 1;
  double timeLimit = 60;
  double memoryMb = 0;  // 0: no limit
  bool quiet = false;
};

struct PlanArgs : RunArgs {
  bool svgRoadmap = false;   // draw line points and the path's slice cells
  bool saveRoadmap = false;  // keep them in the path file (for mms view)
  std::string queries;       // mms-queries/1 file: several queries on one roadmap
  std::string record;        // mms-record/1 file: what the planner built and when
  std::string planner = mms::kDefaultPlanner;
  std::string statsJson;  // write a machine-readable summary of the run here
  PlannerParams params;   // the planner's declared parameters the user gave
};
int plan(const PlanArgs& a);

/// Time since the process started (the time limits hold for the whole command).
const Stopwatch& processClock();

}  // namespace mms::cli

namespace mms::cli {

struct ScenarioArgs : ScenarioRequest {
  std::string output;
};
int scenario(const ScenarioArgs& a);

}  // namespace mms::cli

namespace mms::cli {

struct BenchArgs : BenchSettings {
  bool reportOnly = false;
};
int bench(const BenchArgs& a);
int benchMerge(const std::vector<std::string>& dirs, const std::string& output);

}  // namespace mms::cli

namespace mms::cli {

struct AssembleArgs : RunArgs {
  bool noPairs = false;
};
int assemble(const AssembleArgs& a);

}  // namespace mms::cli

namespace mms::cli {

struct LabArgs {
  std::string experiment;  // completeness or passages
  std::string output;      // required: a report in the current folder would go unnoticed
  uint64_t seed = 1;
  size_t trials = 0;  // 0: the experiment's default
  unsigned threads = 0;
  bool quick = false, noPacman = false, quiet = false;
};
int lab(const LabArgs& a);

}  // namespace mms::cli

namespace mms::cli {

struct ImportArgs {
  std::string input, output;
  std::string bounds;  // "XMIN,YMIN,XMAX,YMAX", or empty
  bool quiet = false;
};
int importScene(const ImportArgs& a);

struct ExportArgs {
  std::string scene, path, to, output;
  bool quiet = false;
  bool force = false;  // a rotating robot written translating to discopygal
};
int exportScene(const ExportArgs& a);

}  // namespace mms::cli
