// Mistakes users make on the command line and in scene and path files: each gets one line
// that says what is wrong and where, exit 2 (or a note where the input is valid but likely
// not meant).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

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
  EXPECT_EQ(half.err, "mms: --n-theta: not an integer (see mms plan --help)\n");
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
  // Quiet silences progress, not a likely mistake in the input.
  const test::Outcome quiet = run("plan " + test::quote(deg) + " -q --time-limit 5");
  EXPECT_NE(quiet.err.find("angles are in radians"), std::string::npos) << quiet.err;
}

// Validate names each robot's shape: a disc by its radius, a polygon by its vertices.
TEST(CliInput, ValidateNamesDiscsByTheirRadius) {
  test::TempDir dir;
  const std::string scene = dir.path("box.json");
  ASSERT_EQ(run("scenario disc-box --seed 3 --robots 4 -o " + test::quote(scene)).code, 0);
  const test::Outcome r = run("validate " + test::quote(scene));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("robot 'disc-0': disc of radius 0.5, translate"), std::string::npos)
      << r.out;
  const test::Outcome polygons =
      run("validate " + test::quote(test::scenario("one-robot/bar-slot.json")));
  EXPECT_NE(polygons.out.find(" vertices, "), std::string::npos) << polygons.out;
  EXPECT_EQ(polygons.out.find("disc of radius"), std::string::npos) << polygons.out;
}

// GeoJSON and shapely write polygons as closed rings: the same polygon, read with a note.
TEST(CliInput, AClosedRingIsThePolygonWithANote) {
  test::TempDir dir;
  const std::string scene = dir.path("s.json"), closed = dir.path("closed.json");
  ASSERT_EQ(run("scenario open-clutter --seed 2 -o " + test::quote(scene)).code, 0);
  json s = readJson(scene);
  for (json& o : s["obstacles"]) o.push_back(o[0]);
  s["robots"][0]["shape"].push_back(s["robots"][0]["shape"][0]);
  std::ofstream(closed) << s.dump();
  const test::Outcome r = run("validate " + test::quote(closed));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(
      r.err.find(std::to_string(s["obstacles"].size() + 1) + " polygon(s) given as closed rings"),
      std::string::npos)
      << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  const test::Outcome written = run("import " + test::quote(closed) + " -q -o -");
  ASSERT_EQ(written.code, 0) << written.err;
  EXPECT_EQ(json::parse(written.out)["obstacles"], readJson(scene)["obstacles"]);
}

// A path for other robots names both lists.
TEST(CliInput, APathForOtherRobotsNamesThem) {
  test::TempDir dir;
  const std::string path = dir.file(
      "p.json",
      R"({"format": "mms-path/1", "robots": ["a", "b"], "waypoints": [[0, 0, 0, 1, 1, 0]]})");
  const test::Outcome r = run("check " + test::quote(test::scenario("one-robot/bar-slot.json")) +
                              " " + test::quote(path));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("robots: the path moves 2 robot(s) [a, b], the scene has 1 [bar]"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(lines(r.err), 1u);
}

// What a run prints reads as English and adds up: "1 round", no time "to the path" when there
// is none, a query's phases within its own time, and numbers in path files as declared.
TEST(CliInput, TheSummaryReadsRightAndAddsUp) {
  test::TempDir dir;
  const std::string scene = test::quote(test::scenario("one-robot/bar-slot.json"));
  const std::string path = dir.path("p.json");
  const test::Outcome one = run("plan " + scene + " --planner mms -o " + test::quote(path));
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_NE(one.out.find("; 1 round\n"), std::string::npos) << one.out;
  const json parameters = readJson(path)["parameters"];
  EXPECT_TRUE(parameters["n_theta"].is_number_integer()) << parameters;
  EXPECT_EQ(parameters["objective"], "length") << parameters;
  const test::Outcome none =
      run("plan " + test::quote(test::scenario("one-robot/zigzag-slot.json")) +
          " --planner mms --time-limit 1");
  EXPECT_EQ(none.code, 1);
  EXPECT_NE(none.out.find(" s = slices "), std::string::npos) << none.out;
  EXPECT_EQ(none.out.find("to the path"), std::string::npos) << none.out;
  const std::string queries = dir.file(
      "q.json",
      R"({"format": "mms-queries/1", "queries": [{"start": [-6, 0, 1.5], "goal": [6, 0, 1.5]},
          {"start": [6, 0, 1.5], "goal": [-6, 0, 1.5]}, {"start": [-6, 2, 1.5], "goal": [6, 3, 1.5]}]})");
  for (const std::string planner : {"mms", "auto"}) {
    const test::Outcome q =
        run("plan " + scene + " --planner " + planner + " --queries " + test::quote(queries));
    ASSERT_EQ(q.code, 0) << q.err;
    std::istringstream in(q.out);
    size_t checked = 0;
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("  time: ", 0) != 0) continue;
      std::istringstream l(line.substr(8));
      double seconds = 0, sum = 0;
      std::string word;
      l >> seconds >> word >> word >> word;  // "s to the path"
      l >> word;                             // "="
      for (double t; l >> word >> t;) {
        sum += t;
        if (!(l >> word) || word != "+") break;
      }
      EXPECT_LE(sum, seconds + 0.004) << planner << ": " << line;
      ++checked;
    }
    EXPECT_EQ(checked, 3u) << q.out;
  }
}

