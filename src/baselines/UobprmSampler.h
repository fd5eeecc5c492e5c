#pragma once
// U-OB-PRM's sampler (Yeh, Thomas, Eppstein, Amato: "UOBPRM: A uniformly distributed obstacle-
// based PRM", IROS 2012), which OMPL lacks: sample a segment of length l, walk it at the
// collision-checking resolution, and keep the free states where it crosses between free and
// forbidden space. As in the MMS paper's experiments, half of the samples are drawn uniformly.
#include <ompl/base/StateSampler.h>
#include <ompl/base/ValidStateSampler.h>
#include <ompl/util/RandomNumbers.h>

#include <deque>

namespace mms {

class UobprmSampler : public ompl::base::ValidStateSampler {
 public:
  UobprmSampler(const ompl::base::SpaceInformation* si, double segmentLength, double step);
  ~UobprmSampler() override;
  bool sample(ompl::base::State* state) override;
  bool sampleNear(ompl::base::State* state, const ompl::base::State* near,
                  double distance) override;

 private:
  bool fromSegment(ompl::base::State* out);
  ompl::base::StateSamplerPtr sampler_;
  ompl::RNG rng_;
  double length_, step_;
  std::deque<ompl::base::State*> pending_;  // further boundary states found on earlier segments
  ompl::base::State *a_, *b_, *walk_, *prev_;
};

}  // namespace mms
