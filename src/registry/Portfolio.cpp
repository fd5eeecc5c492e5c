// "auto", the default planner: MMS and a sampling planner on two cores. A user does not know in
// advance whether a scene is tight: where the passages are wide a sampler needs a few hundred
// states and MMS would still be building its first slices; where they are narrow MMS wins by
// orders of magnitude.
//
// Determinism: the sampler's path is taken when it finds one within its allowance of iterations,
// and MMS's otherwise. The allowance is a budget that doubles with each round MMS grows through,
// counted in shares of the round's targets (MMS doubles its manifolds each round): the sampler
// runs while MMS works, so that scenes where MMS struggles (many robots nearly filling a room)
// still get the sampler's path, however many iterations it needs. Each member is deterministic
// for its seed and the allowance is counted in iterations and MMS's growth, not timed: MMS's
// growth when it ends fixes the last allowance, so which member's path is returned does not
// depend on the
// machine's load; the clock only decides how soon (docs/planner.md, "The default: a
// portfolio"). The portfolio returns a member's path unchanged, naming it
// (PlanStatistics::solvedBy).
#include <execinfo.h>
#include <malloc.h>
#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "registry/Adapters.h"

namespace mms {

namespace {

/// The sampler beside MMS: the fastest of OMPL's planners in open clutter (docs/planner.md).
constexpr const char* kSampler = "rrtconnect";
/// How the sampler runs (`--planner rrtconnect` with these reproduces its paths): motions
/// certified by clearance, samples redrawn until clear, so its trees grow into free space, half
/// the angles drawn between start and goal, so its paths turn less back and forth, and among two
/// robots or more motions half OMPL's default length, which then fail less often on the others
/// (for one robot about the same: docs/planner.md, "The default: a portfolio").
std::map<std::string, double> samplerSettings(const Scene& scene) {
  std::map<std::string, double> p{
      {"certified-motions", 1}, {"free-samples", 1}, {"lean-angles", 0.5}};
  if (scene.robots.size() >= 2) p["range-share"] = 0.1;
  return p;
}
/// How long the sampler runs alone before MMS starts: on open scenes it is then often done,
/// and no second thread is paid for (docs/planner.md, "The default: a portfolio").
constexpr std::chrono::milliseconds kHeadStart{2};
/// The sampler's iterations by default when MMS begins its first round, doubled for each round
/// MMS grows through (samplerAllowance): its path is taken when it finds one within them.
constexpr double kSamplerIterations = 2000;
/// How often a sampler waiting for MMS's next round looks at the caller's limits.
constexpr std::chrono::milliseconds kWaitStep{5};

/// MMS's large blocks kept in the heap, so that mapping them does not hold the memory-map lock
/// the sampler's page faults need (the command line's jemalloc ignores this); and what a second
/// thread needs loaded before memory runs out. Once per process.
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

/// Keeps the two members on different cores: left to the scheduler a new thread often shares
/// its creator's core for milliseconds, the whole run on open scenes. MMS's
/// thread is created with its cores rather than moved there, which would wait for the sampler's
/// time slice (docs/planner.md, "The default: a portfolio").
class CoresApart {
 public:
  CoresApart() = default;
  CoresApart(const CoresApart&) = delete;
  CoresApart& operator=(const CoresApart&) = delete;

  /// On the sampler's thread, before MMS's starts: whether the two can run apart, and then
  /// `others()` are the cores for MMS's thread.
  bool plan() {
    if (pthread_getaffinity_np(pthread_self(), sizeof allowed_, &allowed_) != 0) return false;
    here_ = sched_getcpu();
    if (CPU_COUNT(&allowed_) < 2 || here_ < 0 || here_ >= CPU_SETSIZE ||
        !CPU_ISSET(here_, &allowed_))
      return false;
    others_ = allowed_;
    CPU_CLR(here_, &others_);
    return true;
  }
  const cpu_set_t& others() const { return others_; }
  /// On the sampler's thread, once MMS's has started on the others: keeps this thread where it is.
  void keepHere() {
    cpu_set_t mine;
    CPU_ZERO(&mine);
    CPU_SET(here_, &mine);
    pinned_ = pthread_setaffinity_np(pthread_self(), sizeof mine, &mine) == 0;
  }
  /// On the sampler's thread, once it is done: its cores back to it. MMS's thread keeps the
  /// others while it runs on (the sampler gave up, or its path was refused).
  void restore() {
    if (pinned_) pthread_setaffinity_np(pthread_self(), sizeof allowed_, &allowed_);
    pinned_ = false;
  }

