#pragma once
// pthread_once without a system call per first use (QuietOnce.cpp), for the programs that link
// it: the command line and the test binary.

namespace mms {
/// Initialisations run by this pthread_once so far: grows with std::call_once in a program
/// that links it (a test checks that it took glibc's place).
unsigned long quietOnceInitsRun();
}  // namespace mms
