// Waiting for a benchmark's runs to end: a run is seen to end when it does, not at the next
// poll, and a wait for a run that goes on ends at its timeout.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>

#include "bench/ChildExit.h"

using namespace mms;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

pid_t childThatSleeps(useconds_t micros) {
  const pid_t pid = fork();
  if (pid == 0) {
    usleep(micros);
    _exit(0);
  }
  return pid;
}

}  // namespace

TEST(ChildExit, TheWaitEndsWhenTheChildDoes) {
  const pid_t pid = childThatSleeps(20'000);
  ASSERT_GT(pid, 0);
  const ChildExit exit(pid);
  const auto started = std::chrono::steady_clock::now();
  int status = 0;
  // Woken by the child's end (or by a signal): at most a few waits, far within the timeout.
  for (int k = 0; k < 100 && waitpid(pid, &status, WNOHANG) == 0; ++k)
    awaitChildExit({exit.fd()}, 30.0);
  EXPECT_LT(secondsSince(started), 15.0);
  EXPECT_TRUE(WIFEXITED(status));
}

TEST(ChildExit, TheWaitEndsAtItsTimeoutWhileTheChildRuns) {
  const pid_t pid = childThatSleeps(5'000'000);
  ASSERT_GT(pid, 0);
  const ChildExit exit(pid);
  const auto started = std::chrono::steady_clock::now();
  awaitChildExit({exit.fd()}, 0.05);
  EXPECT_LT(secondsSince(started), 4.0);
  EXPECT_EQ(waitpid(pid, nullptr, WNOHANG), 0);  // still running
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
}
