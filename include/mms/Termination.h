#pragma once
// When a long computation must stop: a deadline, and an optional flag set from outside (e.g.
// a SIGINT handler). Planners check it between manifolds.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>

namespace mms {

class Termination {
 public:
  using Clock = std::chrono::steady_clock;
  /// Told of every check of a condition that carries it, and of every round an MMS planner
  /// begins under it: work that should begin only if the computation checking runs long (the
  /// portfolio's MMS) begins from there, and the portfolio's sampler runs for as many
  /// iterations as MMS's rounds have earned it.
  struct Watcher {
    /// `now`: the time the check read (one clock read per check, which a sampler makes per
    /// iteration).
    virtual void onCheck(Clock::time_point now) { (void)now; }
    /// `round`: the round begun, counted as the planner counts them (1 for its first).
    virtual void onRound(size_t round) { (void)round; }
    /// `share`: how much of the current round's growth targets the planner has met (0 to 1),
    /// after each step of growth.
    virtual void onGrowth(double share) { (void)share; }

   protected:
    ~Watcher() = default;
  };
  explicit Termination(double seconds, const std::atomic<bool>* cancel = nullptr)
      : deadline_(Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>(seconds))),
        cancel_(cancel) {}
  /// The cancel flag, for budgets of sub-tasks that must stop with this one.
  const std::atomic<bool>* cancelFlag() const { return cancel_; }
  bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }
  /// This condition, ending also when `ended` is set: for a sub-task that a sibling may end
  /// early (the portfolio's planners, once one of them has a path). It does not count as
  /// cancelled: cancelled() still means the caller's flag.
  Termination endingAlsoOn(const std::atomic<bool>* ended) const {
    Termination t = *this;
    t.ended_ = ended;
    return t;
  }
  /// This condition with `cancel` as its cancel flag: for work that may outlive the caller's
  /// flag (the portfolio's losing member, left to stop after solve() returned), to which the
  /// caller passes its flag on while it waits.
  Termination cancelledBy(const std::atomic<bool>* cancel) const {
    Termination t = *this;
    t.cancel_ = cancel;
    return t;
  }
  /// This condition, telling `watcher` of each check.
  Termination watchedBy(Watcher* watcher) const {
    Termination t = *this;
    t.watcher_ = watcher;
    return t;
  }
  /// This condition without the notes of growth within rounds (its watcher still hears of
  /// checks and rounds): for a planner that runs other MMS planners in turn (many robots one at
  /// a time), whose shares of their rounds are not shares of its own work.
  Termination withoutGrowthNotes() const {
    Termination t = *this;
    t.growthNotes_ = false;
    return t;
  }
  /// A watcher may end the condition from onCheck (by setting `ended`): this check then holds.
  bool operator()() const {
    if (cancelled() || endedEarly()) return true;
    const Clock::time_point now = Clock::now();
    if (watcher_) {
      watcher_->onCheck(now);
      if (cancelled() || endedEarly()) return true;
    }
    return now >= deadline_;
  }
  /// An MMS planner begins round `round` (1, 2, ...) under this condition.
  void noteRound(size_t round) const {
    if (watcher_) watcher_->onRound(round);
  }
  /// An MMS planner has met `share` (0 to 1) of its current round's growth targets.
  void noteGrowth(double share) const {
    if (watcher_ && growthNotes_) watcher_->onGrowth(share);
  }
  /// Seconds until the deadline (0 once passed, cancelled or ended), for budgets of sub-tasks.
  double secondsLeft() const {
    if (cancelled() || endedEarly()) return 0;
    return std::max(0.0, std::chrono::duration<double>(deadline_ - Clock::now()).count());
  }

 private:
  bool endedEarly() const { return ended_ && ended_->load(std::memory_order_relaxed); }
  Clock::time_point deadline_;
  const std::atomic<bool>* cancel_;
  const std::atomic<bool>* ended_ = nullptr;
  Watcher* watcher_ = nullptr;
  bool growthNotes_ = true;
};

/// Thrown by checkpoint() once the termination condition of the enclosing StopScope holds.
struct Stopped {};

/// One exact manifold among thousands of obstacles takes seconds inside exact-geometry calls that
/// no Termination reaches. A planner's solve() opens a StopScope; that work calls checkpoint()
/// between its steps, which throws Stopped once the scope's condition holds, and solve() drops
/// the unfinished manifold. Per thread: a thread that builds manifolds opens its own scope.
class StopScope {
 public:
  explicit StopScope(const Termination& stop) : previous_(current()) { current() = &stop; }
  ~StopScope() { current() = previous_; }
  StopScope(const StopScope&) = delete;
  StopScope& operator=(const StopScope&) = delete;
  static const Termination*& current() {
    thread_local const Termination* stop = nullptr;
    return stop;
  }

 private:
  const Termination* previous_;
};

/// `nextStepSeconds`: what the work up to the next checkpoint is expected to cost; a step that
/// would end past the limit is not begun.
inline void checkpoint(double nextStepSeconds = 0) {
  const Termination* stop = StopScope::current();
  if (stop && ((*stop)() || (nextStepSeconds > 0 && nextStepSeconds > stop->secondsLeft())))
    throw Stopped{};
}

/// Seconds since construction, for phase timings.
class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// Adds the seconds its scope lasted to `total` when the scope ends, also by an exception: a
/// manifold the time limit cut short (Stopped) took that time too, and the phases must account
/// for the run.
class TimeCharge {
 public:
  explicit TimeCharge(double& total) : total_(total) {}
  ~TimeCharge() { total_ += watch_.seconds(); }
  TimeCharge(const TimeCharge&) = delete;
  TimeCharge& operator=(const TimeCharge&) = delete;

 private:
  double& total_;
  Stopwatch watch_;
};

}  // namespace mms
