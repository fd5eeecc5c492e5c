#pragma once
// "did you mean ...?" for a name a user mistyped: an option, a planner, a scenario, a keyword.
#include <string>
#include <vector>

namespace mms {

/// The candidate nearest to `name` by edit distance, when it is near enough to be the one
/// meant (at most a third of its letters, and at least one, differ); "" otherwise.
std::string nearest(const std::string& name, const std::vector<std::string>& candidates);

/// "; did you mean 'X'?" for the nearest candidate, or "".
std::string didYouMean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace mms
