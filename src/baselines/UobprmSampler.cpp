#include "baselines/UobprmSampler.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/util/RandomNumbers.h>

#include <cmath>

namespace mms {

namespace ob = ompl::base;

UobprmSampler::UobprmSampler(const ob::SpaceInformation* si, double segmentLength, double step)
    : ob::ValidStateSampler(si),
      sampler_(si->allocStateSampler()),
      length_(segmentLength),
      step_(step) {
  name_ = "uobprm";
  a_ = si->allocState();
  b_ = si->allocState();
  walk_ = si->allocState();
  prev_ = si->allocState();
}

UobprmSampler::~UobprmSampler() {
  for (ob::State* s : {a_, b_, walk_, prev_}) si_->freeState(s);
  for (ob::State* s : pending_) si_->freeState(s);
}

// One segment: a uniform endpoint, the other within distance l of it; every change of validity
// along the walk yields the free state next to it.
bool UobprmSampler::fromSegment(ob::State* out) {
  sampler_->sampleUniform(a_);
  sampler_->sampleUniformNear(b_, a_, length_);
  const double d = si_->distance(a_, b_);
  const unsigned steps = std::max(1u, unsigned(std::ceil(d / step_)));
  si_->copyState(prev_, a_);
  bool prevValid = si_->isValid(prev_);
  for (unsigned i = 1; i <= steps; ++i) {
    si_->getStateSpace()->interpolate(a_, b_, double(i) / steps, walk_);
    const bool valid = si_->isValid(walk_);
    if (valid != prevValid) {
      ob::State* keep = si_->allocState();
      si_->copyState(keep, valid ? walk_ : prev_);
      pending_.push_back(keep);
    }
    si_->copyState(prev_, walk_);
    prevValid = valid;
  }
  if (pending_.empty()) return false;
  si_->copyState(out, pending_.front());
  si_->freeState(pending_.front());
  pending_.pop_front();
  return true;
}

bool UobprmSampler::sample(ob::State* state) {
  for (unsigned attempt = 0; attempt < attempts_; ++attempt) {
    if (!pending_.empty()) {
      si_->copyState(state, pending_.front());
      si_->freeState(pending_.front());
      pending_.pop_front();
      return true;
    }
    if (rng_.uniform01() < 0.5) {
      sampler_->sampleUniform(state);
      if (si_->isValid(state)) return true;
    } else if (fromSegment(state)) {
      return true;
    }
  }
  return false;
}

bool UobprmSampler::sampleNear(ob::State* state, const ob::State* near, double distance) {
  for (unsigned attempt = 0; attempt < attempts_; ++attempt) {
    sampler_->sampleUniformNear(state, near, distance);
    if (si_->isValid(state)) return true;
  }
  return false;
}

}  // namespace mms
