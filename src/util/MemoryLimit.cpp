#include "util/MemoryLimit.h"

#include <gmp.h>
#include <sys/resource.h>

#include <cstdlib>
#include <new>

namespace mms {

namespace {

// GMP aborts when an allocation fails; these throw instead, so the failure unwinds to the
// command boundary (GMP's frames have unwind tables on Debian's x86-64 and arm64 builds).
void* gmpAllocate(size_t n) {
  if (void* p = std::malloc(n)) return p;
  throw std::bad_alloc();
}

void* gmpReallocate(void* p, size_t, size_t n) {
  if (void* q = std::realloc(p, n)) return q;
  throw std::bad_alloc();
}

void gmpFree(void* p, size_t) { std::free(p); }

}  // namespace

bool limitMemory(double megabytes) {
  if (megabytes <= 0) return true;
  mp_set_memory_functions(gmpAllocate, gmpReallocate, gmpFree);
  const rlim_t bytes = rlim_t(megabytes * 1024 * 1024);
  const struct rlimit limit { bytes, bytes };
  return setrlimit(RLIMIT_AS, &limit) == 0;
}

}  // namespace mms
