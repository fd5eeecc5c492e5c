#include "baselines/OmplPlanner.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/samplers/BridgeTestValidStateSampler.h>
#include <ompl/base/samplers/GaussianValidStateSampler.h>
#include <ompl/base/samplers/ObstacleBasedValidStateSampler.h>
#include <ompl/base/samplers/informed/RejectionInfSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <atomic>
#include <boost/functional/hash.hpp>
#include <cmath>
#include <mutex>
#include <unordered_map>

#include "baselines/UobprmSampler.h"
#include "graph/RoadmapRecord.h"
#include "util/Random.h"

namespace mms {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

// Every angle that reaches OMPL goes through here: OMPL's SO(2) is [-pi, pi) and asserts
// on anything else (its distance, its interpolation), while std::remainder gives [-pi, pi]
// and a scene's angles may be any number (a robot at 7.5 rad, or at pi from start to goal).
double so2Angle(double theta) {
  const double a = std::remainder(theta, 2 * M_PI);
  return a >= M_PI ? -M_PI : a;
}

// State <-> configuration: robot i is component i (SE(2), or R^2 keeping its start angle).
struct Layout {
  const Scene& scene;
  Pose pose(const ob::State* s, size_t i) const {
    const auto* c = s->as<ob::CompoundState>();
    if (scene.robots[i].motion == Motion::Translate) {
      const auto* r = c->as<ob::RealVectorStateSpace::StateType>(i);
      return {r->values[0], r->values[1], scene.robots[i].start.theta};
    }
    const auto* r = c->as<ob::SE2StateSpace::StateType>(i);
    return {r->getX(), r->getY(), r->getYaw()};
  }
  /// With `from`: each angle within pi of from's, the way OMPL interpolates SO(2) (the short
  /// way), so that the straight motion from `from` to q in mms's terms is OMPL's.
  void toConfig(const ob::State* s, Config& q, const Config* from = nullptr) const {
    q.resize(scene.dof());
    for (size_t i = 0; i < scene.robots.size(); ++i) {
      const Pose p = pose(s, i);
      q[3 * i] = p.x;
      q[3 * i + 1] = p.y;
      q[3 * i + 2] = p.theta;
      if (from) {
        const double prev = (*from)[3 * i + 2];
        q[3 * i + 2] = prev + std::remainder(p.theta - prev, 2 * M_PI);
      }
    }
  }
  void fromConfig(const Config& q, ob::State* s) const {
    auto* c = s->as<ob::CompoundState>();
    for (size_t i = 0; i < scene.robots.size(); ++i) {
      if (scene.robots[i].motion == Motion::Translate) {
        auto* r = c->as<ob::RealVectorStateSpace::StateType>(i);
        r->values[0] = q[3 * i];
        r->values[1] = q[3 * i + 1];
      } else {
        auto* r = c->as<ob::SE2StateSpace::StateType>(i);
        r->setXY(q[3 * i], q[3 * i + 1]);
        r->setYaw(so2Angle(q[3 * i + 2]));
      }
    }
  }
};

class Validity : public ob::StateValidityChecker {
 public:
  Validity(const ob::SpaceInformationPtr& si, const Layout& layout, const CollisionChecker& checker)
      : ob::StateValidityChecker(si), layout_(layout), checker_(checker) {}
  bool isValid(const ob::State* s) const override {
    thread_local Config q;
    layout_.toConfig(s, q);
    return checker_.isFree(q);
  }

 private:
  const Layout& layout_;
  const CollisionChecker& checker_;
};

// Motions certified as continuous, as mms certifies paths: in open space a few clearance
// evaluations cover a motion that OMPL's discrete validator checks at hundreds of poses, and
// a tree or roadmap built of certified motions yields a path the certifier accepts.
class CertifiedMotions : public ob::MotionValidator {
 public:
  CertifiedMotions(const ob::SpaceInformationPtr& si, const Layout& layout,
                   const CollisionChecker& checker)
      : ob::MotionValidator(si), layout_(layout), checker_(checker) {}
  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    load(s1, s2);
    return counted(motionFree(checker_, a_, b_));
  }
  /// Where the motion stops being certified, for planners that keep a refused motion's start
  /// (RRT, KPIECE).
  bool checkMotion(const ob::State* s1, const ob::State* s2,
                   std::pair<ob::State*, double>& lastValid) const override {
    load(s1, s2);
    const double t = certifiedPrefix(checker_, a_, b_);
    if (t < 1) {
      if (lastValid.first) si_->getStateSpace()->interpolate(s1, s2, t, lastValid.first);
      lastValid.second = t;
    }
    return counted(t >= 1);
  }