 private:
  cpu_set_t allowed_{}, others_{};
  int here_ = -1;
  bool pinned_ = false;
};

/// MMS's side of the portfolio, and the sampler's allowance. MMS begins only once the sampler has
/// run for the head start: the sampler tells it of each check of its termination condition (one
/// per iteration), and the first check past the head start makes MMS and starts it on a thread
/// of its own. The same checks, counted, hold the sampler once they pass its allowance (the
/// budget, doubled for each round MMS has grown through) until MMS grows further,
/// and end it if MMS finishes first (with its path, or a proof that none exists). MMS finishing
/// does not end the sampler within its allowance, so that the sampler's path within it wins whoever
/// was faster; MMS failing (throwing) leaves the sampler unbounded. On open scenes the sampler is
/// done before that, and there is neither MMS nor a second thread: MMS's construction (exact
/// obstacles, arrangements) beside a 2 ms sampler slowed it by 5-8 % on the bends (seeds 1-10,
/// median per scene), and a process with a second thread pays for atomic reference counts and
/// locked allocation in every shared pointer and malloc of the sampler.
///
/// When the sampler has its path, MMS's thread is left to stop on its own: it checks its end
/// between exact steps, and the step it is in took 0.1-2 ms (mean 0.5 ms over 36 open-clutter
/// and discs-swap runs), a sixth of the whole run on open scenes. So that thread reads
/// nothing of the caller's after solve() returns: its own cancel flag (the caller's is passed
/// on while the caller waits), its own clock, and progress reports that stop at the return.
class Challenger final : public Termination::Watcher {
 public:
  using Maker = std::function<std::unique_ptr<Planner>()>;
  /// `mms`: the MMS planner of earlier queries, or null (`make` makes it when it starts); both
  /// must outlive this. `iterations`: the sampler's budget in MMS's first round.
  Challenger(std::unique_ptr<Planner>& mms, const Maker& make, const Termination& stop,
             const Planner::Progress& progress, size_t iterations)
      : mms_(mms),
        make_(make),
        progress_(&progress),
        budget_(iterations),
        allowed_(double(iterations)),
        sampler_(stop.endingAlsoOn(&spent_)),
        here_(stop.endingAlsoOn(&ended_).watchedBy(&rounds_)),
        apart_(here_.cancelledBy(&cancelled_)),
        headStartEnds_(Termination::Clock::now() + kHeadStart) {}
  ~Challenger() {
    cores_.restore();  // the sampler threw: its cores back to it (after a normal end: nothing)
    end();
    join();
  }
  Challenger(const Challenger&) = delete;
  Challenger& operator=(const Challenger&) = delete;

  /// The sampler's condition: the caller's, ending also once MMS is done and the sampler's
  /// allowance is spent.
  const Termination& sampler() const { return sampler_; }
  const Stopwatch& clock() const { return clock_; }
  void onCheck(Termination::Clock::time_point now) override {
    const bool over = !unbounded_ && double(++checks_) > allowed_;
    // MMS starts at once when the sampler's allowance runs out within the head start.
    if (!started_.load(std::memory_order_relaxed) && (over || now >= headStartEnds_)) startMms();
    if (over) awaitAllowance();
  }
  /// MMS on the calling thread, for the time left, if it has not started: the sampler gave up
  /// before the head start was over.
  void runHere() {
    if (started_.exchange(true)) return;
    run(here_);
  }
  /// Ends MMS: it stops at its next check.
  void end() { ended_ = true; }
  /// On the sampler's thread, once it is done: its cores back to it.
  void restoreCores() { cores_.restore(); }
  /// Waits for MMS to finish, passing the caller's cancel flag on. On the sampler's thread.
  void await(const Termination& stop) {
    if (!threadStarted_) return;
    std::unique_lock lock(doneMutex_);
    do {
      if (stop.cancelled()) cancelled_ = true;
    } while (!doneChanged_.wait_for(lock, std::chrono::milliseconds(5), [&] { return done_; }));
  }
  /// No more progress reports: the caller's function may be gone once solve() returns.
  void mute() {
    const std::lock_guard lock(progressMutex_);
    progress_ = nullptr;
  }
  void join() {
    if (threadStarted_) pthread_join(thread_, nullptr);
    threadStarted_ = false;
  }
  /// Rethrows what MMS threw.
  void rethrow() const {
    if (failure_) std::rethrow_exception(failure_);
  }
  PlanResult& result() { return own_; }

