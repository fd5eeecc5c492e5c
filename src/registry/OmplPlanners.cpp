// OMPL's planners behind the planner seam: each name one registry entry, with only the
// parameters that planner reads.
#include <memory>

#include "baselines/OmplPlanner.h"
#include "registry/Adapters.h"

namespace mms {

namespace {

using Type = ParamSpec::Type;

// The counts of OMPL's tree or roadmap, as every planner reports them.
PlanStatistics statistics(const OmplResult& r) {
  PlanStatistics s;
  s.seconds = r.seconds;
  s.graphNodes = r.states;
  s.graphEdges = r.edges;
  s.checks = r.checks;
  s.counts = {{"states", r.states}, {"iterations", r.iterations}, {"checks", r.checks}};
  return s;
}

class OmplAdapter : public Planner {
 public:
  OmplAdapter(const Scene& scene, OmplSettings settings, std::map<std::string, double> parameters,
              std::vector<ParamSpec> specs)
      : scene_(scene),
        settings_(std::move(settings)),
        parameters_(std::move(parameters)),
        specs_(std::move(specs)) {}

  PlanResult solve(const Termination& stop, const Progress& progress) override {
    OmplProgress onProgress;
    if (progress) onProgress = [&](const OmplResult& sofar) { progress(statistics(sofar)); };
    const OmplResult r = planWithOmpl(scene_, settings_, stop, onProgress);
    PlanResult out;
    // OMPL does not tell a cancelled run from one out of time.
    out.status =
        r.status == PlanStatus::NotFound && stop.cancelled() ? PlanStatus::Cancelled : r.status;
    out.waypoints = r.waypoints;
    out.certificate = r.certificate;
    out.stats = statistics(r);
    out.stats.phases = {{"setup", r.setupSeconds},
                        {"solve", r.solveSeconds},
                        {"certify", r.seconds - r.setupSeconds - r.solveSeconds}};
    if (settings_.simplify) out.stats.phases.emplace_back("simplify", r.simplifySeconds);
    out.parameters = parameters_;
    out.parameterSpecs = specs_;  // a flag is written as one wherever the result goes
    if (settings_.record) {
      auto record = std::make_shared<PlanRecord>();
      record->planner = settings_.planner;
      record->robots = scene_.robots.size();
      record->seconds = r.seconds;
      record->recordSeconds = r.recordSeconds;
      record->tree = r.tree;
      record->growth = r.growth;
      out.record = std::move(record);
    }
    return out;
  }