 private:
  /// The motion's ends, angles turning the short way as OMPL interpolates SO(2).
  void load(const ob::State* s1, const ob::State* s2) const {
    layout_.toConfig(s1, a_);
    layout_.toConfig(s2, b_, &a_);
  }
  bool counted(bool ok) const {
    (ok ? valid_ : invalid_)++;
    return ok;
  }

  const Layout& layout_;
  const CollisionChecker& checker_;
  mutable Config a_, b_;  // OMPL's planners check motions on one thread
};

// For a record of the planning: when each state was first an end of a motion found free (OMPL's
// trees and roadmaps keep no times). One entry per such state, under a lock: PRM checks motions
// on two threads.
class StampedMotions : public ob::MotionValidator {
 public:
  StampedMotions(const ob::SpaceInformationPtr& si, ob::MotionValidatorPtr inner,
                 const Stopwatch& clock)
      : ob::MotionValidator(si), inner_(std::move(inner)), clock_(clock) {}
  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    return stamped(inner_->checkMotion(s1, s2), s1, s2);
  }
  bool checkMotion(const ob::State* s1, const ob::State* s2,
                   std::pair<ob::State*, double>& lastValid) const override {
    return stamped(inner_->checkMotion(s1, s2, lastValid), s1, s2);
  }
  /// When `s` was stamped, or `otherwise`.
  float at(const ob::State* s, float otherwise) const {
    const std::lock_guard lock(mutex_);
    const auto it = times_.find(key(s));
    return it == times_.end() ? otherwise : it->second;
  }

 private:
  std::vector<double> key(const ob::State* s) const {
    std::vector<double> v;
    si_->getStateSpace()->copyToReals(v, s);
    return v;
  }
  bool stamped(bool ok, const ob::State* s1, const ob::State* s2) const {
    if (!ok) return false;
    const auto now = float(clock_.seconds());
    auto k1 = key(s1), k2 = key(s2);
    const std::lock_guard lock(mutex_);
    times_.emplace(std::move(k1), now);
    times_.emplace(std::move(k2), now);
    return true;
  }

  ob::MotionValidatorPtr inner_;
  const Stopwatch& clock_;
  mutable std::mutex mutex_;
  mutable std::unordered_map<std::vector<double>, float, boost::hash<std::vector<double>>> times_;
};

