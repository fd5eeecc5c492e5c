#pragma once
// Independent work items on a few threads, for manifolds: items are built in parallel and the
// caller adds the results in index order, so the roadmap (and the path) does not depend on the
// thread count or on which thread finished first.
#include <algorithm>
#include <atomic>
#include <exception>
#include <optional>
#include <thread>
#include <vector>

#include "mms/Termination.h"

namespace mms {

/// Calls f(i) for i in [0, n) on up to `threads` threads, the caller's included. Workers see the
/// caller's StopScope. Returns, per item, the exception it threw (null if none).
template <class F>
std::vector<std::exception_ptr> parallelFor(size_t n, unsigned threads, const F& f) {
  std::vector<std::exception_ptr> errors(n);
  std::atomic<size_t> next{0};
  const Termination* scope = StopScope::current();
  auto work = [&] {
    // A scope per thread: checkpoint() inside f must stop at the caller's limit.
    std::optional<StopScope> local;
    if (scope && StopScope::current() != scope) local.emplace(*scope);
    for (size_t i; (i = next.fetch_add(1)) < n;) {
      try {
        f(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> workers;
  for (unsigned t = 1; t < std::min<size_t>(threads, n); ++t) workers.emplace_back(work);
  work();
  for (std::thread& w : workers) w.join();
  return errors;
}

/// Threads to use for `--threads 0`: the machine's hardware threads.
inline unsigned hardwareThreads() { return std::max(1u, std::thread::hardware_concurrency()); }

}  // namespace mms
