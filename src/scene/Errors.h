#pragma once
#include <stdexcept>
#include <string>

namespace mms {

/// Bad input: the message is one line "FILE: LOCATION: PROBLEM"; the CLI prints it and exits 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mms