// Uniform samples drawn again until free: a tree then grows only towards free space. Where
// the free space is a corridor through a large box (a bend), most uniform samples fall in the
// walls, and RRT-Connect pays a nearest-neighbour search and a refused motion for each; a
// collision test per redrawn sample costs less, and a point test first less still (most
// redrawn samples put the robot's reference point in a wall: the sampler 0.8x on the bends and
// 0.9x on the keyholes, same paths). Its draws are its own (one 64-bit number per coordinate,
// where OMPL's samplers take two 32-bit ones through std::generate_canonical) and a robot's
// angle is drawn only once its reference point is clear: the same distribution, and the
// sampler 0.8x again on the bends. Each robot is drawn again on its own until it
// is clear of the obstacles, the others ignored: redrawing the whole configuration until no two
// robots overlap made RRT-Connect 1.3x slower among discs (discs-swap, seeds 1-10). After kTries
// draws a robot keeps the last, so a scene with almost no free space is sampled as before.
// With leaning angles (OmplSettings::leanAngles), a share of the angles is drawn between the
// robot's start and goal angles: in open clutter the default portfolio's optimiser then had
// less back-and-forth turning to take out (the 90th percentile of rotation beyond the short way
// 4.4 rad -> 1.7 rad, tuning seeds) and the sampler on the bends took 0.6x the time; where the
// robots must turn to pass (doors), the sampler found fewer paths and MMS found them instead.
class FreeSampler : public ob::StateSampler {
 public:
  static constexpr int kTries = 100;
  FreeSampler(const ob::CompoundStateSpace* space, const Layout& layout,
              const CollisionChecker& checker, bool redraw, double lean)
      : ob::StateSampler(space),
        layout_(layout),
        checker_(checker),
        compound_(space->allocDefaultStateSampler()),
        tries_(redraw ? kTries : 1),
        lean_(lean),
        draws_(seedFrom(rng_)) {}
  void sampleUniform(ob::State* state) override {
    auto* c = state->as<ob::CompoundState>();
    for (size_t i = 0; i < layout_.scene.robots.size(); ++i) {
      const Robot& robot = layout_.scene.robots[i];
      const bool rigid = robot.motion != Motion::Translate;
      const Pose p = tries_ > 1 ? clearDraw(i) : uniformDraw(robot);
      if (rigid) {
        auto* se2 = c->as<ob::SE2StateSpace::StateType>(i);
        se2->setXY(p.x, p.y);
        se2->setYaw(so2Angle(p.theta));
      } else {
        auto* rv = c->as<ob::RealVectorStateSpace::StateType>(i);
        rv->values[0] = p.x;
        rv->values[1] = p.y;
      }
    }
  }
  void sampleUniformNear(ob::State* state, const ob::State* near, double distance) override {
    compound_->sampleUniformNear(state, near, distance);
  }
  void sampleGaussian(ob::State* state, const ob::State* mean, double stdDev) override {
    compound_->sampleGaussian(state, mean, stdDev);
  }

 private:
  // Robot i's pose redrawn until it is clear of the obstacles, or the last draw.
  Pose clearDraw(size_t i) {
    const Robot& robot = layout_.scene.robots[i];
    const bool rigid = robot.motion != Motion::Translate;
    Pose p{0, 0, robot.start.theta};
    bool angled = !rigid;  // a draw's angle is drawn only once its reference point is clear
    for (int k = 0; k < tries_; ++k) {
      const Vec2 at = draw();
      p.x = at.x;
      p.y = at.y;
      angled = !rigid;
      if (checker_.referenceBlocked(i, p)) continue;
      if (rigid) p.theta = angle(robot);
      angled = true;
      if (checker_.robotFree(i, p)) break;
    }
    if (!angled) p.theta = angle(robot);  // the last draw's
    return p;
  }
  Vec2 draw() { return draws_.uniformIn(layout_.scene.bounds); }
  Pose uniformDraw(const Robot& robot) {
    const Vec2 at = draw();
    return {at.x, at.y, robot.motion != Motion::Translate ? angle(robot) : 0};
  }
  double angle(const Robot& robot) {
    if (lean_ > 0 && draws_.uniform() < lean_) {
      double turn = std::remainder(robot.goal.theta - robot.start.theta, 2 * M_PI);
      // A half turn is as short either way round: each draw takes one (a U that turns half
      // round about a part may fit only one way).
      if (std::fabs(turn) > M_PI - kHalfTurnSlack && draws_.below(2) == 0) turn = -turn;
      return robot.start.theta + draws_.uniform() * turn;  // so2Angle where it is set
    }
    return draws_.uniform(-M_PI, M_PI);
  }
  static constexpr double kHalfTurnSlack = 1e-6;
  // The sampler's own stream, seeded from OMPL's (so from --seed).
  static uint64_t seedFrom(ompl::RNG& rng) {
    const auto half = [&] { return uint64_t(rng.uniformInt(0, 0x7fffffff)); };
    return half() << 32 | half();
  }
  const Layout& layout_;
  const CollisionChecker& checker_;
  ob::StateSamplerPtr compound_;  // OMPL's, for samples near a state
  int tries_;                     // 1: uniform positions, not redrawn
  double lean_;                   // OmplSettings::leanAngles
  Random draws_;
};

