// The command boundary: whatever a command throws becomes one line on stderr and an exit code,
// CGAL's own failure mechanism included (CGAL_error_msg is what CGAL's checks call).
#include <CGAL/assertions.h>
#include <gtest/gtest.h>

#include <new>
#include <sstream>

#include "mms/Errors.h"
#include "util/CommandBoundary.h"
#include "util/Interrupt.h"

namespace mms {
namespace {

struct Result {
  int code;
  std::string err;
};

Result run(const std::function<int()>& command) {
  std::ostringstream err;
  const int code = runAtBoundary(command, err);
  return {code, err.str()};
}

bool isOneLine(const std::string& s) {
  return !s.empty() && s.back() == '\n' && s.find('\n') == s.size() - 1;
}

TEST(CommandBoundary, CgalFailureIsAnInternalErrorOnOneLine) {
  const Result r = run([]() -> int {
    CGAL_error_msg("precondition violated\nsecond line");
    return 0;
  });
  EXPECT_EQ(r.code, kExitInternal);
  EXPECT_TRUE(isOneLine(r.err)) << r.err;
  EXPECT_NE(r.err.find("mms: internal error: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("precondition violated"), std::string::npos) << r.err;
}

TEST(CommandBoundary, CgalFailureIsCaughtEvenIfSomeoneSetAbort) {
  CGAL::set_error_behaviour(CGAL::ABORT);
  const Result r = run([]() -> int { CGAL_error_msg("boom"); });
  EXPECT_EQ(r.code, kExitInternal);
  EXPECT_EQ(CGAL::set_error_behaviour(CGAL::THROW_EXCEPTION), CGAL::THROW_EXCEPTION);
}

TEST(CommandBoundary, EachKindOfFailureHasItsCode) {
  EXPECT_EQ(run([] { return 1; }).code, kExitNo);
  const Result bad = run([]() -> int { throw InputError("f.json: robots[0]: bad"); });
  EXPECT_EQ(bad.code, kExitBadInput);
  EXPECT_EQ(bad.err, "f.json: robots[0]: bad\n");
  const Result ctrlC = run([]() -> int { throw Interrupted{}; });
  EXPECT_EQ(ctrlC.code, kExitInterrupted);
  EXPECT_TRUE(isOneLine(ctrlC.err));
  const Result oom = run([]() -> int { throw std::bad_alloc(); });
  EXPECT_EQ(oom.code, kExitInternal);
  EXPECT_NE(oom.err.find("out of memory"), std::string::npos);
  const Result odd = run([]() -> int { throw 42; });
  EXPECT_EQ(odd.code, kExitInternal);
  EXPECT_TRUE(isOneLine(odd.err));
}

}  // namespace
}  // namespace mms
