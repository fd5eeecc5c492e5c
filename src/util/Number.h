#pragma once
// A number typed by a user (an option, a field of a text file): the whole text, or nothing.
#include <exception>
#include <optional>
#include <string>

namespace mms {

/// `text` as a double when all of it is one (std::stod: "1e3", "-2.5", "inf" and "nan" too;
/// callers that need a finite value check it); nothing when it is empty, not a number, out of
/// range, or followed by anything ("1,5", "3x").
inline std::optional<double> wholeNumber(const std::string& text) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used == 0 || used != text.size()) return std::nullopt;
  return v;
}

/// `v` as messages and help texts show it: "%g" ("0.5", "1e+06"). Also declared in the public
/// mms/Planner.h; defined once, in util/Number.cpp.
std::string formatNumber(double v);

}  // namespace mms