// KPIECE needs a projection: the robots' reference points (2-D for one robot, 4-D for two),
// with cells a twentieth of the bounds.
class PositionsProjection : public ob::ProjectionEvaluator {
 public:
  PositionsProjection(const ob::StateSpace* space, const Scene& scene)
      : ob::ProjectionEvaluator(space),
        layout_{scene},
        bounds_(scene.bounds),
        robots_(scene.robots.size()) {}
  unsigned int getDimension() const override { return unsigned(2 * robots_); }
  void defaultCellSizes() override {
    cellSizes_.clear();
    for (size_t i = 0; i < robots_; ++i) {
      cellSizes_.push_back(bounds_.width() / 20);
      cellSizes_.push_back(bounds_.height() / 20);
    }
  }
  void project(const ob::State* state, Eigen::Ref<Eigen::VectorXd> out) const override {
    thread_local Config q;
    layout_.toConfig(state, q);
    for (size_t i = 0; i < robots_; ++i) {
      out[2 * i] = q[3 * i];
      out[2 * i + 1] = q[3 * i + 1];
    }
  }

 private:
  Layout layout_;
  Box bounds_;
  size_t robots_;
};

// OMPL 1.5.2's path-length objective samples its informed set directly only in RealVector,
// SE(2) and SE(3) spaces, and BIT* always asks for it; ours is a compound of one space per
// robot, so the informed set is sampled by rejection.
class PathLength : public ob::PathLengthOptimizationObjective {
 public:
  using ob::PathLengthOptimizationObjective::PathLengthOptimizationObjective;
  ob::InformedSamplerPtr allocInformedStateSampler(const ob::ProblemDefinitionPtr& problem,
                                                   unsigned int maxCalls) const override {
    return std::make_shared<ob::RejectionInfSampler>(problem, maxCalls);
  }
};

ob::StateSpacePtr makeSpace(const Scene& scene) {
  auto space = std::make_shared<ob::CompoundStateSpace>();
  ob::RealVectorBounds b(2);
  b.setLow(0, scene.bounds.xmin);
  b.setHigh(0, scene.bounds.xmax);
  b.setLow(1, scene.bounds.ymin);
  b.setHigh(1, scene.bounds.ymax);
  for (const Robot& r : scene.robots) {
    if (r.motion == Motion::Translate) {
      auto rv = std::make_shared<ob::RealVectorStateSpace>(2);
      rv->setBounds(b);
      space->addSubspace(rv, 1.0);
    } else {
      auto se2 = std::make_shared<ob::SE2StateSpace>();
      se2->setBounds(b);
      space->addSubspace(se2, 1.0);
    }
  }
  space->registerDefaultProjection(std::make_shared<PositionsProjection>(space.get(), scene));
  return space;
}

// The size of a planner's tree or roadmap, read where the planner keeps it: OMPL's
// PlannerData copies every state (seconds for a million), these read counts. A tree has an
// edge per vertex but its roots.
struct GraphSize {
  size_t vertices = 0, edges = 0;
};
GraphSize tree(size_t vertices, size_t roots) {
  return {vertices, vertices > roots ? vertices - roots : 0};
}
struct SizedRrt : og::RRT {
  using og::RRT::RRT;
  GraphSize size() const { return tree(nn_ ? nn_->size() : 0, 1); }
};
struct SizedRrtConnect : og::RRTConnect {
  using og::RRTConnect::RRTConnect;
  GraphSize size() const {
    return tree((tStart_ ? tStart_->size() : 0) + (tGoal_ ? tGoal_->size() : 0), 2);
  }
};
struct SizedRrtStar : og::RRTstar {
  using og::RRTstar::RRTstar;
  GraphSize size() const { return tree(nn_ ? nn_->size() : 0, 1); }
};
struct SizedKpiece : og::KPIECE1 {
  using og::KPIECE1::KPIECE1;
  GraphSize size() const { return tree(disc_.getMotionCount(), 1); }
};
struct SizedBkpiece : og::BKPIECE1 {
  using og::BKPIECE1::BKPIECE1;
  GraphSize size() const { return tree(dStart_.getMotionCount() + dGoal_.getMotionCount(), 2); }
};
struct SizedLazyPrm : og::LazyPRM {
  using og::LazyPRM::LazyPRM;
  GraphSize size() const { return {boost::num_vertices(g_), boost::num_edges(g_)}; }
};

