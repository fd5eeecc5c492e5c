#include "lab/PrmOnBoxes.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/ValidStateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/planners/prm/ConnectionStrategy.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/util/Console.h>

#include <chrono>
#include <stdexcept>

#include "util/Random.h"

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace mms::lab {

namespace {

const double* valuesOf(const ob::State* s) {
  return s->as<ob::RealVectorStateSpace::StateType>()->values;
}

class SeededUniformSampler : public ob::ValidStateSampler {
 public:
  SeededUniformSampler(const ob::SpaceInformation* si, const BoxSpace& space, uint64_t seed)
      : ob::ValidStateSampler(si), space_(space), random_(seed) {
    name_ = "seeded uniform";
  }
  bool sample(ob::State* state) override {
    double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    for (int i = 0; i < space_.dim(); ++i) v[i] = random_.uniform();
    return space_.isFree(v);
  }
  bool sampleNear(ob::State* state, const ob::State*, double) override { return sample(state); }

 private:
  const BoxSpace& space_;
  Random random_;
};

class ExactBoxMotionValidator : public ob::MotionValidator {
 public:
  ExactBoxMotionValidator(const ob::SpaceInformationPtr& si, const BoxSpace& space)
      : ob::MotionValidator(si), space_(space) {}
  bool checkMotion(const ob::State* a, const ob::State* b) const override {
    bool ok = space_.segmentFree(valuesOf(a), valuesOf(b));
    (ok ? valid_ : invalid_)++;
    return ok;
  }
  bool checkMotion(const ob::State* a, const ob::State* b,
                   std::pair<ob::State*, double>& lastValid) const override {
    if (checkMotion(a, b)) return true;
    // PRM never asks for the last valid state; report the start, which is always valid.
    if (lastValid.first) si_->copyState(lastValid.first, a);
    lastValid.second = 0;
    return false;
  }

 private:
  const BoxSpace& space_;
};

// PRM needs no projection; OMPL's default random projection for d > 2 is left out (its
// Eigen matrix is freed with a mismatched allocator under AddressSanitizer).
class UnprojectedSpace : public ob::RealVectorStateSpace {
 public:
  using ob::RealVectorStateSpace::RealVectorStateSpace;
  void registerProjections() override {}
};

// PRM's milestone insertion and component test are protected; the lab drives them directly.
class SteppedPrm : public og::PRM {
 public:
  using og::PRM::addMilestone;
  using og::PRM::PRM;
  using og::PRM::sameComponent;
};

}  // namespace

PrmResult solvePrmOnBoxes(const BoxSpace& space, const Point& start, const Point& goal,
                          const PrmSettings& settings) {
  if (!space.isFree(start) || !space.isFree(goal))
    throw std::invalid_argument("start or goal is not free");
  auto t0 = std::chrono::steady_clock::now();
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  auto stateSpace = std::make_shared<UnprojectedSpace>(space.dim());
  stateSpace->setBounds(0.0, 1.0);
  auto si = std::make_shared<ob::SpaceInformation>(stateSpace);
  si->setStateValidityChecker([&space](const ob::State* s) { return space.isFree(valuesOf(s)); });
  si->setMotionValidator(std::make_shared<ExactBoxMotionValidator>(si, space));
  si->setValidStateSamplerAllocator([&space, &settings](const ob::SpaceInformation* s) {
    return std::make_shared<SeededUniformSampler>(s, space, settings.seed);
  });
  si->setup();

  // PRM weighs edges with the problem's optimization objective: it needs a problem.
  ob::ScopedState<> from(stateSpace), to(stateSpace);
  for (int i = 0; i < space.dim(); ++i) from[i] = start[i], to[i] = goal[i];
  auto problem = std::make_shared<ob::ProblemDefinition>(si);
  problem->setStartAndGoalStates(from, to);
  SteppedPrm prm(si);
  prm.setProblemDefinition(problem);
  prm.setMaxNearestNeighbors(settings.neighbours);
  prm.setup();
  auto milestone = [&](const Point& p) {
    ob::State* s = si->allocState();
    double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
    std::copy(p.begin(), p.end(), v);
    return prm.addMilestone(s);  // the roadmap owns s
  };
  auto s = milestone(start), g = milestone(goal);
  const size_t cap = settings.maxMilestones + 2;
  ob::PlannerTerminationCondition done(
      [&] { return prm.sameComponent(s, g) || prm.milestoneCount() >= cap; });
  if (!done()) prm.growRoadmap(done);

  PrmResult result;
  if (prm.sameComponent(s, g)) result.milestones = prm.milestoneCount() - 2;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace mms::lab
