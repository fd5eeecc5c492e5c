// Ctrl-C: a long mms plan or mms assemble stops at once, says so, exits 130 and writes nothing.
#include <gtest/gtest.h>

#include "Support.h"
#include "mms/Termination.h"

using namespace mms;
using namespace mms::test;

namespace {

// Starts `args` in the background, sends SIGINT after two seconds, reports its exit code.
Outcome interruptLater(const std::string& args) {
  return runCommand("( " + std::string(MMS_BINARY) + " " + args +
                    " & pid=$!; sleep 2; kill -INT $pid; wait $pid; echo \"rc=$?\" )");
}

}  // namespace

TEST(Interrupt, CtrlCEndsPlanWithoutOutput) {
  TempDir dir;
  const std::string out = dir.path("p.json"), stats = dir.path("s.json");
  Stopwatch clock;
  const Outcome r =
      interruptLater("plan " + quote(scenario("one-robot/zigzag-slot.json")) +
                     " --time-limit 120 -o " + quote(out) + " --stats-json " + quote(stats));
  EXPECT_LT(clock.seconds(), 30.0);
  EXPECT_NE(r.out.find("rc=130"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(stats));
}

TEST(Interrupt, CtrlCEndsAssembleWithoutOutput) {
  TempDir dir;
  const std::string scene = dir.path("tight.json"), out = dir.path("out");
  ASSERT_EQ(runMms("scenario assembly-1 --slack 0.002 -o " + quote(scene)).code, 0);
  Stopwatch clock;
  const Outcome r =
      interruptLater("assemble " + quote(scene) + " -q --time-limit 120 -o " + quote(out));
  EXPECT_LT(clock.seconds(), 30.0);
  EXPECT_NE(r.out.find("rc=130"), std::string::npos) << r.out << r.err;
  EXPECT_FALSE(std::filesystem::exists(out + "/disassembly.json"));
}

// Ctrl-C in a terminal reaches the bench and its runs (one process group): it stops, exits
// 130, and records none of the interrupted runs, so resuming runs them again.
TEST(Interrupt, CtrlCEndsBenchWithoutRecordingInterruptedRuns) {
  TempDir dir;
  const std::string out = dir.path("b");
  Stopwatch clock;
  const Outcome r = runCommand(
      "( setsid " + std::string(MMS_BINARY) + " bench " +
      quote(scenario("one-robot/zigzag-slot.json")) +
      " --planners mms --runs 2 --time-limit 30 --memory-limit 0 --jobs 2 -o " + quote(out) +
      " & pid=$!; sleep 2; /bin/kill -INT -- -$pid; wait $pid; echo \"rc=$?\" )");
  EXPECT_LT(clock.seconds(), 20.0);
  EXPECT_NE(r.out.find("rc=130"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
  EXPECT_EQ(readFile(out + "/runs.jsonl"), "");
}

// A run that Ctrl-C ended before the bench saw the signal itself is not a result either.
TEST(Interrupt, BenchStopsWhenARunWasInterrupted) {
  TempDir dir;
  const std::string out = dir.path("b");
  const Outcome r = runCommand(
      "( " + std::string(MMS_BINARY) + " bench " + quote(scenario("one-robot/zigzag-slot.json")) +
      " --planners mms --runs 2 --time-limit 30 --memory-limit 0 --jobs 1 -o " + quote(out) +
      " & pid=$!; sleep 2; /bin/kill -INT $(pgrep -P $pid); wait $pid; echo \"rc=$?\" )");
  EXPECT_NE(r.out.find("rc=130"), std::string::npos) << r.out << r.err;
  EXPECT_EQ(readFile(out + "/runs.jsonl"), "");
}