struct MadePlanner {
  ob::PlannerPtr planner;
  std::function<GraphSize()> size;
};

template <class P>
MadePlanner sized(std::shared_ptr<P> p) {
  return {p, [q = p.get()] { return q->size(); }};
}

MadePlanner makePlanner(const ob::SpaceInformationPtr& si, const OmplSettings& s, double extent) {
  const std::string& n = s.planner;
  auto prm = [&]() -> MadePlanner {
    auto p = std::make_shared<og::PRM>(si);
    if (s.neighbours) p->setMaxNearestNeighbors(s.neighbours);
    return {
        p, [q = p.get()] {
          return GraphSize{boost::num_vertices(q->getRoadmap()), boost::num_edges(q->getRoadmap())};
        }};
  };
  auto withSampler = [&](ob::ValidStateSamplerAllocator alloc) {
    si->setValidStateSamplerAllocator(std::move(alloc));
    return prm();
  };
  auto withRange = [&](auto p) {
    if (s.range > 0)
      p->setRange(s.range);
    else if (s.rangeShare > 0)
      p->setRange(s.rangeShare * extent);
    return sized(p);
  };
  if (n == "prm") return prm();
  if (n == "obprm")
    return withSampler([](const ob::SpaceInformation* i) {
      return std::make_shared<ob::ObstacleBasedValidStateSampler>(i);
    });
  if (n == "prm-bridge")
    return withSampler([](const ob::SpaceInformation* i) {
      return std::make_shared<ob::BridgeTestValidStateSampler>(i);
    });
  if (n == "prm-gaussian")
    return withSampler([](const ob::SpaceInformation* i) {
      return std::make_shared<ob::GaussianValidStateSampler>(i);
    });
  if (n == "uobprm") {
    const double length = s.segmentFactor * s.resolution * extent;
    const double step = s.resolution * extent;
    return withSampler([length, step](const ob::SpaceInformation* i) {
      return std::make_shared<UobprmSampler>(i, length, step);
    });
  }
  if (n == "rrt") return withRange(std::make_shared<SizedRrt>(si));
  if (n == "rrtconnect") return withRange(std::make_shared<SizedRrtConnect>(si));
  if (n == "kpiece") return withRange(std::make_shared<SizedKpiece>(si));
  if (n == "bkpiece") return withRange(std::make_shared<SizedBkpiece>(si));
  if (n == "lazyprm") return withRange(std::make_shared<SizedLazyPrm>(si));
  if (n == "rrtstar") return withRange(std::make_shared<SizedRrtStar>(si));
  if (n == "bitstar") {
    // BIT* keeps its tree's size as a progress property only.
    auto p = std::make_shared<og::BITstar>(si);
    return {p, [q = p.get()] {
              const auto& props = q->getPlannerProgressProperties();
              const auto it = props.find("current graph vertices INTEGER");
              return tree(it == props.end() ? 0 : std::stoul(it->second()), 1);
            }};
  }
  throw std::invalid_argument("unknown planner '" + n + "'");
}

// Progress about once a second, from whichever of the planner's threads checks its
// termination condition first (PRM grows its roadmap on a second one).
class ProgressReporter {
 public:
  ProgressReporter(const OmplProgress& progress, const MadePlanner& made, const Stopwatch& clock)
      : progress(progress), made(made), clock(clock) {}
  void operator()() const {
    if (!progress || clock.seconds() < next.load(std::memory_order_relaxed)) return;
    std::unique_lock lock(reporting, std::try_to_lock);
    if (!lock || clock.seconds() < next) return;
    next = clock.seconds() + 1;
    OmplResult sofar;
    sofar.seconds = clock.seconds();
    const GraphSize size = made.size();
    sofar.states = size.vertices;
    sofar.edges = size.edges;
    progress(sofar);
  }

 private:
  const OmplProgress& progress;
  const MadePlanner& made;
  const Stopwatch& clock;
  mutable std::mutex reporting;
  mutable std::atomic<double> next{1};
};

