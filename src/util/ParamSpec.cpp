// The methods of the public ParamSpec (mms/Planner.h): what a parameter's declaration says
// of a value. Here rather than beside the registry so that every library can read parameters
// (run summaries type them by their declarations) without depending on the planners.
#include <cmath>
#include <optional>

#include "mms/Planner.h"
#include "util/Number.h"

namespace mms {

std::string ParamSpec::key() const {
  std::string k = name;
  for (char& c : k)
    if (c == '-') c = '_';
  return k;
}

std::string ParamSpec::problem(double v) const {
  if (!std::isfinite(v)) return "not a number";
  if ((type == Type::Integer || type == Type::Flag) && v != std::floor(v)) return "not an integer";
  if (v < min || v > max)
    return formatNumber(v) + " is not in [" + formatNumber(min) + ", " + formatNumber(max) + "]";
  return "";
}

std::string ParamSpec::parse(const std::string& text, double& v) const {
  for (size_t i = 0; i < choices.size(); ++i)
    if (text == choices[i]) {
      v = double(i);
      return "";
    }
  std::string names;
  for (const std::string& c : choices) names += (names.empty() ? "" : ", ") + c;
  const std::optional<double> number = wholeNumber(text);
  if (number) v = *number;
  if (!number) return "'" + text + "' is not " + (choices.empty() ? "a number" : "one of " + names);
  return problem(v);
}

}  // namespace mms
