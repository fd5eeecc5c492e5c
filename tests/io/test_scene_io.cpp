// Scene and path loading: every class of bad input gets exit code 2 and one line naming the
// file, the JSON location and the problem.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>

#include "Support.h"
#include "geometry/PolygonOps.h"
#include "io/Json.h"
#include "io/PathIO.h"
#include "io/SceneIO.h"
#include "mms/Errors.h"

using nlohmann::json;
using namespace mms;
using namespace mms::test;

namespace {

json square(double x0, double y0, double s) {
  return json::array({{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}});
}

// A valid two-robot scene; each bad-input case breaks one thing in it.
json baseScene() {
  return {{"format", "mms-scene/1"},
          {"name", "base"},
          {"bounds", {0, 0, 10, 10}},
          {"obstacles", json::array({square(4, 4, 2)})},
          {"robots", json::array({{{"name", "a"},
                                   {"shape", square(-0.5, -0.5, 1)},
                                   {"start", {1, 1, 0}},
                                   {"goal", {9, 9, 0}},
                                   {"motion", "rigid"}},
                                  {{"name", "b"},
                                   {"shape", square(-0.5, -0.5, 1)},
                                   {"start", {9, 1, 0}},
                                   {"goal", {1, 9, 1.0}}}})}};
}

struct BadCase {
  const char* label;
  std::function<void(json&)> mutate;  // empty: `text` is the whole file
  const char* text;
  const char* location;  // expected in the message after "FILE: "
  const char* problem;   // expected substring of the message
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.label; }

std::string deepJson(int depth) { return std::string(depth, '[') + std::string(depth, ']'); }

}  // namespace

