// Every scene generator, planned with the default command: what a user runs first on a family
// must give a certified path, never an abort, a signal or an internal error. Robots of some
// families start and end at angle pi (the warehouse's carts), which OMPL's SO(2) refuses.
#include <gtest/gtest.h>

#include <string>

#include "Support.h"
#include "scenarios/Catalog.h"

using namespace mms;

namespace {

class EveryFamily : public testing::TestWithParam<std::string> {};

std::string familyName(const testing::TestParamInfo<std::string>& info) {
  std::string n = info.param;
  for (char& c : n)
    if (c == '-') c = '_';
  return n;
}

}  // namespace

// Seeds 1-3 (1 under the sanitizers), `mms scenario NAME --seed S` with the family's defaults,
// then `mms plan` with nothing but the seed and the output: exit 0 and a path that `mms check`
// certifies. Every family's default scene but the two-robot swallow's and the round room's is
// solved in under 1.1 s here (release build; swallow-two 0.03-6.7 s), so the default 60 s limit
// leaves room for a sanitized, loaded machine.
TEST_P(EveryFamily, TheDefaultCommandPlansACertifiedPath) {
  const std::string family = GetParam();
  const test::TempDir dir;
  for (int seed = 1; seed <= test::seedsToRun(3); ++seed) {
    const std::string s = std::to_string(seed);
    const std::string scene = test::quote(dir.path(family + "-" + s + ".json"));
    const std::string path = test::quote(dir.path(family + "-" + s + ".path.json"));
    const test::Outcome made = test::runMms("scenario " + family + " --seed " + s + " -o " + scene);
    ASSERT_EQ(made.code, 0) << family << " seed " << s << ": " << made.err;
    // Round rooms whose discs nearly fill them are not all solved by either member of the
    // default planner (seed 2: no path in 60 s, nor from the main of 2026-11-27): there, no
    // path within 10 s is an answer, an abort or an internal error is not.
    const bool hard = family == "round-room";
    const test::Outcome planned = test::runMms("plan " + scene + " --seed " + s + " -o " + path +
                                               (hard ? " --time-limit 10" : ""));
    if (hard && planned.code == 1) {
      EXPECT_NE(planned.out.find("no path found"), std::string::npos) << planned.out;
      continue;
    }
    EXPECT_EQ(planned.code, 0) << family << " seed " << s << ": " << planned.err;
    if (planned.code != 0) continue;
    const test::Outcome checked = test::runMms("check " + scene + " " + path);
    EXPECT_EQ(checked.code, 0) << family << " seed " << s << ": " << checked.out << checked.err;
  }
}

INSTANTIATE_TEST_SUITE_P(Generators, EveryFamily, testing::ValuesIn(scenarioNames()), familyName);