 private:
  /// MMS on its own thread, on the cores the sampler's thread does not use.
  void startMms() {
    if (started_.exchange(true)) return;
    const bool apart = cores_.plan();
    bool created = apart && start(&cores_.others());
    // Cores that cannot be set (a cpuset changed under the process) leave them to the scheduler.
    if (created)
      cores_.keepHere();
    else
      created = start(nullptr);
    if (!created) {  // no room for a thread's stack: the memory limit
      failure_ = std::make_exception_ptr(std::bad_alloc());
      ended_ = true;
    }
  }
  /// Tells the challenger of the rounds MMS begins and of its growth in each, on MMS's thread.
  struct Rounds final : Termination::Watcher {
    explicit Rounds(Challenger& c) : challenger(c) {}
    void onRound(size_t round) override { challenger.roundBegun(round); }
    void onGrowth(double share) override { challenger.grown(share); }
    Challenger& challenger;
  };
  /// `round` as the MMS planner counts them: after earlier queries, its first in this one may
  /// be past 1.
  void roundBegun(size_t round) {
    {
      const std::lock_guard lock(doneMutex_);
      if (firstRound_ == 0) firstRound_ = round;
      if (round > lastRound_) lastRound_ = round, share_ = 0;
    }
    doneChanged_.notify_all();
  }
  /// MMS has met `share` of its round's targets; never less than before within the round.
  void grown(double share) {
    {
      const std::lock_guard lock(doneMutex_);
      share_ = std::max(share_, std::clamp(share, 0.0, 1.0));
    }
    doneChanged_.notify_all();
  }
  /// The sampler's iterations now allowed: the budget, doubled for each round MMS has grown
  /// through, counted in shares of the round's targets (kSamplerAllowance).
  double allowanceLocked() const {
    return firstRound_ == 0 ? double(budget_)
                            : samplerAllowance(budget_, lastRound_ - firstRound_, share_);
  }
  /// The sampler past its allowance: waits for MMS to grow further. MMS done ends the sampler (its
  /// path, or its proof that none exists, is the answer); MMS failing lets it run on unbounded,
  /// as does an MMS that could not start.
  void awaitAllowance() {
    if (!threadStarted_) {
      unbounded_ = true;
      return;
    }
    std::unique_lock lock(doneMutex_);
    while (double(checks_) > (allowed_ = allowanceLocked())) {
      if (done_) {
        // MMS's answer stands (a path, or a proof that none exists), unless it failed.
        if (failure_)
          unbounded_ = true;
        else
          spent_ = true;
        return;
      }
      if (sampler_.secondsLeft() == 0) {  // the caller's limit or Ctrl-C: the sampler ends
        spent_ = true;
        return;
      }
      doneChanged_.wait_for(lock, kWaitStep);
    }
  }
  /// MMS's thread, on `cores` if given; whether it started.
  bool start(const cpu_set_t* cores) {
    pthread_attr_t attr;
    if (pthread_attr_init(&attr) != 0) return false;
    bool ok = !cores || pthread_attr_setaffinity_np(&attr, sizeof(cpu_set_t), cores) == 0;
    ok = ok && pthread_create(
                   &thread_, &attr,
                   [](void* self) -> void* {
                     auto* me = static_cast<Challenger*>(self);
                     me->run(me->apart_);
                     return nullptr;
                   },
                   this) == 0;
    pthread_attr_destroy(&attr);
    threadStarted_ = ok;
    return ok;
  }
  void run(const Termination& stop) {
    // Here, not on the sampler's thread: loading libgcc_s took 0.2 ms of its time.
    prepareTheProcess();
    const Planner::Progress relay = [this](const PlanStatistics& s) {
      const std::lock_guard lock(progressMutex_);
      if (progress_ && *progress_) (*progress_)(s);
    };
    try {
      if (!mms_ && !stop()) mms_ = make_();
      if (!stop()) {
        own_ = mms_->solve(stop, relay);
      }
    } catch (...) {
      failure_ = std::current_exception();
    }
    {
      const std::lock_guard lock(doneMutex_);
      done_ = true;
    }
    doneChanged_.notify_all();
  }

