#pragma once
// Work cut by a time limit leaves exact structures behind (a slice half built among thousands
// of obstacles: arrangements of millions of exact points). Freeing them takes tens of ms, past
// the limit that cut them. They are kept here instead and freed when no planner runs: by the
// outermost planner's destructor, or never in a command about to exit (the system takes the
// memory back at once). At most one unfinished manifold per thread and stopped run is kept.
#include <cstddef>
#include <memory>

namespace mms {

/// Keeps `garbage` alive until freeDeferred().
void freeLater(std::shared_ptr<const void> garbage);

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
