// The pthread_once the command line and this test binary link (src/util/QuietOnce.cpp) in
// place of glibc's: std::call_once's guarantees, with threads racing, waiting and throwing.
#include <gtest/gtest.h>
#include <pthread.h>

#include <atomic>
#include <chrono>
#include <latch>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "Support.h"

#ifdef MMS_QUIET_ONCE
#include "util/QuietOnce.h"
#endif

namespace {

using namespace std::chrono_literals;

#ifdef MMS_QUIET_ONCE
void nothing() {}

TEST(QuietOnce, TakesThePlaceOfGlibcsInThisProgram) {
  pthread_once_t once = PTHREAD_ONCE_INIT;
  ASSERT_EQ(pthread_once(&once, nothing), 0);
  EXPECT_EQ(once, mms::kQuietOnceDone);  // glibc's leaves 2
}

TEST(QuietOnce, TheCommandLineLinksIt) {
  // The symbol table of the executable defines pthread_once (T): its calls do not reach glibc's.
  const mms::test::Outcome r =
      mms::test::runCommand("(nm " + std::string(MMS_BINARY) + " | grep ' T pthread_once$')");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(" T pthread_once"), std::string::npos) << r.out;
}
#endif

// Whichever pthread_once is linked: these are the guarantees CGAL's lazy values rely on.
TEST(QuietOnce, ManyThreadsRunTheInitialisationOnceAndAllSeeItsResult) {
  constexpr int kThreads = 8;
  for (int round = 0; round < 200; ++round) {
    std::once_flag flag;
    std::atomic<int> runs{0};
    int value = 0;  // plain: call_once's return must publish it
    std::atomic<int> seen{0};
    std::latch go(kThreads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
      threads.emplace_back([&] {
        go.arrive_and_wait();
        std::call_once(flag, [&] {
          if (round % 4 == 0) std::this_thread::sleep_for(200us);  // let the others wait
          value = 42;
          runs.fetch_add(1);
        });
        if (value == 42) seen.fetch_add(1);
      });
    for (std::thread& t : threads) t.join();
    ASSERT_EQ(runs.load(), 1) << "round " << round;
    ASSERT_EQ(seen.load(), kThreads) << "round " << round;
  }
}

TEST(QuietOnce, AnInitialisationThatThrowsLeavesItToTheNextCaller) {
  std::once_flag flag;
  EXPECT_THROW(std::call_once(flag, [] { throw std::runtime_error("no room"); }),
               std::runtime_error);
  bool ran = false;
  std::call_once(flag, [&] { ran = true; });
  EXPECT_TRUE(ran);
  bool again = false;
  std::call_once(flag, [&] { again = true; });
  EXPECT_FALSE(again);
}

TEST(QuietOnce, AWaiterRunsTheInitialisationWhenTheFirstThrows) {
  for (int round = 0; round < 20; ++round) {
    std::once_flag flag;
    std::atomic<bool> firstInside{false};
    std::atomic<int> runs{0};
    std::thread first([&] {
      try {
        std::call_once(flag, [&] {
          firstInside = true;
          std::this_thread::sleep_for(2ms);  // the second caller arrives and waits
          throw std::runtime_error("failed");
        });
      } catch (const std::runtime_error&) {
      }
    });
    while (!firstInside) std::this_thread::yield();
    std::call_once(flag, [&] { runs.fetch_add(1); });  // waits, then runs it itself
    first.join();
    ASSERT_EQ(runs.load(), 1) << "round " << round;
  }
}

pthread_once_t cOnce = PTHREAD_ONCE_INIT;
int cRuns = 0;
void cInit() { ++cRuns; }

TEST(QuietOnce, PlainPthreadOnceFromC) {
  EXPECT_EQ(pthread_once(&cOnce, cInit), 0);
  EXPECT_EQ(pthread_once(&cOnce, cInit), 0);
  EXPECT_EQ(cRuns, 1);
}

}  // namespace
