#include "util/Deferred.h"

#include <atomic>
#include <mutex>
#include <vector>

namespace mms {

namespace {

struct Graveyard {
  std::mutex mutex;
  std::vector<std::shared_ptr<const void>> kept;
  std::atomic<int> running{0};
};

// Never destroyed: a command may exit while a worker thread still adds to it.
Graveyard& graveyard() {
  static Graveyard* g = new Graveyard;
  return *g;
}

}  // namespace

void freeLater(std::shared_ptr<const void> garbage) noexcept {
  if (!garbage) return;
  Graveyard& g = graveyard();
  const std::lock_guard lock(g.mutex);
  try {
    g.kept.push_back(std::move(garbage));
  } catch (...) {  // no memory to keep it: `garbage` is freed on return
  }
}

void freeDeferred() {
  std::vector<std::shared_ptr<const void>> kept;
  {
    Graveyard& g = graveyard();
    const std::lock_guard lock(g.mutex);
    kept.swap(g.kept);
  }
  // Freed here, outside the lock.
}

size_t deferredCount() {
  Graveyard& g = graveyard();
  const std::lock_guard lock(g.mutex);
  return g.kept.size();
}

RunningSolve::RunningSolve() { graveyard().running.fetch_add(1); }
RunningSolve::~RunningSolve() { graveyard().running.fetch_sub(1); }

void freeDeferredIfIdle() {
  if (graveyard().running.load() == 0) freeDeferred();
}

}  // namespace mms
