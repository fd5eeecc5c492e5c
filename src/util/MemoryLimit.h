#pragma once
// `--memory-limit` for long commands: caps the process's address space, so that a planner that
// grows without bound ends with "out of memory" (exit 3, no output file) instead of taking the
// machine down. An allocation beyond the cap, GMP's included (its default is to abort), ends
// the process there with that line: unwinding through CGAL code cut short mid-operation
// could crash.
#include <cstddef>
#include <string>
#include <system_error>

namespace mms {

/// Caps the address space at `megabytes` (0: no cap). Not for sanitizer builds, which reserve
/// terabytes of address space up front. Returns false if the system refused the cap.
bool limitMemory(double megabytes);

/// The cap alone, for a child process about to exec another program: what limitMemory
/// prepares besides (allocator hooks, a grown stack, thread arenas) would die with the exec
/// and cost the child's run its time. Returns false if the system refused the cap.
bool capAddressSpace(double megabytes);

/// Whether `e` says the system had no memory for a request (a thread's stack, a mapping).
bool outOfMemory(const std::system_error& e);

/// While one lives, running out of memory is reported as `file` being too large for the cap
/// (a scene of a million robots), not as the planner's growth.
class ReadingFile {
 public:
  explicit ReadingFile(const std::string& file);
  ~ReadingFile();
  ReadingFile(const ReadingFile&) = delete;
  ReadingFile& operator=(const ReadingFile&) = delete;
};

/// The one line (with its newline) that reports running out of memory.
std::string outOfMemoryLine();

}  // namespace mms