// A straight move between two poses at one angle ends without a turn: the optimiser tries
// shortcuts from the start and to the end.
TEST(CliInput, AStraightMoveGainsNoRotation) {
  test::TempDir dir;
  const std::string scene = dir.file("straight.json",
                                     R"({"format": "mms-scene/1", "bounds": [-5, -5, 5, 5],
          "obstacles": [[[3, 3], [4, 3], [4, 4], [3, 4]]],
          "robots": [{"name": "r", "shape": [[-0.5, -0.2], [0.5, -0.2], [0.5, 0.2], [-0.5, 0.2]],
                      "start": [0, 0, 0.3], "goal": [1, 0, 0.3]}]})");
  for (const std::string planner : {"mms", "auto"})
    for (int seed = 1; seed <= 3; ++seed) {
      const test::Outcome r = run("plan " + test::quote(scene) + " -q --planner " + planner +
                                  " --seed " + std::to_string(seed));
      ASSERT_EQ(r.code, 0) << r.err;
      const size_t at = r.out.find("rotation ");
      ASSERT_NE(at, std::string::npos) << r.out;
      EXPECT_LT(std::stod(r.out.substr(at + 9)), 1e-9) << planner << " seed " << seed << r.out;
    }
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

// A mistyped name is answered with the one likely meant: options, planners, commands,
// scenarios, a planner's parameters.
TEST(CliInput, AMistypedNameGetsADidYouMean) {
  const std::string scene = test::quote(test::scenario("one-robot/bar-slot.json"));
  const struct {
    std::string args, hint;
  } cases[] = {
      {"plan " + scene + " --timelimit 3", "did you mean '--time-limit'?"},
      {"plan " + scene + " --planner rrtconect", "did you mean 'rrtconnect'?"},
      {"plna " + scene, "'plna' is not a command; did you mean 'plan'?"},
      {"scenario bendd -o x.json", "did you mean 'bend'?"},
      {"bench " + scene + " --planners mms,rrtconect -o x", "did you mean 'rrtconnect'?"},
      {"plan " + scene + " --planner mms --n-thetaa 3", "did you mean '--n-theta'?"},
  };
  for (const auto& c : cases) {
    const test::Outcome r = run(c.args);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_NE(r.err.find(c.hint), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1u) << r.err;
  }
  // Nothing near: no guess.
  const test::Outcome far = run("plan " + scene + " --planner xyz");
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

// Every numeric option of every command, as its --help lists it, refuses NaN and infinity with
// exit 2 and one line naming it: CLI11's range checks let NaN through (every comparison with it
// is false), so `--time-limit nan` once planned "within nan s" and broke mms bench's records.
TEST(CliInput, EveryNumericOptionRefusesNanAndInfinity) {
  const std::vector<std::string> commands = {"validate", "check",    "render", "plan",
                                             "scenario", "assemble", "bench",  "bench-merge",
                                             "view",     "import",   "export", "lab"};
  const std::regex numeric("\\n  (--[a-z-]+) (NUMBER|FLOAT|INT|UINT|MB)");
  // A valid first argument, so that what is refused is the option (plan reads its planners'
  // parameters once the scene is known).
  const std::string scene = test::quote(test::scenario("one-robot/bar-slot.json"));
  size_t options = 0;
  for (const std::string& command : commands) {
    const std::string first = command == "scenario" ? "pacman"
                              : command == "lab"    ? "passages"
                                                    : scene;
    const std::string help = run(command + " --help").out;
    ASSERT_FALSE(help.empty()) << command;
    for (std::sregex_iterator m(help.begin(), help.end(), numeric), end; m != end; ++m) {
      const std::string option = (*m)[1];
      ++options;
      for (const char* value : {"nan", "inf", "-inf", "NaN"}) {
        const test::Outcome r = run(command + " " + first + " " + option + " " + value);
        EXPECT_EQ(r.code, 2) << command << " " << option << " " << value;
        EXPECT_EQ(lines(r.err), 1u) << command << " " << option << " " << value << ": " << r.err;
        EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
      }
    }
  }
  // plan's time and memory limits, its planners' numeric parameters, render's width, ...
  EXPECT_GT(options, 30u);
}

// Help reads as text: wrapped to the terminal's width ($COLUMNS where there is no terminal),
// types a person reads ("INT in [1, 2000]", not CLI11's "INT:INT in [1 - 2000]=1"), defaults
// after the description, mms plan's options in groups and the scenario families one a line.
TEST(CliInput, HelpIsWrappedGroupedAndReadsAsText) {
  const std::vector<std::string> commands = {
      "",      "validate", "check",  "render",      "plan",   "scenario", "assemble",
      "bench", "view",     "import", "bench-merge", "export", "lab"};
  const std::regex cli11Range(" in \\[[^\\]]* - "), typeEqualsDefault("[A-Z\\]]=\\S");
  for (const std::string& command : commands)
    for (const size_t width : {60, 100}) {
      const test::Outcome r = test::runCommand("COLUMNS=" + std::to_string(width) + " " +
                                               MMS_BINARY + " " + command + " --help");
      ASSERT_EQ(r.code, 0) << command;
      // The program's name, not the path it was started by, however long that is.
      EXPECT_NE(r.out.find("\nUsage: mms " + command), std::string::npos) << r.out;
      std::istringstream in(r.out);
      for (std::string line; std::getline(in, line);)
        EXPECT_LE(line.size(), width) << "mms " << command << " --help: " << line;
      EXPECT_EQ(r.out.find("UINT:UINT"), std::string::npos) << command;
      EXPECT_EQ(r.out.find(":{"), std::string::npos) << command;
      EXPECT_FALSE(std::regex_search(r.out, cli11Range)) << command;
      EXPECT_FALSE(std::regex_search(r.out, typeEqualsDefault)) << command;
    }
  const std::string plan = run("plan --help").out;
  size_t at = 0;
  for (const char* group :
       {"\nPlanner:\n", "\nLimits:\n", "\nOutputs:\n",
        "\nMMS (auto, mms, mms-ordered, mms-joint):\n", "\nThe default planner (auto):\n",
        "\nEvery planner: the path optimiser and the schedule:\n", "\nOMPL's planners:\n"}) {
    const size_t here = plan.find(group);
    ASSERT_NE(here, std::string::npos) << group << plan;
    EXPECT_GT(here, at) << group;
    at = here;
  }
  EXPECT_NE(plan.find("--time-limit NUMBER in [0.01, 1e+06]"), std::string::npos) << plan;
  EXPECT_NE(plan.find("Seconds before giving up (default 60)"), std::string::npos) << plan;
  const std::string scenario = run("scenario --help").out;
  EXPECT_NE(scenario.find("\n" + std::string(32, ' ') + "keyhole (--seed, --slack): a key passes"),
            std::string::npos)
      << scenario;
}

// A parameter whose default differs between planners says each default with its planners
// (--optimize is on for MMS's planners, off for OMPL's); one the planners share says one.
TEST(CliInput, PlanHelpGivesEachPlannersDefault) {
  std::string help;  // unwrapped: the help wraps its lines to the terminal
  for (const char c : run("plan --help").out)
    if (c != '\n' && !(c == ' ' && !help.empty() && help.back() == ' ')) help += c;
  const size_t at = help.find("--optimize INT");
  ASSERT_NE(at, std::string::npos) << help;
  const std::string line = help.substr(at, help.find("--objective", at) - at);
  EXPECT_NE(line.find("(default 1 for auto, mms, mms-ordered, mms-joint; 0 for every OMPL "
                      "planner)"),
            std::string::npos)
      << line;
  EXPECT_EQ(line.find("(default 1)"), std::string::npos) << line;
  const size_t restarts = help.find("--restarts INT");
  ASSERT_NE(restarts, std::string::npos);
  EXPECT_NE(help.find("(default 0)", restarts), std::string::npos);
}