// The planner's tree or roadmap with its states' stamps (the end of the run for a state no free
// motion reached), every k-th state kept within `budget` numbers and the edges between
// those kept; how many states there were by when, from them all.
RecordTree treeOf(const ob::Planner& planner, const ob::SpaceInformationPtr& si,
                  const Layout& layout, const StampedMotions& stamps, float end, size_t budget,
                  RecordGrowth& growth) {
  ob::PlannerData data(si);
  planner.getPlannerData(data);
  RecordTree t;
  t.totalStates = data.numVertices();
  t.totalEdges = data.numEdges();
  const size_t n = t.totalStates, numbers = 3 * layout.scene.robots.size();
  const size_t keep = std::max<size_t>(1, budget / numbers),
               stride = std::max<size_t>(1, (n + keep - 1) / keep);
  constexpr uint32_t kDropped = ~uint32_t(0);
  std::vector<uint32_t> kept(n, kDropped);
  std::vector<std::pair<uint32_t, float>> all;
  Config q;
  for (size_t i = 0; i < n; ++i) {
    const ob::State* s = data.getVertex(unsigned(i)).getState();
    all.emplace_back(0, stamps.at(s, end));
    if (i % stride) continue;
    kept[i] = uint32_t(t.states.size());
    layout.toConfig(s, q);
    t.states.push_back(q);
    t.at.push_back(all.back().second);
  }
  growth = growthOf(std::move(all), {"states"});
  std::vector<unsigned> out;
  for (size_t i = 0; i < n; ++i) {
    if (kept[i] == kDropped) continue;
    data.getEdges(unsigned(i), out);
    for (unsigned j : out)
      if (kept[j] != kDropped) t.edges.push_back({kept[i], kept[j]});
  }
  return t;
}

// The motion validator: OMPL's discrete one at the resolution, or mms's certifier; with a
// record asked for, wrapped to stamp when states are reached (returned, else null).
std::shared_ptr<StampedMotions> setMotions(const ob::SpaceInformationPtr& si,
                                           const OmplSettings& settings, const Layout& layout,
                                           const CollisionChecker& checker,
                                           const Stopwatch& clock) {
  si->setStateValidityCheckingResolution(settings.resolution);
  if (settings.certifiedMotions)
    si->setMotionValidator(std::make_shared<CertifiedMotions>(si, layout, checker));
  if (!settings.record) return nullptr;
  ob::MotionValidatorPtr inner = si->getMotionValidator();
  if (!inner) inner = std::make_shared<ob::DiscreteMotionValidator>(si);
  auto stamps = std::make_shared<StampedMotions>(si, std::move(inner), clock);
  si->setMotionValidator(stamps);
  return stamps;
}

// OMPL's problem for the scene: its space, the checker as validity checker, the motion
// validator, the planner, start and goal, and the free sampler when asked for.
struct Problem {
  std::shared_ptr<og::SimpleSetup> setup;
  std::shared_ptr<StampedMotions> stamps;  // with a record asked for
  MadePlanner made;
};

Problem makeProblem(const Scene& scene, const OmplSettings& settings, const Layout& layout,
                    const CollisionChecker& checker, const Stopwatch& clock) {
  Problem p;
  p.setup = std::make_shared<og::SimpleSetup>(makeSpace(scene));
  // Freeing a million states takes seconds; a process about to exit can skip it.
  if (settings.keepUntilExit) {
    static auto* kept =
        new std::vector<std::shared_ptr<og::SimpleSetup>>();  // reachable, never freed
    kept->push_back(p.setup);
  }
  og::SimpleSetup& setup = *p.setup;
  const ob::SpaceInformationPtr si = setup.getSpaceInformation();
  setup.setStateValidityChecker(std::make_shared<Validity>(si, layout, checker));
  p.stamps = setMotions(si, settings, layout, checker, clock);
  p.made = makePlanner(si, settings, si->getMaximumExtent());
  setup.setPlanner(p.made.planner);
  if (settings.planner == "rrtstar" || settings.planner == "bitstar")
    setup.setOptimizationObjective(std::make_shared<PathLength>(si));
  ob::ScopedState<> start(setup.getStateSpace()), goal(setup.getStateSpace());
  layout.fromConfig(startConfig(scene), start.get());
  layout.fromConfig(goalConfig(scene), goal.get());
  setup.setStartAndGoalStates(start, goal);
  if (settings.freeSamples || settings.leanAngles > 0) {
    setup.getStateSpace()->setStateSamplerAllocator(
        [&layout, &checker, redraw = settings.freeSamples,
         lean = settings.leanAngles](const ob::StateSpace* s) {
          return std::make_shared<FreeSampler>(s->as<ob::CompoundStateSpace>(), layout, checker,
                                               redraw, lean);
        });
  }
  setup.setup();
  return p;
}