class BadScene : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadScene, ExitsTwoWithOneLineNamingFileFieldAndProblem) {
  const BadCase& c = GetParam();
  TempDir dir;
  std::string content;
  if (c.mutate) {
    json j = baseScene();
    c.mutate(j);
    content = j.dump();
  } else {
    content = c.text;
  }
  const std::string file = dir.file("scene.json", content);
  const Outcome r = runMms("validate " + quote(file));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.out, "");
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  EXPECT_EQ(r.err.rfind(file + ": " + c.location + ": ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(c.problem), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(
    Classes, BadScene,
    ::testing::Values(
        BadCase{"not_json", {}, "{\"format\": mms", "(document)", "not valid JSON"},
        BadCase{"empty_file", {}, "", "(document)", "not valid JSON"},
        BadCase{"not_utf8", {}, "{\"format\": \"\xff\xfe\"}", "(document)", "not valid JSON"},
        BadCase{"top_not_object", {}, "[1,2]", "(document)", "expected an object, found an array"},
        BadCase{"missing_format", [](json& j) { j.erase("format"); }, nullptr, "format", "missing"},
        BadCase{"wrong_format", [](json& j) { j["format"] = "mms-scene/9"; }, nullptr, "format",
                "unsupported format 'mms-scene/9'"},
        BadCase{"format_type", [](json& j) { j["format"] = 1; }, nullptr, "format",
                "expected a string, found a number"},
        BadCase{"unknown_field", [](json& j) { j["obstacle"] = json::array(); }, nullptr,
                "obstacle", "unknown field"},
        BadCase{"missing_bounds", [](json& j) { j.erase("bounds"); }, nullptr, "bounds", "missing"},
        BadCase{"bounds_short",
                [](json& j) {
                  j["bounds"] = {0, 0, 10};
                },
                nullptr, "bounds", "expected 4 elements, found 3"},
        BadCase{"bounds_type", [](json& j) { j["bounds"] = "big"; }, nullptr, "bounds",
                "expected an array, found a string"},
        BadCase{"bounds_element_type", [](json& j) { j["bounds"][2] = true; }, nullptr, "bounds[2]",
                "expected a number, found a boolean"},
        BadCase{"bounds_inverted",
                [](json& j) {
                  j["bounds"] = {10, 0, 0, 10};
                },
                nullptr, "bounds", "inverted"},
        BadCase{"bounds_empty",
                [](json& j) {
                  j["bounds"] = {0, 5, 10, 5};
                },
                nullptr, "bounds", "inverted or empty"},
        BadCase{"huge_number", [](json& j) { j["bounds"][2] = 1e300; }, nullptr, "bounds[2]",
                "out of range"},
        BadCase{"polygon_two_vertices",
                [](json& j) {
                  j["obstacles"][0] = {{0, 0}, {1, 1}};
                },
                nullptr, "obstacles[0]", "expected at least 3 elements, found 2"},
        BadCase{"point_three_coords",
                [](json& j) {
                  j["obstacles"][0][1] = {1, 1, 1};
                },
                nullptr, "obstacles[0][1]", "expected 2 elements"},
        BadCase{"zero_area",
                [](json& j) {
                  j["obstacles"][0] = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
                },
                nullptr, "obstacles[0]", "zero area"},
        BadCase{"repeated_vertex",
                [](json& j) {
                  j["obstacles"][0] = {{4, 4}, {6, 4}, {6, 6}, {6, 4}, {4, 6}};
                },
                nullptr, "obstacles[0]", "repeated vertex (vertices 1 and 3 coincide)"},
        BadCase{"self_intersecting",
                [](json& j) {
                  j["robots"][0]["shape"] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
                },
                nullptr, "robots[0].shape", "polygon self-intersects (edges 1 and 3)"},
        BadCase{"fold_back",
                [](json& j) {
                  j["obstacles"][0] = {{4, 4}, {6, 4}, {5, 4}, {5, 6}};
                },
                nullptr, "obstacles[0]", "self-intersects"},
        BadCase{"no_robots", [](json& j) { j["robots"] = json::array(); }, nullptr, "robots",
                "expected at least 1 elements, found 0"},
        BadCase{"robot_not_object", [](json& j) { j["robots"][1] = 7; }, nullptr, "robots[1]",
                "expected an object, found a number"},
        BadCase{"missing_shape", [](json& j) { j["robots"][0].erase("shape"); }, nullptr,
                "robots[0].shape", "missing"},
        BadCase{"start_short",
                [](json& j) {
                  j["robots"][0]["start"] = {1, 1};
                },
                nullptr, "robots[0].start", "expected 3 elements, found 2"},
        BadCase{"huge_angle", [](json& j) { j["robots"][0]["goal"][2] = 1e9; }, nullptr,
                "robots[0].goal[2]", "out of range"},
        BadCase{"start_outside_bounds",
                [](json& j) {
                  j["robots"][0]["start"] = {0.2, 1, 0};
                },
                nullptr, "robots[0].start", "robot 'a' is not inside the bounds"},
        // Found by fuzzing: a vertex off a line by 1e-320 put the shrunk shape's vertex at
        // infinity, which then reached CGAL's exact predicates.
        BadCase{"robot_vertex_off_by_denormal",
                [](json& j) {
                  j["robots"][0]["shape"] = {{0, 0},     {1, 0},   {1, 1},         {1.5, 1},
                                             {1.5, 1.5}, {1, 1.5}, {1.01e-320, 2}, {0, 2}};
                },
                nullptr, "robots[0].shape", "smaller than the contact tolerance"},
        BadCase{"robot_larger_than_bounds",
                [](json& j) { j["robots"][0]["shape"] = square(-6, -6, 12); }, nullptr,
                "robots[0].start", "not inside the bounds"},
        BadCase{"start_in_obstacle",
                [](json& j) {
                  j["robots"][0]["start"] = {4.2, 5, 0};
                },
                nullptr, "robots[0].start", "robot 'a' collides with obstacles[0]"},
        BadCase{"goal_in_obstacle", [](json& j) { j["robots"][1]["goal"] = {5, 6.3, 0.3}; },
                nullptr, "robots[1].goal", "robot 'b' collides with obstacles[0]"},
        BadCase{"robots_overlap_at_goal", [](json& j) { j["robots"][1]["goal"] = {8.5, 8.6, 0}; },
                nullptr, "robots[1].goal", "robot 'b' collides with robot 'a'"},
        BadCase{"duplicate_names", [](json& j) { j["robots"][1]["name"] = "a"; }, nullptr,
                "robots[1].name", "duplicate robot name 'a'"},
        BadCase{"empty_name", [](json& j) { j["robots"][1]["name"] = ""; }, nullptr,
                "robots[1].name", "empty"},
        BadCase{"unknown_motion", [](json& j) { j["robots"][0]["motion"] = "fly"; }, nullptr,
                "robots[0].motion", "unknown motion kind 'fly'"},
        BadCase{"translate_goal_angle", [](json& j) { j["robots"][1]["motion"] = "translate"; },
                nullptr, "robots[1].goal[2]", "a translate robot keeps its angle"},
        BadCase{"robot_unknown_field", [](json& j) { j["robots"][0]["speed"] = 3; }, nullptr,
                "robots[0].speed", "unknown field"},
        // Exact discs: a radius that is no radius, a robot that is both, discs that overlap.
        BadCase{"disc_radius_zero",
                [](json& j) {
                  j["robots"][0].erase("shape");
                  j["robots"][0]["disc"] = 0;
                },
                nullptr, "robots[0].disc", "radius must be positive"},
        BadCase{"disc_radius_negative",
                [](json& j) { j["obstacles"].push_back({{"center", {2, 8}}, {"radius", -0.5}}); },
                nullptr, "obstacles[1].radius", "radius must be positive (got -0.5)"},
        BadCase{"disc_radius_not_a_number",
                [](json& j) { j["obstacles"].push_back({{"center", {2, 8}}, {"radius", "big"}}); },
                nullptr, "obstacles[1].radius", "expected a number"},
        BadCase{"disc_radius_infinite", nullptr,
                R"({"format": "mms-scene/1", "bounds": [0, 0, 10, 10], "obstacles": [],
                    "robots": [{"disc": 1e300, "start": [5, 5, 0], "goal": [5, 5, 0]}]})",
                "robots[0].disc", "out of range"},
        BadCase{"disc_radius_below_tolerance",
                [](json& j) {
                  j["robots"][0].erase("shape");
                  j["robots"][0]["disc"] = 1e-9;
                },
                nullptr, "robots[0].disc", "not above twice the contact tolerance"},
        BadCase{"disc_and_shape",
                [](json& j) { j["robots"][0]["disc"] = 0.5; }, nullptr, "robots[0]",
                "a shape or a disc, not both"},
        BadCase{"disc_obstacle_unknown_field",
                [](json& j) {
                  j["obstacles"].push_back({{"center", {2, 8}}, {"radius", 1}, {"colour", 1}});
                },
                nullptr, "obstacles[1].colour", "unknown field"},
        BadCase{"disc_robots_overlap_at_start",
                [](json& j) {
                  for (int i : {0, 1}) {
                    j["robots"][i].erase("shape");
                    j["robots"][i]["disc"] = 0.5;
                    j["robots"][i]["goal"][2] = 0;
                  }
                  j["robots"][1]["start"] = {1.99, 1, 0};
                },
                nullptr, "robots[1].start", "robot 'b' collides with robot 'a'"},
        BadCase{"disc_robot_in_disc_obstacle",
                [](json& j) {
                  j["obstacles"].push_back({{"center", {2, 8}}, {"radius", 1}});
                  j["robots"][0]["start"] = {2.5, 7.5, 0};
                },
                nullptr, "robots[0].start", "robot 'a' collides with obstacles[1]"}),
    [](const auto& info) { return std::string(info.param.label); });

