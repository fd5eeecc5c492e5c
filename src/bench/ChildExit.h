#pragma once
// Waiting for a benchmark's runs to end, to the microsecond. A run's whole-command time is when
// its process ends; runs of 10 ms, reaped by polling every millisecond, came out in steps of
// 1.1 ms (a tenth of a run, as large as the ratios between planners' whole commands).
#include <sys/types.h>

#include <vector>

namespace mms {

/// A child's end as a file descriptor that becomes readable when it exits (Linux's pidfd), or
/// -1 where the kernel has none; the child is still reaped with waitpid.
class ChildExit {
 public:
  ChildExit() = default;
  explicit ChildExit(pid_t pid);
  ~ChildExit();
  ChildExit(ChildExit&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
  ChildExit& operator=(ChildExit&& o) noexcept;
  ChildExit(const ChildExit&) = delete;
  ChildExit& operator=(const ChildExit&) = delete;
  int fd() const { return fd_; }

 private:
  int fd_ = -1;
};

/// Returns once one of `fds` is readable (its child ended), a signal arrived, or `timeoutSeconds`
/// passed; with a -1 among them it polls every 0.1 ms instead.
void awaitChildExit(const std::vector<int>& fds, double timeoutSeconds);

}  // namespace mms