// OMPL's solution as mms waypoints. OMPL interpolates SO(2) the short way; unwrapping the
// angles says the same in mms-path/1.
std::vector<Config> waypointsOf(const og::PathGeometric& path, const Layout& layout) {
  std::vector<Config> w;
  Config q;
  for (size_t k = 0; k < path.getStateCount(); ++k) {
    layout.toConfig(path.getState(k), q, w.empty() ? nullptr : &w.back());
    w.push_back(q);
  }
  return w;
}

// The solution certified (a refused one is cleared) and, when asked for, simplified. The
// simplifier comes after the time to a path, as in OMPL's benchmarks, and within the time
// limit; its path replaces the first only once certified.
void certifySolution(og::SimpleSetup& setup, const Scene& scene, const OmplSettings& settings,
                     const Layout& layout, const CollisionChecker& checker, const Termination& stop,
                     const Stopwatch& total, OmplResult& r) {
  r.waypoints = waypointsOf(setup.getSolutionPath(), layout);
  r.certificate = checkPath(scene, checker, r.waypoints);
  r.status = r.certificate.ok ? PlanStatus::Found : PlanStatus::Uncertified;
  if (!r.certificate.ok) r.waypoints.clear();
  r.seconds = total.seconds();
  if (!settings.simplify || r.status != PlanStatus::Found || stop()) return;
  Stopwatch simplify;
  setup.simplifySolution(ob::PlannerTerminationCondition([&] { return stop(); }));
  std::vector<Config> w = waypointsOf(setup.getSolutionPath(), layout);
  if (const PathCheckResult c = checkPath(scene, checker, w); c.ok) {
    r.waypoints = std::move(w);
    r.certificate = c;
  }
  r.simplifySeconds = simplify.seconds();
}

}  // namespace

OmplResult planWithOmpl(const Scene& scene, const OmplSettings& settings, const Termination& stop,
                        const OmplProgress& progress) {
  // The time to a certified path, as MMS reports it: setup, solve, certification.
  const Stopwatch total;
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(settings.seed);
  const CollisionChecker checker(scene);
  const Layout layout{scene};
  const Problem problem = makeProblem(scene, settings, layout, checker, total);
  og::SimpleSetup& setup = *problem.setup;

  OmplResult r;
  r.setupSeconds = total.seconds();
  Stopwatch watch;
  const size_t checksBefore = CollisionChecker::workOnThisThread();
  const ProgressReporter reporter(progress, problem.made, total);
  const ob::PlannerStatus status = setup.solve(ob::PlannerTerminationCondition([&] {
    ++r.iterations;
    reporter();
    return stop();
  }));
  r.solveSeconds = watch.seconds();
  r.checks = CollisionChecker::workOnThisThread() - checksBefore;
  const GraphSize size = problem.made.size();
  r.states = size.vertices;
  r.edges = size.edges;
  if (problem.stamps) {
    const Stopwatch recording;
    r.tree = treeOf(*problem.made.planner, setup.getSpaceInformation(), layout, *problem.stamps,
                    float(total.seconds()), RecordBudget{}.numbers, r.growth);
    r.recordSeconds = recording.seconds();
  }
  if (status == ob::PlannerStatus::EXACT_SOLUTION)
    certifySolution(setup, scene, settings, layout, checker, stop, total, r);
  else
    r.seconds = total.seconds();
  return r;
}

}  // namespace mms