// The nesting limit counts brackets of arrays and objects, not those inside strings (escaped
// quotes included): 64 levels are read, 65 are refused.
TEST(BadSceneText, NestingIsCountedOutsideStrings) {
  auto depth = [](int n, const std::string& inside) {
    return std::string(size_t(n), '[') + inside + std::string(size_t(n), ']');
  };
  EXPECT_NO_THROW(json_in::parseText(depth(64, "1"), "f.json"));
  try {
    json_in::parseText(depth(65, "1"), "f.json");
    ADD_FAILURE() << "65 levels were read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "f.json: (document): JSON nested deeper than 64 levels");
  }
  const std::string brackets = "\"a \\\" " + std::string(200, '[') + std::string(200, '{') + "\"";
  const json_in::Json j = json_in::parseText(depth(60, brackets), "f.json");
  EXPECT_EQ(j.dump().size(), depth(60, brackets).size());
}

// JSON lets a key appear twice and nlohmann keeps the last: two "bounds" silently dropped the
// first. Every reader refuses a key given twice in one object, naming where; the same key in
// two objects, and values that repeat, are fine.
TEST(BadSceneText, AKeyGivenTwiceInOneObjectIsRefusedNamingWhere) {
  const std::pair<const char*, const char*> cases[] = {
      {R"({"format": "mms-scene/1", "bounds": [0, 0, 1, 1], "bounds": [0, 0, 9, 9]})", "bounds"},
      {R"({"robots": [{"name": "a"}, {"name": "b", "start": [0, 0, 0], "name": "c"}]})",
       "robots[1].name"},
      {R"({"a": [[1, 2], [3, {"x": 1, "y": {"z": 1, "z": 2}}]]})", "a[1][1].y.z"},
  };
  for (const auto& [text, where] : cases) {
    try {
      json_in::parseText(text, "f.json");
      ADD_FAILURE() << text << " was read";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                std::string("f.json: ") + where + ": given twice (a key may appear once)");
    }
  }
  std::string many = "{";
  for (int k = 0; k < 100; ++k) many += "\"k" + std::to_string(k) + "\": 1, ";
  EXPECT_NO_THROW(json_in::parseText(many + "\"k100\": 1}", "f.json"));
  EXPECT_THROW(json_in::parseText(many + "\"k7\": 1}", "f.json"), InputError);
  const json_in::Json same = json_in::parseText(R"([{"a": 1}, {"a": 1, "b": {"a": 1}}])", "f.json");
  EXPECT_EQ(same.dump(), R"([{"a":1},{"a":1,"b":{"a":1}}])");
  // A scene file through the command line: exit 2 and the one line.
  const test::TempDir dir;
  const std::string file = dir.file("dup.json", cases[0].first);
  const Outcome r = runMms("validate " + quote(file));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, file + ": bounds: given twice (a key may appear once)\n");
}

