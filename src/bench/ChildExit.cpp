#include "bench/ChildExit.h"

#include <poll.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace mms {

ChildExit::ChildExit(pid_t pid) {
#ifdef SYS_pidfd_open
  // (glibc 2.36 wraps it, but the system call alone needs no newer headers.)
  fd_ = int(syscall(SYS_pidfd_open, pid, 0));
#else
  (void)pid;
#endif
}

ChildExit::~ChildExit() {
  if (fd_ >= 0) close(fd_);
}

ChildExit& ChildExit::operator=(ChildExit&& o) noexcept {
  if (this != &o) {
    if (fd_ >= 0) close(fd_);
    fd_ = o.fd_;
    o.fd_ = -1;
  }
  return *this;
}

void awaitChildExit(const std::vector<int>& fds, double timeoutSeconds) {
  const bool everyOne = std::none_of(fds.begin(), fds.end(), [](int fd) { return fd < 0; });
  if (!everyOne) {
    usleep(100);
    return;
  }
  std::vector<pollfd> polled;
  for (int fd : fds) polled.push_back({fd, POLLIN, 0});
  const int ms = int(std::ceil(std::clamp(timeoutSeconds, 0.0, 3600.0) * 1000));
  poll(polled.data(), polled.size(), ms);  // EINTR: a signal, which the caller looks at
}

}  // namespace mms
