#include "util/MemoryLimit.h"

#include <gmp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <latch>
#include <new>
#include <system_error>
#include <thread>
#include <vector>

namespace mms {

bool outOfMemory(const std::system_error& e) {
  return e.code() == std::errc::not_enough_memory ||
         e.code() == std::errc::resource_unavailable_try_again;
}

namespace {

double limitMegabytes = 0;
std::terminate_handler previousTerminate = nullptr;
// The line that reports the failure, composed ahead: the failure must not allocate.
char line[768] = "";
int lineLength = 0;

void composeLine(const char* readingFile) {
  lineLength = readingFile
                   ? std::snprintf(line, sizeof line,
                                   "mms: %s: does not fit in --memory-limit %g MB (out of memory "
                                   "while reading it); no output written\n",
                                   readingFile, limitMegabytes)
                   : std::snprintf(line, sizeof line,
                                   "mms: out of memory (see --memory-limit); no output written\n");
  lineLength = std::clamp(lineLength, 0, int(sizeof line) - 1);
}

// Under the cap a failed allocation ends the command at once, with its line and exit 3. It
// does not unwind: CGAL's arrangements cut short inside an insertion cannot be destroyed
// safely (their half-linked DCEL crashes the destructor), and nothing is left to save, for
// outputs are written whole at the end of a command (AtomicFile.h).
[[noreturn]] void endOutOfMemory() {
  (void)!::write(STDERR_FILENO, line, size_t(lineLength));
  ::_exit(3);
}

// GMP aborts when an allocation fails; these end the command as any other failure does.
void* gmpAllocate(size_t n) {
  if (void* p = std::malloc(n)) return p;
  endOutOfMemory();
}

void* gmpReallocate(void* p, size_t, size_t n) {
  if (void* q = std::realloc(p, n)) return q;
  endOutOfMemory();
}

void gmpFree(void* p, size_t) { std::free(p); }

// A thread that could not be made (no room for its stack) throws std::system_error; one that
// escapes a library thread ends in std::terminate: the limit at work, reported the same way.
[[noreturn]] void terminateAfterFailure() {
  if (std::exception_ptr e = std::current_exception()) try {
      std::rethrow_exception(e);
    } catch (const std::bad_alloc&) {
      endOutOfMemory();
    } catch (const std::system_error& error) {
      if (outOfMemory(error)) endOutOfMemory();
    } catch (...) {
    }
  if (previousTerminate) previousTerminate();
  std::abort();
}

// The main thread's stack grows into address space too: grown now, under no limit, a deep
// call later cannot meet the cap as a segmentation fault. Touching the lowest byte grows the
// stack's mapping in one page fault; touching every page (a fault each) took 5-10 ms.
__attribute__((noinline)) void growStack() {
  volatile char pages[2 << 20];
  pages[0] = 0;
  (void)pages[0];
}

// The allocator (jemalloc, as glibc's malloc) gives each new thread an arena of its own, made on
// the thread's first allocation; jemalloc crashes when it cannot map one. Threads that allocate
// now, under no cap, leave arenas that later threads (the portfolio's challenger, OMPL's PRM)
// take over once these have ended.
void warmThreadArenas() {
  constexpr int kThreads = 3;
  std::latch allocated(kThreads);
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i)
    threads.emplace_back([&allocated] {
      void* volatile p = std::malloc(64);
      allocated.arrive_and_wait();  // all at once, so that each takes an arena of its own
      std::free(p);
    });
  for (std::thread& t : threads) t.join();
}

}  // namespace

bool limitMemory(double megabytes) {
  if (megabytes <= 0) return true;
  mp_set_memory_functions(gmpAllocate, gmpReallocate, gmpFree);
  std::set_new_handler([] { endOutOfMemory(); });
  previousTerminate = std::set_terminate(terminateAfterFailure);
  growStack();
  warmThreadArenas();
  limitMegabytes = megabytes;
  composeLine(nullptr);
  return capAddressSpace(megabytes);
}

bool capAddressSpace(double megabytes) {
  if (megabytes <= 0) return true;
  const rlim_t bytes = rlim_t(megabytes * 1024 * 1024);
  const struct rlimit limit { bytes, bytes };
  return setrlimit(RLIMIT_AS, &limit) == 0;
}

ReadingFile::ReadingFile(const std::string& file) {
  if (limitMegabytes > 0) composeLine(file.c_str());
}

ReadingFile::~ReadingFile() { composeLine(nullptr); }

std::string outOfMemoryLine() {
  if (lineLength == 0) composeLine(nullptr);
  return std::string(line, size_t(lineLength));
}

}  // namespace mms