// Cases whose text is built at run time.
TEST(BadSceneText, DeepNestingAndOverflow) {
  TempDir dir;
  {
    const std::string f = dir.file("deep.json", deepJson(100000));
    const Outcome r = runMms("validate " + quote(f));
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("nested deeper than 64 levels"), std::string::npos) << r.err;
  }
  {
    json j = baseScene();
    std::string text = j.dump();
    const std::string from = "\"bounds\":[0,0,10,10]";
    ASSERT_NE(text.find(from), std::string::npos);
    text.replace(text.find(from), from.size(), "\"bounds\":[0,0,1e999,10]");
    const std::string f = dir.file("overflow.json", text);
    const Outcome r = runMms("validate " + quote(f));
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
    EXPECT_NE(r.err.find("not valid JSON: number overflow parsing '1e999'"), std::string::npos)
        << r.err;
  }
}

TEST(BadSceneText, UnreadableFiles) {
  TempDir dir;
  Outcome r = runMms("validate " + quote(dir.path("missing.json")));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("missing.json: (file): cannot open for reading"), std::string::npos)
      << r.err;
  r = runMms("validate " + quote(dir.path("")));  // a directory
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  // A picture or a program given as a scene: said to be binary, not a JSON syntax error at
  // column 1.
  const std::string png = dir.file("scene.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
  r = runMms("validate " + quote(png));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("scene.png: (document): not a text file (byte 6 is binary data)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
}

// `-` reads the scene or the path from standard input, as `-o -` writes standard output.
TEST(SceneLoad, DashReadsStandardInput) {
  TempDir dir;
  const std::string scene = quote(scenario("one-robot/bar-slot.json")),
                    path = quote(dir.path("p.json"));
  ASSERT_EQ(runMms("plan " + scene + " -q --planner mms -o " + path).code, 0);
  // Bracketed: the redirections runCommand adds are the pipeline's, not mms's alone.
  const std::string mms = quote(MMS_BINARY);
  Outcome r = runCommand("(cat " + path + " | " + mms + " check " + scene + " -)");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("certified collision-free"), std::string::npos) << r.out;
  r = runCommand("(cat " + scene + " | " + mms + " check - " + path + ")");
  EXPECT_EQ(r.code, 0) << r.err;
  r = runCommand("(echo '{' | " + mms + " validate -)");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("-: (document): not valid JSON", 0), 0u) << r.err;
}

TEST(SceneLoad, NormalisesOrientationAndAcceptsTouchingStart) {
  json j = baseScene();
  // Clockwise obstacle, and robot a's start touching the obstacle's left side exactly.
  j["obstacles"][0] = {{4, 4}, {4, 6}, {6, 6}, {6, 4}};
  j["robots"][0]["start"] = {3.5, 5, 0};
  const Scene s = parseScene(j, "inline");
  ASSERT_EQ(s.obstacles.size(), 1u);
  EXPECT_GT(signedArea2(s.obstacles[0]), 0);
  EXPECT_EQ(s.robots[0].start.x, 3.5);
  EXPECT_EQ(s.robots[1].motion, Motion::Rigid);  // default
  // Pushed in by ten tolerances it collides.
  j["robots"][0]["start"] = {3.5 + 10 * s.tolerance(), 5, 0};
  EXPECT_THROW(parseScene(j, "inline"), InputError);
}

