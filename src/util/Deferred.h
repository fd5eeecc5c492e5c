#pragma once
// Work cut by a time limit leaves exact structures behind (a slice half built among thousands
// of obstacles: arrangements of millions of exact points). Freeing them takes tens of ms, past
// the limit that cut them. They are kept here instead and freed within some budget: at the
// start of the next run and between restarts (registry/Optimizing.cpp), by the outermost planner's
// destructor when no planner runs, or never in a command about to exit (the system takes the
// memory back at once). So at most the unfinished manifolds of the runs since the last start
// are kept: one per thread of each.
#include <cstddef>
#include <exception>
#include <memory>

#include "mms/Termination.h"

namespace mms {

/// Keeps `garbage` alive until freeDeferred(). Never throws: called while a Stopped unwinds,
/// it frees `garbage` at once when it cannot keep it (no memory left).
void freeLater(std::shared_ptr<const void> garbage) noexcept;

/// Moves `value` (a local about to be unwound) into the garbage; on no memory it stays where
/// it is and is freed with its scope.
template <class T>
void freeLaterMoved(T& value) noexcept {
  try {
    freeLater(std::make_shared<T>(std::move(value)));
  } catch (...) {
  }
}

/// Rethrows a parallel batch's `error`; when the limit stopped it, the batch's finished results
/// go to the garbage first instead of being freed past the limit.
template <class T>
[[noreturn]] void rethrowDeferring(const std::exception_ptr& error, T& batch) {
  try {
    std::rethrow_exception(error);
  } catch (const Stopped&) {
    freeLaterMoved(batch);
    throw;
  }
}

/// Frees what freeLater() kept.
void freeDeferred();

/// How many objects freeLater() keeps now.
size_t deferredCount();

/// Counts a planner's run as under way while it lives: deferred garbage is freed only when
/// none is (freeDeferredIfIdle).
class RunningSolve {
 public:
  RunningSolve();
  ~RunningSolve();
  RunningSolve(const RunningSolve&) = delete;
  RunningSolve& operator=(const RunningSolve&) = delete;
};

/// freeDeferred() unless some planner's solve is under way (its limit must not pay for it).
void freeDeferredIfIdle();

}  // namespace mms
