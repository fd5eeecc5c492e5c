#pragma once
#include <stdexcept>
#include <string>

namespace mms {

/// Bad input: the message is one line "FILE: LOCATION: PROBLEM"; the CLI prints it and exits 2.
/// Control characters (a newline inside a JSON string the message quotes) become '?', so the
/// message stays one line whatever the input holds.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(printable(message)) {}

 private:
  static std::string printable(std::string s) {
    for (char& c : s)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    return s;
  }
};

}  // namespace mms
