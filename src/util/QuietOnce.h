#pragma once
// pthread_once without a system call per first use (QuietOnce.cpp), for the programs that link
// it: the command line and the test binary.

namespace mms {
/// What a pthread_once_t holds once its initialisation has run (glibc's own leaves 2): a test
/// tells by it that this pthread_once took glibc's place.
constexpr int kQuietOnceDone = 3;
}  // namespace mms