 private:
  Scene scene_;
  OmplSettings settings_;
  std::map<std::string, double> parameters_;
  std::vector<ParamSpec> specs_;
};

struct Entry {
  const char* name;
  const char* summary;
  bool range, neighbours, segment;  // which of the optional parameters it reads
};

// The parameters OMPL's planners declare, each once (a planner takes those its entry names).
struct OmplSpecs {
  ParamSpec resolution, range, share, k, segment, simplify, certified, free, lean;
};

OmplSpecs omplSpecs() {
  const OmplSettings d;
  const ParamSpec resolution{
      "resolution",
      Type::Real,
      1e-7,
      0.5,
      d.resolution,
      "OMPL planners: motion-check resolution, a fraction of the state space's extent (default " +
          formatNumber(d.resolution) + ")"};
  const ParamSpec range{"range",
                        Type::Real,
                        0,
                        1e9,
                        d.range,
                        "OMPL tree planners and LazyPRM: maximum motion length (0: OMPL's "
                        "default)"};
  const ParamSpec share{"range-share",
                        Type::Real,
                        0,
                        1,
                        d.rangeShare,
                        "OMPL tree planners and LazyPRM, where --range is 0: maximum motion "
                        "length as a share of the state space's extent (0: OMPL's 0.2)"};
  const ParamSpec k{"k",
                    Type::Integer,
                    0,
                    100000,
                    double(d.neighbours),
                    "OMPL PRM family: nearest neighbours per milestone (0: OMPL's default)"};
  const ParamSpec segment{"segment-factor",
                          Type::Real,
                          1,
                          1e6,
                          d.segmentFactor,
                          "U-OB-PRM: segment length l in units of the resolution (default " +
                              formatNumber(d.segmentFactor) + ")"};
  const ParamSpec simplify{
      "simplify", Type::Flag,         0,
      1,          double(d.simplify), "OMPL planners: run OMPL's path simplifier on the solution"};
  const ParamSpec certified{"certified-motions",
                            Type::Flag,
                            0,
                            1,
                            double(d.certifiedMotions),
                            "OMPL planners: check motions with mms's continuous certifier instead "
                            "of discrete poses at the resolution"};
  const ParamSpec free{
      "free-samples",
      Type::Flag,
      0,
      1,
      double(d.freeSamples),
      "OMPL planners: redraw each robot's uniform samples until it is clear of the "
      "obstacles (up to 100 draws), so that trees grow towards free space"};
  const ParamSpec lean{"lean-angles",
                       Type::Real,
                       0,
                       1,
                       d.leanAngles,
                       "OMPL planners: the share of samples whose angles are drawn between "
                       "each robot's start and goal angles (the short way) instead of from the "
                       "whole circle, so that paths turn less back and forth"};
  return {resolution, range, share, k, segment, simplify, certified, free, lean};
}

}  // namespace

std::vector<PlannerInfo> omplPlannerInfos() {
  const auto [resolution, range, share, k, segment, simplify, certified, free, lean] = omplSpecs();
  const Entry entries[] = {
      {"prm", "OMPL PRM (uniform samples)", false, true, false},
      {"obprm", "OMPL PRM with OMPL's obstacle-based sampler", false, true, false},
      {"uobprm", "PRM with the uniform obstacle-based sampler (U-OB-PRM)", false, true, true},
      {"prm-bridge", "OMPL PRM with the bridge-test sampler", false, true, false},
      {"prm-gaussian", "OMPL PRM with the Gaussian sampler", false, true, false},
      {"rrt", "OMPL RRT", true, false, false},
      {"rrtconnect", "OMPL RRT-Connect", true, false, false},
      {"kpiece", "OMPL KPIECE1", true, false, false},
      {"bkpiece", "OMPL BKPIECE1", true, false, false},
      {"lazyprm", "OMPL LazyPRM", true, false, false},
      {"rrtstar",
       "OMPL RRT* (asymptotically optimal: improves its path, shortest length, until the time "
       "limit)",
       true, false, false},
      {"bitstar", "OMPL BIT* (asymptotically optimal: improves its path until the time limit)",
       false, false, false},
  };
  std::vector<PlannerInfo> out;
  for (const Entry& e : entries) {
    PlannerInfo info;
    info.name = e.name;
    info.summary = e.summary;
    info.params = {resolution};
    if (e.range) {
      info.params.push_back(range);
      info.params.push_back(share);
    }
    if (e.neighbours) info.params.push_back(k);
    if (e.segment) info.params.push_back(segment);
    info.params.push_back(simplify);
    info.params.push_back(certified);
    info.params.push_back(free);
    info.params.push_back(lean);
    const std::string name = e.name;
    const std::vector<ParamSpec> specs = info.params;
    info.make = [name, specs](const Scene& scene, const PlannerParams& params,
                              const std::string&) -> std::unique_ptr<Planner> {
      OmplSettings s;
      s.planner = name;
      s.seed = params.seed;
      s.keepUntilExit = params.exitsAfterRun;
      s.record = params.record;
      std::map<std::string, double> used;
      for (const ParamSpec& spec : specs) {
        const double v = paramValue(params, spec);
        used[spec.key()] = v;
        if (spec.name == "resolution") s.resolution = v;
        if (spec.name == "range") s.range = v;
        if (spec.name == "range-share") s.rangeShare = v;
        if (spec.name == "k") s.neighbours = unsigned(v);
        if (spec.name == "segment-factor") s.segmentFactor = v;
        if (spec.name == "simplify") s.simplify = v != 0;
        if (spec.name == "certified-motions") s.certifiedMotions = v != 0;
        if (spec.name == "free-samples") s.freeSamples = v != 0;
        if (spec.name == "lean-angles") s.leanAngles = v;
      }
      return std::make_unique<OmplAdapter>(scene, s, std::move(used), specs);
    };
    out.push_back(std::move(info));
  }
  return out;
}

}  // namespace mms
