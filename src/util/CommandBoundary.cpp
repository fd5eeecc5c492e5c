#include "util/CommandBoundary.h"

#include <CGAL/assertions.h>  // also brings the header-only definitions

#include <new>
#include <ostream>
#include <stdexcept>
#include <system_error>

#include "mms/Errors.h"
#include "util/Interrupt.h"
#include "util/MemoryLimit.h"

namespace mms {

std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

int runAtBoundary(const std::function<int()>& command, std::ostream& err) {
  // CGAL's default, set again in case a library changed it: a failed CGAL check must reach the
  // handlers below instead of printing and aborting.
  CGAL::set_error_behaviour(CGAL::THROW_EXCEPTION);
  CGAL::set_warning_behaviour(CGAL::CONTINUE);
  try {
    return command();
  } catch (const InputError& e) {
    err << oneLine(e.what()) << "\n";
    return kExitBadInput;
  } catch (const Interrupted&) {
    err << "mms: interrupted (Ctrl-C); no output written\n";
    return kExitInterrupted;
  } catch (const std::bad_alloc&) {
    err << outOfMemoryLine();
    return kExitInternal;
  } catch (const std::system_error& e) {
    if (outOfMemory(e)) {
      err << outOfMemoryLine();
      return kExitInternal;
    }
    err << "mms: internal error: " << oneLine(e.what()) << "\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    err << "mms: internal error: " << oneLine(e.what()) << "\n";
    return kExitInternal;
  } catch (...) {
    err << "mms: internal error: unknown exception\n";
    return kExitInternal;
  }
}

}  // namespace mms
