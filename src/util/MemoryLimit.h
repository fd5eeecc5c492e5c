#pragma once
// `--memory-limit` for long commands: caps the process's address space, so that a planner that
// grows without bound ends with "out of memory" (exit 3, no output file) instead of taking the
// machine down. Allocations beyond the cap throw std::bad_alloc, GMP's included (its default
// is to abort), and the command boundary reports them.
#include <cstddef>
#include <system_error>

namespace mms {

/// Caps the address space at `megabytes` (0: no cap). Not for sanitizer builds, which reserve
/// terabytes of address space up front. Returns false if the system refused the cap.
bool limitMemory(double megabytes);

/// Whether `e` says the system had no memory for a request (a thread's stack, a mapping).
bool outOfMemory(const std::system_error& e);

}  // namespace mms
