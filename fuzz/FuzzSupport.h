#pragma once
// What every fuzz target checks besides "no crash": failures are one line naming the file.
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "mms/Errors.h"

namespace mms::fuzz {

inline void require(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz: %s\n", what);
  std::abort();
}

inline void requireOneLine(const InputError& e, std::string_view prefix) {
  const std::string_view message = e.what();
  require(message.starts_with(prefix), "error message does not start with the file name");
  require(message.size() > prefix.size(), "error message names no problem");
  require(message.find('\n') == std::string_view::npos, "error message is not one line");
}

}  // namespace mms::fuzz
