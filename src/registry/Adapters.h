#pragma once
// The registry's entries, one function per planner family: to add a planner, write its adapter
// (a class derived from mms::Planner) and its PlannerInfo, and list it in Registry.cpp.
#include <string>
#include <vector>

#include "mms/Planner.h"

namespace mms {

/// "mms": MMS chosen by the scene: recursive MMS (one robot, two, k) below kOrderedFrom robots,
/// the ordered planner from there.
PlannerInfo mmsPlannerInfo();
/// "mms-ordered": robots one at a time (OrderedPlanner), which "mms" is from kOrderedFrom robots.
PlannerInfo orderedPlannerInfo();
/// "mms-joint": recursive MMS (one, two or k robots), which "mms" is below kOrderedFrom robots.
PlannerInfo jointPlannerInfo();
inline constexpr size_t kOrderedFrom = 8;
/// Whether "mms" takes the scene (one robot or more).
bool mmsTakes(const Scene& scene);
/// "auto": MMS and a sampling planner on two cores: the sampler's path when it finds one within
/// its allowance (samplerAllowance), MMS's otherwise.
PlannerInfo portfolioPlannerInfo();
/// The portfolio's sampler's iterations allowed once MMS has begun `rounds` rounds after its
/// first and met `share` (0 to 1) of the last one's targets: `budget` x 2^(rounds + share).
double samplerAllowance(size_t budget, size_t rounds, double share);
/// OMPL 1.5.2's planners with mms's collision checker and continuous certification.
std::vector<PlannerInfo> omplPlannerInfos();

/// `info` with the parameters optimize and objective: its planner's first certified path is
/// then optimised (path/Optimize.h) within the time limit, when optimize is 1.
PlannerInfo withPathOptimization(PlannerInfo info, bool onByDefault);

/// Sides of the polygons MMS plans on in place of discs, by default: 32 below kOrderedFrom
/// robots, where slices are cheap, and 16 from there, as slices of many discs cost about
/// sides^1.8 (100 discs among triangles: 2.5 s at 16, 9 s at 32).
constexpr int kFewDiscSides = 32, kManyDiscSides = 16;

/// `info` with the parameter disc-sides: its planner plans on stand-ins of that many sides for
/// the scene's discs (robots and obstacles).
PlannerInfo withDiscStandIns(PlannerInfo info);

/// A parameter's value: the one given, or the default declared in `spec`.
double paramValue(const PlannerParams& params, const ParamSpec& spec);

}  // namespace mms
