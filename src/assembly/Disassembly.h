#pragma once
// Three-handed translational disassembly, as in the Further Work section of Salzman, Hemmer,
// Halperin, "On the power of manifold samples in exploring configuration spaces and the
// dimensionality of narrow passages": the obstacles are the static part (the first hand), the
// robots are the movable parts. Each step moves one part, or two together (second and third
// hands), while the remaining parts stay put as obstacles, until every part has left the static
// part's bounding box (or reached its given target).
//
// One translating part alone is planned exactly: its free space is one slice, so "no step" is a
// proof. A rigid part alone gets the one-robot MMS (it may have to turn on its way out), and
// two parts the two-robot recursion (a 4-D C-space for translating parts), both under budgets
// that double every pass, so their search is complete only in the limit. Parts
// that left stay parked where they went, as obstacles for the later steps, so the whole disassembly
// is one continuous motion of all parts, certified at the end.
#include <functional>
#include <string>
#include <vector>

#include "geometry/CollisionChecker.h"
#include "mms/Scene.h"
#include "mms/Termination.h"

namespace mms {

struct DisassemblySettings {
  uint64_t seed = 1;
  bool pairs = true;  // three hands: let two parts move together
  // Budgets of one attempt in the first pass over the parts left, in rounds of the planner it
  // runs; every further pass allows one round more, so the work per attempt doubles. Rounds,
  // not seconds: the same seed gives the same sequence on any machine.
  size_t firstSingleRounds = 2;  // a rigid part alone (one-robot MMS; a translating one is exact)
  size_t firstPairRounds = 3;    // two parts together (two-robot MMS)
};

struct DisassemblyStep {
  std::vector<size_t> parts;      // the parts that move (indices into the scene's robots)
  std::vector<size_t> removed;    // those that end at their targets (a helper may return)
  Scene scene;                    // the step's problem: moving parts as robots, the rest obstacles
  std::vector<Config> waypoints;  // certified path in `scene`
  double seconds = 0;
};

struct DisassemblyResult {
  std::vector<DisassemblyStep> steps;
  std::vector<size_t> stuck;  // parts still in place when no step was found
  // Why they are stuck, in words: what was tried and for how long, or what proves it.
  std::string stuckBecause;
  Scene finalScene;          // the input with every part's goal where it ended
  std::vector<Config> path;  // all parts, the whole disassembly; certified in finalScene
  size_t attempts = 0;       // planner runs (single parts and pairs)
  double seconds = 0;
  bool complete() const { return stuck.empty(); }
};

class DisassemblyPlanner {
 public:
  /// Parts whose goal equals their start are to leave the static part's bounding box (the
  /// box of all obstacles); the others go to their goals. The scene must have obstacles.
  DisassemblyPlanner(const Scene& scene, DisassemblySettings settings = {});

  DisassemblyResult solve(const Termination& stop,
                          const std::function<void(size_t, const DisassemblyStep&)>& progress = {});

 private:
  // What an attempt found: a step, no step now (more rounds may find one), or a proof that the
  // part (the pair) cannot make this step while the others stay where they are.
  enum class Attempt { Step, NotYet, Never };
  // One pass over the parts left at the budgets of pass `pass`: a step, or whether a later
  // pass could find one (Never: none could).
  Attempt tryPass(const std::vector<size_t>& left, size_t pass, const Termination& stop,
                  DisassemblyResult& out);
  Attempt trySingle(size_t part, size_t rounds, const Termination& stop, DisassemblyResult& out);
  Attempt tryPair(size_t a, size_t b, int returning, size_t rounds, const Termination& stop,
                  DisassemblyResult& out);
  Scene stepScene(const std::vector<size_t>& moving) const;
  std::vector<Pose> targetsFor(const Scene& step, const CollisionChecker& checker, size_t robot,
                               size_t count) const;
  void record(DisassemblyStep step, DisassemblyResult& out);
  std::string whyStuck(const std::vector<size_t>& left, size_t passes, bool proved,
                       const DisassemblyResult& out, const Termination& stop) const;

  Scene scene_;
  DisassemblySettings settings_;
  Box box_;                 // the static part's bounding box
  std::vector<Pose> pose_;  // every part's current pose
  std::vector<bool> done_;  // left the box or reached its target
  std::vector<Config> path_;
  uint64_t attemptSeed_;
  // Of the passes since the last step: parts proved unable to leave alone, the proofs in words,
  // and the largest budgets tried.
  std::vector<bool> neverAlone_;
  std::vector<std::string> reasons_;
  size_t singleRounds_ = 0, pairRounds_ = 0;
};

}  // namespace mms