// Discs that touch (radius 0.5 at spacing 1, in any direction, and along a wall) load: the
// checker tests the discs, not polygons around them. They save and load as discs.
TEST(SceneLoad, TouchingDiscsLoadAndRoundTripAsDiscs) {
  json j = baseScene();
  j["obstacles"].push_back({{"center", {7, 2}}, {"radius", 0.5}});
  j["robots"] = json::array();
  const double a = 0.7;  // not a multiple of any polygon's edge angle
  const double xs[] = {0.5, 1.5, 1.5 + std::cos(a), 7, 4};
  const double ys[] = {0.5, 0.5, 0.5 + std::sin(a), 3, 2};
  for (int i = 0; i < 5; ++i)
    j["robots"].push_back({{"name", "disc-" + std::to_string(i)},
                           {"disc", 0.5},
                           {"start", {xs[i], ys[i], 0}},
                           {"goal", {xs[i], ys[i] + 6, 0}}});
  const Scene s = parseScene(j, "touching.json");
  ASSERT_EQ(s.robots.size(), 5u);
  EXPECT_EQ(s.robots[2].disc, 0.5);
  EXPECT_EQ(s.robots[2].motion, Motion::Translate) << "a disc translates unless told";
  ASSERT_NE(s.obstacleDisc(1), nullptr);
  EXPECT_EQ(s.obstacleDisc(0), nullptr);
  const Scene back = parseScene(sceneToJson(s), "again.json");
  EXPECT_EQ(sceneToJson(back), sceneToJson(s));
  EXPECT_EQ(sceneToJson(s)["robots"][0].count("shape"), 0u);
  EXPECT_EQ(sceneToJson(s)["obstacles"][1]["radius"], 0.5);
}

TEST(SceneLoad, RoundTripsThroughSave) {
  TempDir dir;
  const Scene s = parseScene(baseScene(), "inline");
  const std::string f = dir.path("saved.json");
  saveScene(s, f);
  const Scene t = loadScene(f);
  EXPECT_EQ(t.name, s.name);
  ASSERT_EQ(t.robots.size(), 2u);
  EXPECT_EQ(t.robots[1].goal.theta, 1.0);
  EXPECT_EQ(t.obstacles[0].size(), 4u);
}

TEST(ValidateCommand, PrintsSummaryForBundledScenes) {
  for (const char* s :
       {"one-robot/bar-slot.json", "two-robots/niche-swap.json", "translating/cup.json"}) {
    const Outcome r = runMms("validate " + quote(scenario(s)));
    EXPECT_EQ(r.code, 0) << s << ": " << r.err;
    EXPECT_NE(r.out.find("valid mms-scene/1 scene"), std::string::npos) << r.out;
  }
}

// ---- paths ----

