#pragma once
// Ctrl-C for long commands: SIGINT sets a flag that Terminations watch, so a planner stops at
// the next manifold and the command exits 130 without writing its outputs.
#include <atomic>
#include <csignal>

namespace mms {

/// The SIGINT flag; installs the handler on the first call.
inline const std::atomic<bool>* sigintFlag() {
  static std::atomic<bool> flag{false};
  static const bool installed = [] {
    std::signal(SIGINT, [](int) { flag.store(true, std::memory_order_relaxed); });
    return true;
  }();
  (void)installed;
  return &flag;
}

inline bool interruptRequested() { return sigintFlag()->load(std::memory_order_relaxed); }

/// Thrown by a command that was interrupted; the command line reports it and exits 130.
struct Interrupted {};

}  // namespace mms