  std::unique_ptr<Planner>& mms_;
  const Maker& make_;
  std::mutex progressMutex_;
  const Planner::Progress* progress_;  // null once muted
  const Stopwatch clock_;
  std::atomic<bool> ended_{false};      // MMS is to stop
  std::atomic<bool> spent_{false};      // the sampler's budget is spent
  std::atomic<bool> cancelled_{false};  // the caller's flag, passed on while it waits
  std::atomic<bool> started_{false};
  const size_t budget_;
  // The sampler's, on its thread: its checks, its allowance when last read, and whether MMS
  // failed, so that it runs on.
  size_t checks_ = 0;
  double allowed_;
  bool unbounded_ = false;
  Rounds rounds_{*this};  // MMS's conditions tell it of the rounds begun
  const Termination sampler_;
  const Termination here_;   // MMS's when it runs on the caller's thread
  const Termination apart_;  // MMS's on its own thread
  const Termination::Clock::time_point headStartEnds_;
  pthread_t thread_{};
  bool threadStarted_ = false;
  std::mutex doneMutex_;
  std::condition_variable doneChanged_;
  bool done_ = false;
  size_t firstRound_ = 0, lastRound_ = 0;  // of MMS in this query; 0: none begun
  double share_ = 0;                       // of MMS's targets in its last round
  CoresApart cores_;
  PlanResult own_;
  std::exception_ptr failure_;
};

}  // namespace

// Doubled per round, and within a round as its growth goes (MMS's own manifolds double per
// round): the sampler need not wait for the end of a long round, and where MMS has its path
// early in a round the sampler's allowance has grown by little.
double samplerAllowance(size_t budget, size_t rounds, double share) {
  return std::ldexp(double(budget) * std::exp2(share), int(std::min<size_t>(rounds, 1000)));
}

namespace {

/// The sampler's budget, declared once for the command line, benchmarks and docs.
const ParamSpec& samplerIterations() {
  static const ParamSpec spec{
      "sampler-iterations",
      ParamSpec::Type::Integer,
      0,
      1e9,
      kSamplerIterations,
      std::string("Iterations of ") + kSampler +
          " beside MMS as MMS begins, doubled for each round MMS grows through (counted in "
          "shares of its round's targets): its path is taken when it finds one within them, "
          "MMS's otherwise, so the same seed gives "
          "the same path whatever the load; 0: MMS alone (default " +
          formatNumber(kSamplerIterations) + ")"};
  return spec;
}

class Portfolio : public Planner {
 public:
  /// `makeMms`: null for scenes MMS does not take.
  Portfolio(const Scene& scene, Challenger::Maker makeMms, const PlannerParams& params)
      : scene_(scene),
        makeMms_(std::move(makeMms)),
        samplerParams_{params.seed, samplerSettings(scene), false, params.exitsAfterRun,
                       params.record},
        iterations_(size_t(paramValue(params, samplerIterations()))),
        mmsAlone_(makeMms_ && params.roadmapPicture && scene.robots.size() == 1) {}
  ~Portfolio() override { finishBackgroundWork(); }

