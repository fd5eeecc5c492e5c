// Mistakes users make on the command line and in scene and path files: each gets one line
// that says what is wrong and where, exit 2 (or a note where the input is valid but likely
// not meant).
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "Support.h"

using namespace mms;
using nlohmann::json;

namespace {

test::Outcome run(const std::string& args) { return test::runMms(args); }

size_t lines(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }

json readJson(const std::string& path) { return json::parse(test::readFile(path)); }

}  // namespace

// The command line allocates through jemalloc where the build found it (apps/CMakeLists.txt):
// a link that let glibc's malloc win the symbol lookup would cost 10-20 % of every plan, unseen.
// Without it (sanitized builds, MMS_JEMALLOC off) the allocator is the one the build chose.
TEST(CliInput, TheCommandLineAllocatesThroughJemallocWhereBuiltWithIt) {
  const test::Outcome r =
      test::runCommand("MALLOC_CONF=stats_print:true " + std::string(MMS_BINARY) + " --version");
  EXPECT_EQ(r.code, 0);
#ifdef MMS_CLI_JEMALLOC
  constexpr bool kJemalloc = true;
#else
  constexpr bool kJemalloc = false;
#endif
  EXPECT_EQ(r.err.find("jemalloc statistics") != std::string::npos, kJemalloc)
      << r.err.substr(0, 200);
}

TEST(CliInput, NegativeSeedAndNonNumericLimitsAreRefusedPlainly) {
  test::TempDir dir;
  const std::string scene = dir.path("s.json");
  ASSERT_EQ(run("scenario open-clutter --seed 2 -o " + test::quote(scene)).code, 0);
  const test::Outcome seed = run("plan " + test::quote(scene) + " --seed -1");
  EXPECT_EQ(seed.code, 2);
  EXPECT_NE(seed.err.find("--seed: '-1' is not a whole number from 0 up"), std::string::npos)
      << seed.err;
  const test::Outcome abc = run("plan " + test::quote(scene) + " --time-limit abc");
  EXPECT_EQ(abc.code, 2);
  EXPECT_EQ(abc.err.find("not in range"), std::string::npos) << abc.err;
  EXPECT_NE(abc.err.find("--time-limit: 'abc' is not a number"), std::string::npos) << abc.err;
  EXPECT_EQ(lines(abc.err), 1u);
  // An option checked by range alone says the same of text that is no number.
  const test::Outcome robots = run("scenario random --robots abc -o " + test::quote(dir.path("r")));
  EXPECT_EQ(robots.code, 2);
  EXPECT_NE(robots.err.find("--robots: 'abc' is not a number"), std::string::npos) << robots.err;
  // A planner parameter out of its type says so in the same form.
  const test::Outcome half = run("plan " + test::quote(scene) + " --n-theta 1.5");
  EXPECT_EQ(half.code, 2);
  EXPECT_EQ(half.err, "mms: --n-theta: not an integer (see mms --help)\n");
  // plan and bench take the same limits.
  for (const std::string& cmd :
       std::vector<std::string>{"plan " + test::quote(scene), "bench " + test::quote(scene)}) {
    const test::Outcome zero = run(cmd + " --time-limit 0 -o " + test::quote(dir.path("out")));
    EXPECT_EQ(zero.code, 2) << cmd;
    EXPECT_NE(zero.err.find("--time-limit"), std::string::npos) << zero.err;
  }
}

TEST(CliInput, AFolderIsNotAScene) {
  test::TempDir dir;
  const test::Outcome r = run("validate " + test::quote(dir.path("")));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("is a folder, not a file"), std::string::npos) << r.err;
  EXPECT_EQ(lines(r.err), 1u);
}

TEST(CliInput, AnglesBeyondAFullTurnGetANoteAboutRadians) {
  test::TempDir dir;
  const std::string scene = dir.path("s.json"), deg = dir.path("deg.json");
  ASSERT_EQ(run("scenario open-clutter --seed 2 -o " + test::quote(scene)).code, 0);
  json s = readJson(scene);
  const test::Outcome plain = run("validate " + test::quote(scene));
  EXPECT_EQ(plain.err.find("radians"), std::string::npos);
  s["robots"][0]["start"][2] = 90;  // degrees by mistake, and still a free pose here
  std::ofstream(deg) << s.dump();
  const test::Outcome r = run("validate " + test::quote(deg));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("robots[0].start: angle 90 is more than a full turn; angles are in radians"),
            std::string::npos)
      << r.err;
}

TEST(CliInput, AShapeInWorldCoordinatesIsToldItsFrame) {
  test::TempDir dir;
  const std::string scene = dir.path("s.json"), world = dir.path("world.json");
  ASSERT_EQ(run("scenario open-clutter --seed 2 -o " + test::quote(scene)).code, 0);
  json s = readJson(scene);
  json& r = s["robots"][0];
  for (json& p : r["shape"]) {  // the shape where the robot stands, not about its origin
    p[0] = p[0].get<double>() + r["start"][0].get<double>();
    p[1] = p[1].get<double>() + r["start"][1].get<double>();
  }
  std::ofstream(world) << s.dump();
  const test::Outcome bad = run("validate " + test::quote(world));
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("robots[0].start: robot"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("given in the robot's own frame"), std::string::npos) << bad.err;
  EXPECT_EQ(lines(bad.err), 1u);
}

TEST(CliInput, APathEndingElsewhereIsToldWhereAndWhereTheGoalIs) {
  test::TempDir dir;
  const std::string scene = dir.path("s.json"), path = dir.path("p.json"),
                    moved = dir.path("moved.json");
  ASSERT_EQ(run("scenario open-clutter --seed 2 -o " + test::quote(scene)).code, 0);
  ASSERT_EQ(run("plan " + test::quote(scene) + " -q -o " + test::quote(path)).code, 0);
  json p = readJson(path);
  p["waypoints"].back()[0] = p["waypoints"].back()[0].get<double>() + 0.5;
  std::ofstream(moved) << p.dump();
  const test::Outcome r = run("check " + test::quote(scene) + " " + test::quote(moved));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("rejected: the last waypoint puts robot"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", not at its goal ("), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("segment"), std::string::npos) << r.out;
}
