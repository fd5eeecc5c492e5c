// Ctrl-C: a long mms plan or mms assemble stops at once, says so, exits 130 and writes nothing.
#include <gtest/gtest.h>

#include "Support.h"
#include "util/Termination.h"

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
      interruptLater("plan " + quote(scenario("one-robot/sealed-ring.json")) +
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
