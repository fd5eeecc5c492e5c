#pragma once
// Helpers for tests: temporary files, running the mms binary, loading bundled scenarios.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "mms/Geometry.h"
#include "mms/Scene.h"
#include "scenarios/Generators.h"

namespace mms::test {

inline std::string sourceDir() { return MMS_SOURCE_DIR; }

#ifdef MMS_SANITIZED
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
/// Seeds a planner test runs: all of them normally, one under the sanitizers (10-20x slower).
inline int seedsToRun(int seeds) { return kSanitized ? 1 : seeds; }
/// A planner test's time limit: generous under the sanitizers.
inline double planSeconds(double seconds) { return kSanitized ? 10 * seconds : seconds; }
inline std::string scenario(const std::string& rel) { return sourceDir() + "/scenes/" + rel; }
/// The axis-aligned rectangle [x0, x1] x [y0, y1], counter-clockwise: the generators' own.
using mms::rect;

/// A bar (2 x 0.2) in a room (10 x 6) split by a wall 0.4 thick with a slot `slot` wide about
/// height 3: the bar passes lying across the wall (along x), not along it, when the slot is
/// wider than the bar.
inline Scene slottedBarScene(double slot) {
  Scene s;
  s.name = "slotted";
  s.bounds = {0, 0, 10, 6};
  s.obstacles = {rect(4.8, 0, 5.2, 3 - slot / 2), rect(4.8, 3 + slot / 2, 5.2, 6)};
  Robot bar;
  bar.name = "bar";
  bar.shape = rect(-1, -0.1, 1, 0.1);
  bar.start = {2, 3, 0};
  bar.goal = {8, 3, 0};
  s.robots = {bar};
  return s;
}

/// A wall across the whole box parts the left half from the right; robot "a" only translates
/// and has its goal across the wall, so no motion exists. The other robots (rigid squares,
/// `robots` in all) have room enough on the left.
inline Scene walledOffScene(size_t robots) {
  Scene s;
  s.name = "walled-off";
  s.bounds = {-10, -10, 10, 10};
  s.obstacles = {rect(-0.5, -10, 0.5, 10)};
  const Ring square = rect(-0.4, -0.4, 0.4, 0.4);
  s.robots.push_back({"a", square, {-5, 0, 0}, {5, 0, 0}, Motion::Translate});
  for (size_t r = 1; r < robots; ++r) {
    const double y = 2.5 * double(r);
    s.robots.push_back(
        {std::string(1, char('a' + r)), square, {-8, y, 0}, {-3, -y, 1}, Motion::Rigid});
  }
  return s;
}

/// A fresh directory per test process, removed at exit.
class TempDir {
 public:
  TempDir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "mms-test-XXXXXX").string();
    path_ = ::mkdtemp(tmpl.data());
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name, const std::string& content) const {
    const std::string p = (path_ / name).string();
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Outcome {
  int code = -1;
  std::string out, err;
};

/// Runs a shell command line, capturing stdout and stderr.
inline Outcome runCommand(const std::string& command) {
  TempDir dir;
  const std::string out = dir.path("out"), err = dir.path("err");
  const int status = std::system((command + " >" + out + " 2>" + err + " </dev/null").c_str());
  Outcome r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = readFile(out);
  r.err = readFile(err);
  return r;
}

/// Runs the mms binary with the given arguments (already quoted where needed).
inline Outcome runMms(const std::string& args) {
  return runCommand(std::string(MMS_BINARY) + " " + args);
}

inline std::string quote(const std::string& s) { return "'" + s + "'"; }

}  // namespace mms::test
