// pthread_once without a system call per first use, for programs that link this file.
//
// CGAL's lazy exact kernel guards every object's exact value with std::call_once, which
// libstdc++ implements with pthread_once. glibc's pthread_once makes a futex wake system call
// after each initialisation, whether or not any thread waits: 25 000 calls in a 60 ms plan of
// the niche swap, a tenth of an exact slice's time in perf (docs/benchmarks.md's history, "Exact values
// without a system call each"). This one wakes only when a thread is waiting.
//
// Defining pthread_once in an executable takes the place of glibc's for the whole process (the
// executable comes first in symbol lookup). Only programs opt in: the command line and the test
// binary, never the library or the Python module, which live in other programs' processes.
//
// Semantics as POSIX and glibc's: init runs once; callers arriving while it runs wait for it;
// if init exits by an exception (C++) or by thread cancellation (a forced unwind), the state
// goes back to idle, waiters are woken and one of them runs init next. Not kept from glibc: its
// fork generations (a child forked while another thread runs an init would wait on it forever;
// no program of this project forks while it has threads).
#include "util/QuietOnce.h"

#include <linux/futex.h>
#include <pthread.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <climits>

namespace {

// PTHREAD_ONCE_INIT is 0.
constexpr int kIdle = 0, kRunning = 1, kRunningAwaited = 2, kDone = mms::kQuietOnceDone;

void futex(int* word, int op, int value) {
  syscall(SYS_futex, word, op | FUTEX_PRIVATE_FLAG, value, nullptr, nullptr, 0);
}

void finish(int* word, int to) {
  std::atomic_ref<int> state(*word);
  if (state.exchange(to, std::memory_order_acq_rel) == kRunningAwaited)
    futex(word, FUTEX_WAKE, INT_MAX);
}

}  // namespace

extern "C" int pthread_once(pthread_once_t* control, void (*init)(void)) {
  static_assert(sizeof(pthread_once_t) == sizeof(int));
  int* word = reinterpret_cast<int*>(control);
  std::atomic_ref<int> state(*word);
  int s = state.load(std::memory_order_acquire);
  while (s != kDone) {
    if (s == kIdle) {
      if (!state.compare_exchange_weak(s, kRunning, std::memory_order_acquire)) continue;
      try {
        init();
      } catch (...) {  // an exception, or cancellation's forced unwind: someone else may try
        finish(word, kIdle);
        throw;
      }
      finish(word, kDone);
      return 0;
    }
    // Running: say that we wait, then sleep until the value changes.
    if (s == kRunning &&
        !state.compare_exchange_weak(s, kRunningAwaited, std::memory_order_acquire))
      continue;
    futex(word, FUTEX_WAIT, kRunningAwaited);
    s = state.load(std::memory_order_acquire);
  }
  return 0;
}
