// "auto", the default planner: MMS and a sampling planner race on two cores, and the first
// certified path wins. A user does not know in advance whether a scene is tight: where the
// passages are wide a sampler needs a few hundred states and MMS would still be building its
// first slices; where they are narrow MMS wins by orders of magnitude. Racing the two makes the
// default never slower than the sampler and never much slower than MMS.
//
// Determinism: each member is deterministic for its seed, and the portfolio returns a member's
// path unchanged, naming it (PlanStatistics::solvedBy); `--planner NAME` with the same seed
// reproduces it exactly. Which member wins a close race can depend on the machine's load.
#include <execinfo.h>
#include <malloc.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>

#include "api/Adapters.h"

namespace mms {

namespace {

/// The sampler in the race: in open clutter RRT-Connect was the fastest of OMPL's planners
/// with default parameters (docs/benchmarks.md). Its path is returned as found (OMPL's
/// simplifier would cost 1-3 ms, as much as the search on open scenes): smoothing belongs to a
/// certified post-processing step for every planner alike.
constexpr const char* kSampler = "rrtconnect";
/// How long the sampler runs alone before MMS starts: what MMS gives up on narrow scenes (a
/// few percent of its usual tens of milliseconds there), against the 1-3 ms by which MMS's
/// stopping would otherwise delay a sampler's win on open ones.
constexpr std::chrono::milliseconds kHeadStart{5};

/// MMS allocates and frees large blocks all the time (exact arrangements); with glibc's default
/// thresholds each such block is mapped and unmapped, or the heap's top trimmed, and every one
/// takes the process's memory-map lock, which the sampler's page faults need too: on the bends
/// (seeds 1-10) RRT-Connect took 1.7x as long beside MMS in the same process as alone, and
/// 1.03x with blocks up to 32 MB kept in the heap and 64 MB of free top kept. Set once for the
/// process: what the portfolio costs a program that embeds it is that memory kept. Also once:
/// what a second thread needs loaded before memory runs out (below).
void prepareTheProcess() {
  static std::once_flag once;
  std::call_once(once, [] {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
    // glibc loads libgcc_s, which a second thread's unwinding needs, on first use; at the
    // memory limit that load fails and glibc aborts ("libgcc_s.so.1 must be installed for
    // unwinding to work"). backtrace() loads it now, while there is room.
    void* frame = nullptr;
    backtrace(&frame, 1);
  });
}

class Portfolio : public Planner {
 public:
  Portfolio(const Scene& scene, std::unique_ptr<Planner> mms, const PlannerParams& params)
      : scene_(scene),
        mms_(std::move(mms)),
        samplerParams_{params.seed, {}, false, params.exitsAfterRun} {}

  PlanResult solve(const Termination& stop, const Progress& progress) override {
    const std::unique_ptr<Planner> sampler = makePlanner(kSampler, scene_, samplerParams_);
    if (!mms_) return named(sampler->solve(stop, progress), kSampler);  // scenes MMS cannot take
    prepareTheProcess();
    std::atomic<bool> ended{false};
    bool samplerFinished = false;  // guarded by mutex
    std::mutex mutex;
    std::condition_variable samplerDone;
    const Termination race = stop.endingAlsoOn(&ended);
    const Stopwatch clock;
    PlanResult sampled, own;
    double sampledAt = std::numeric_limits<double>::infinity(), ownAt = sampledAt;
    std::exception_ptr failure;
    // MMS on the new thread, the sampler on this one: the sampler, done in a millisecond or two
    // on open scenes, starts at once where the memory is warm (open clutter and bends, seeds
    // 1-10: 3 % faster per scene, median, than the other way round).
    std::thread other([&] {
      try {
        // The sampler's head start: on open scenes it is done within it, and MMS, which checks
        // the limit only between exact steps of a millisecond or more, would only delay it.
        std::unique_lock<std::mutex> lock(mutex);
        samplerDone.wait_for(lock, kHeadStart, [&] { return samplerFinished; });
        lock.unlock();
        if (ended) return;
        own = mms_->solve(race, progress);
        ownAt = clock.seconds();
      } catch (...) {
        failure = std::current_exception();
      }
      ended = true;
    });
    auto finishSampler = [&] {
      const std::lock_guard<std::mutex> lock(mutex);
      samplerFinished = true;
      samplerDone.notify_one();
    };
    try {
      sampled = sampler->solve(race);
    } catch (...) {
      ended = true;
      finishSampler();
      other.join();
      throw;
    }
    if (sampled.found()) {
      sampledAt = clock.seconds();
      ended = true;
    }
    finishSampler();
    other.join();
    if (failure) std::rethrow_exception(failure);
    const bool samplerWon = sampled.found() && (!own.found() || sampledAt < ownAt);
    PlanResult out = samplerWon ? std::move(sampled) : std::move(own);
    if (!out.found() && stop.cancelled()) out.status = PlanStatus::Cancelled;
    out.stats.seconds = clock.seconds();
    return named(std::move(out), samplerWon ? kSampler : "mms");
  }

  bool setQuery(const Config& start, const Config& goal) override {
    if (!mms_ || !mms_->setQuery(start, goal)) return false;
    for (size_t i = 0; i < scene_.robots.size(); ++i) {
      scene_.robots[i].start = poseOf(start, i);
      scene_.robots[i].goal = poseOf(goal, i);
    }
    return true;
  }

 private:
  static PlanResult named(PlanResult r, const char* member) {
    if (r.found()) r.stats.solvedBy = member;
    return r;
  }

  Scene scene_;  // the sampler is made per query, for the query's start and goal
  std::unique_ptr<Planner> mms_;
  PlannerParams samplerParams_;
};

}  // namespace

PlannerInfo portfolioPlannerInfo() {
  const PlannerInfo mms = mmsPlannerInfo();
  PlannerInfo info;
  info.name = "auto";
  info.summary = std::string("MMS and OMPL's ") + kSampler +
                 " race on two cores; the first certified path wins (the statistics name it). "
                 "Scenes MMS does not take go to the sampler alone";
  info.params = mms.params;
  info.multiQuery = true;
  info.make = [make = mms.make](const Scene& scene, const PlannerParams& params,
                                const std::string& source) -> std::unique_ptr<Planner> {
    std::unique_ptr<Planner> own;
    if (mmsTakes(scene)) own = make(scene, params, source);
    return std::make_unique<Portfolio>(scene, std::move(own), params);
  };
  return info;
}

}  // namespace mms
