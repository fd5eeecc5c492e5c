#include "util/MemoryLimit.h"

#include <gmp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <system_error>

namespace mms {

bool outOfMemory(const std::system_error& e) {
  return e.code() == std::errc::not_enough_memory ||
         e.code() == std::errc::resource_unavailable_try_again;
}

namespace {

std::atomic<bool> allocationFailed{false};
std::terminate_handler previousTerminate = nullptr;

[[noreturn]] void throwBadAlloc() {
  allocationFailed = true;
  throw std::bad_alloc();
}

// GMP aborts when an allocation fails; these throw instead, so the failure unwinds to the
// command boundary (GMP's frames have unwind tables on Debian's x86-64 and arm64 builds).
void* gmpAllocate(size_t n) {
  if (void* p = std::malloc(n)) return p;
  throwBadAlloc();
}

void* gmpReallocate(void* p, size_t, size_t n) {
  if (void* q = std::realloc(p, n)) return q;
  throwBadAlloc();
}

void gmpFree(void* p, size_t) { std::free(p); }

// A library thread that lets an allocation failure escape, or a std::thread destroyed while
// unwinding from one (OMPL's PRM), ends in std::terminate: after a failed allocation that is
// the limit at work, reported as the command boundary reports it, without a signal.
[[noreturn]] void terminateAfterFailure() {
  if (std::exception_ptr e = std::current_exception()) try {
      std::rethrow_exception(e);
    } catch (const std::bad_alloc&) {
      allocationFailed = true;
    } catch (const std::system_error& error) {  // a thread's stack could not be mapped
      if (outOfMemory(error)) allocationFailed = true;
    } catch (...) {
    }
  if (allocationFailed) {
    static const char kLine[] = "mms: out of memory (see --memory-limit); no output written\n";
    (void)!::write(STDERR_FILENO, kLine, sizeof kLine - 1);
    ::_exit(3);
  }
  if (previousTerminate) previousTerminate();
  std::abort();
}

// The main thread's stack grows into address space too: grown now, under no limit, a deep
// call later cannot meet the cap as a segmentation fault.
__attribute__((noinline)) void growStack() {
  volatile char pages[2 << 20];
  for (size_t i = 0; i < sizeof pages; i += 4096) pages[i] = 0;
}

}  // namespace

bool limitMemory(double megabytes) {
  if (megabytes <= 0) return true;
  mp_set_memory_functions(gmpAllocate, gmpReallocate, gmpFree);
  std::set_new_handler([] { throwBadAlloc(); });
  previousTerminate = std::set_terminate(terminateAfterFailure);
  growStack();
  const rlim_t bytes = rlim_t(megabytes * 1024 * 1024);
  const struct rlimit limit { bytes, bytes };
  return setrlimit(RLIMIT_AS, &limit) == 0;
}

}  // namespace mms
