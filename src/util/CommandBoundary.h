#pragma once
// Where a command's exceptions become an exit code and one line on stderr: bad input (InputError)
// 2, Ctrl-C (Interrupted) 130, anything else, CGAL's failures included (CGAL throws
// CGAL::Failure_exception, a std::logic_error, by default), 3. Never an abort or a stack trace.
#include <functional>
#include <iosfwd>
#include <string>

namespace mms {

enum ExitCode : int {
  kExitOk = 0,
  kExitNo = 1,
  kExitBadInput = 2,
  kExitInternal = 3,
  kExitInterrupted = 130
};

/// Runs `command` and returns its exit code, or the code of what it threw, reported on `err`.
int runAtBoundary(const std::function<int()>& command, std::ostream& err);

/// Line breaks become spaces, trailing spaces go.
std::string oneLine(std::string s);

}  // namespace mms