  PlanResult solve(const Termination& stop, const Progress& progress) override {
    finishBackgroundWork();  // the last run's MMS, which this one may use again
    if (mmsAlone_ || (iterations_ == 0 && makeMms_)) return runMmsAlone(stop, progress);
    const std::unique_ptr<Planner> sampler = makePlanner(kSampler, scene_, samplerParams_);
    if (!makeMms_) return named(sampler->solve(stop, progress), kSampler);
    // The sampler on this thread, where the memory is warm; MMS joins it after the head start.
    auto challenger = std::make_unique<Challenger>(mms_, makeMms_, stop, progress, iterations_);
    const Stopwatch& clock = challenger->clock();
    PlanResult sampled = sampler->solve(challenger->sampler().watchedBy(challenger.get()));
    challenger->restoreCores();
    if (sampled.found()) {
      // Found within its allowance: its path, whether MMS has one or not. MMS stops in the
      // background (finishBackgroundWork).
      challenger->end();
      challenger->mute();
      sampled.stats.seconds = clock.seconds();
      running_ = std::move(challenger);
      return named(std::move(sampled), kSampler);
    }
    // Without a path (MMS had one first, the time ran out, or the certifier refused the
    // sampler's) the sampler leaves the rest of the time to MMS.
    challenger->runHere();
    challenger->await(stop);
    challenger->join();
    challenger->mute();
    challenger->rethrow();
    PlanResult out = std::move(challenger->result());
    if (!out.found() && stop.cancelled()) out.status = PlanStatus::Cancelled;
    out.stats.seconds = clock.seconds();
    return named(std::move(out), "mms");
  }

  void finishBackgroundWork() override { running_.reset(); }

  bool setQuery(const Config& start, const Config& goal) override {
    if (!makeMms_) return false;
    finishBackgroundWork();
    if (!mms_) mms_ = makeMms_();  // multi-query: MMS's roadmap serves the next queries too
    if (!mms_->setQuery(start, goal)) return false;
    for (size_t i = 0; i < scene_.robots.size(); ++i) {
      scene_.robots[i].start = poseOf(start, i);
      scene_.robots[i].goal = poseOf(goal, i);
    }
    return true;
  }

 private:
  PlanResult runMmsAlone(const Termination& stop, const Progress& progress) {
    if (!mms_) mms_ = makeMms_();
    return named(mms_->solve(stop, progress), "mms");
  }
  static PlanResult named(PlanResult r, const char* member) {
    if (r.found()) r.stats.solvedBy = member;
    return r;
  }

  Scene scene_;  // the sampler is made per query, for the query's start and goal
  Challenger::Maker makeMms_;
  std::unique_ptr<Planner> mms_;
  PlannerParams samplerParams_;
  size_t iterations_;  // the sampler's budget; 0: MMS alone
  /// A picture of the roadmap asks for MMS's cells and lines (one robot), which a sampler's win
  /// would not have: MMS runs alone.
  bool mmsAlone_;
  // MMS after the sampler's path, stopping; declared last: it uses mms_.
  std::unique_ptr<Challenger> running_;
};

}  // namespace

PlannerInfo portfolioPlannerInfo() {
  const PlannerInfo mms = mmsPlannerInfo();
  PlannerInfo info;
  info.name = "auto";
  info.summary = std::string("MMS and OMPL's ") + kSampler +
                 " (certified motions, free samples) on two cores; the sampler's certified path "
                 "if it finds one within its iterations (--sampler-iterations, doubled for each "
                 "round MMS grows through), else MMS's (the statistics name it). "
                 "Scenes MMS does not take go to the sampler alone; with a roadmap picture asked "
                 "for (one robot), MMS runs alone";
  info.params = mms.params;
  info.params.push_back(samplerIterations());
  info.multiQuery = true;
  info.make = [make = mms.make](const Scene& scene, const PlannerParams& params,
                                const std::string& source) -> std::unique_ptr<Planner> {
    Challenger::Maker makeMms;
    if (mmsTakes(scene))
      makeMms = [make, scene, params, source] { return make(scene, params, source); };
    return std::make_unique<Portfolio>(scene, std::move(makeMms), params);
  };
  return info;
}

}  // namespace mms