class BadPath : public ::testing::Test {
 protected:
  TempDir dir;
  std::string scene = scenario("two-robots/niche-swap.json");
  json base = json::parse(readFile(scenario("two-robots/niche-swap.path.json")));
  Outcome check(const json& path) {
    return runMms("check " + quote(scene) + " " + quote(dir.file("p.json", path.dump())));
  }
  void expectBad(const json& path, const std::string& where, const std::string& problem) {
    const Outcome r = check(path);
    EXPECT_EQ(r.code, 2) << r.err << r.out;
    EXPECT_NE(r.err.find(": " + where + ": "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(problem), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  }
};

TEST_F(BadPath, EachProblemIsNamed) {
  json p = base;
  p["format"] = "mms-path/2";
  expectBad(p, "format", "unsupported format");
  p = base;
  p["scene"] = "other";
  expectBad(p, "scene", "path is for scene 'other', not 'niche-swap'");
  p = base;
  p["robots"] = {"right", "left"};
  expectBad(p, "robots[0]", "expected robot 'left'");
  p = base;
  p["robots"] = {"left"};
  expectBad(p, "robots", "the path moves 1 robot(s) [left], the scene has 2 [left, right]");
  p = base;
  p["waypoints"] = json::array();
  expectBad(p, "waypoints", "expected at least 1 elements");
  p = base;
  p["waypoints"][2] = {1, 0.65, 0, 4.8, 2.2};
  expectBad(p, "waypoints[2]", "expected 6 elements, found 5");
  p = base;
  p["waypoints"][1][4] = "x";
  expectBad(p, "waypoints[1][4]", "expected a number, found a string");
  p = base;
  p.erase("waypoints");
  expectBad(p, "waypoints", "missing");
  const Outcome r = runMms("check " + quote(scene) + " " + quote(dir.file("bad.json", "not json")));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("not valid JSON"), std::string::npos);
}

TEST_F(BadPath, ExtraKeysSurviveRoundTrip) {
  const Scene s = loadScene(scene);
  json p = base;
  p["planner"] = "hand";
  Path path = parsePath(p, "inline", s);
  EXPECT_EQ(path.extra["planner"], "hand");
  EXPECT_EQ(pathToJson(path, s)["planner"], "hand");
  EXPECT_EQ(pathToJson(path, s)["waypoints"], base["waypoints"]);
}

TEST(Cli, UsageErrorsExitTwoWithOneLine) {
  for (const char* args : {"", "frobnicate", "check onlyone", "render x.json", "validate a b c",
                           "render --width -3 a.json -o x.svg"}) {
    const Outcome r = runMms(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << args << ": " << r.err;
  }
  const Outcome help = runMms("--help");
  EXPECT_EQ(help.code, 0);
  for (const char* c : {"validate", "check", "render"})
    EXPECT_NE(help.out.find(c), std::string::npos);
  const Outcome sub = runMms("check --help");
  EXPECT_EQ(sub.code, 0);
  EXPECT_NE(sub.out.find("--max-evaluations"), std::string::npos);
}

// Found by fuzzing: a newline inside a string the message quotes broke the one-line rule for
// callers of the library (the command line flattened it, other callers did not).
TEST(SceneErrors, MessagesStayOneLineWhateverTheInputQuotes) {
  json j = baseScene();
  j["format"] = "mms-sc\ne/1\r";
  j["robots"][0]["name"] = "bad\nname";
  try {
    mms::parseScene(j, "in.json");
    FAIL() << "accepted";
  } catch (const mms::InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_EQ(m.find('\r'), std::string::npos) << m;
    EXPECT_NE(m.find("mms-sc?e/1?"), std::string::npos) << m;
  }
}

namespace {

// n unit squares on a grid `spacing` apart, each going to the mirrored cell.
json gridScene(size_t n, double spacing) {
  json robots = json::array();
  const size_t cols = size_t(std::ceil(std::sqrt(double(n))));
  for (size_t i = 0; i < n; ++i) {
    const double x = spacing * double(i % cols + 1), y = spacing * double(i / cols + 1);
    std::string name = "d";
    name += std::to_string(i);  // not "d" + ...: GCC 12 warns there (-Wrestrict, a false positive)
    robots.push_back({{"name", name},
                      {"shape", square(-0.5, -0.5, 1)},
                      {"start", {x, y, 0}},
                      {"goal", {y, x, 0}},
                      {"motion", "translate"}});
  }
  const double side = spacing * double(cols + 2);
  return {{"format", "mms-scene/1"},
          {"bounds", {0, 0, side, side}},
          {"obstacles", json::array()},
          {"robots", robots}};
}

}  // namespace

TEST(SceneLoad, HundredsOfRobotsLoadAndTwoThatOverlapAreNamed) {
  const Scene s = parseScene(gridScene(500, 2), "grid.json");
  EXPECT_EQ(s.robots.size(), 500u);
  json j = gridScene(500, 2);
  // Robot 321 put onto robot 123's start: the pair is named, whatever their order in the sweep.
  j["robots"][321]["start"] = j["robots"][123]["start"];
  try {
    parseScene(j, "grid.json");
    FAIL() << "overlapping robots accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("robots[321].start"), std::string::npos) << what;
    EXPECT_NE(what.find("'d321' collides with robot 'd123'"), std::string::npos) << what;
  }
}

TEST(SceneLoad, ARunawayCountOfRobotsIsRefusedWithOneLine) {
  json j = baseScene();
  j["robots"] = json::array();
  const json robot = baseScene()["robots"][0];
  for (size_t i = 0; i <= kMaxRobots; ++i) j["robots"].push_back(robot);
  try {
    parseScene(j, "big.json");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("robots"), std::string::npos) << what;
    EXPECT_NE(what.find("too many"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}
