// Where commands write: every command that writes one file writes through a symbolic link
// (the link stays, the file it names gets the content), to standard output for "-" (the file
// alone there, the command's report on stderr), and into what a path names when that is no
// regular file (a pipe behind /dev/stdout).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "Support.h"

using namespace mms;

namespace {

namespace fs = std::filesystem;

struct Writer {
  std::string name;
  std::string args;    // OUT stands for the file written
  std::string begins;  // what the file it writes begins with
  bool same = true;    // the same file on every run (a run summary holds times)
};

std::vector<Writer> writers() {
  const std::string scene = test::quote(test::scenario("one-robot/bar-slot.json")),
                    path = test::quote(test::scenario("one-robot/bar-slot.path.json")),
                    cup = test::quote(test::scenario("translating/cup.json"));
  return {
      {"plan -o", "plan " + scene + " --planner mms -q -o OUT", "{"},
      {"plan --svg", "plan " + scene + " --planner mms -q --svg OUT", "<?xml"},
      {"plan --stats-json", "plan " + scene + " --planner mms -q --stats-json OUT", "{", false},
      {"render", "render " + scene + " " + path + " -o OUT", "<?xml"},
      {"view", "view " + scene + " " + path + " -o OUT", "<!DOCTYPE html>"},
      {"scenario", "scenario bend --seed 3 -o OUT", "{"},
      {"import", "import " + scene + " -q -o OUT", "{"},
      {"export ompl-path", "export " + scene + " " + path + " --to ompl-path -q -o OUT", "-"},
      {"export discopygal", "export " + scene + " --to discopygal --force -q -o OUT", "{"},
      {"assemble --svg", "assemble " + cup + " -q -o ASSEMBLY --svg OUT", "<?xml"},
  };
}

std::string with(std::string args, const std::string& out, const test::TempDir& dir) {
  args.replace(args.find("OUT"), 3, out);
  if (const size_t at = args.find("ASSEMBLY"); at != std::string::npos)
    args.replace(at, 8, test::quote(dir.path("assembly-" + std::to_string(::getpid()))));
  return args;
}

bool begins(const std::string& text, const std::string& prefix) {
  // An OMPL.app path begins with a number (its sign, here).
  if (prefix == "-") return !text.empty() && (text[0] == '-' || std::isdigit(text[0]));
  return text.rfind(prefix, 0) == 0;
}

}  // namespace

TEST(Outputs, EveryCommandWritesThroughASymbolicLinkAndKeepsIt) {
  for (const Writer& w : writers()) {
    test::TempDir dir;
    const std::string real = dir.file("real", "old"), link = dir.path("link");
    fs::create_symlink("real", link);
    const test::Outcome r = test::runMms(with(w.args, test::quote(link), dir));
    ASSERT_EQ(r.code, 0) << w.name << ": " << r.err;
    EXPECT_TRUE(fs::is_symlink(link)) << w.name << ": the link was replaced";
    const std::string content = test::readFile(real);
    EXPECT_TRUE(begins(content, w.begins)) << w.name << ": " << content.substr(0, 80);
    // Nothing else was left in the folder (a temporary file).
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path("")), fs::directory_iterator()),
              w.name == "assemble --svg" ? 3 : 2)
        << w.name;
  }
}

TEST(Outputs, DashIsStandardOutputAndTheReportGoesToStandardError) {
  for (const Writer& w : writers()) {
    test::TempDir dir;
    const std::string file = dir.path("file");
    const test::Outcome toFile = test::runMms(with(w.args, test::quote(file), dir));
    ASSERT_EQ(toFile.code, 0) << w.name << ": " << toFile.err;
    const test::Outcome r = test::runMms(with(w.args, "-", dir));
    ASSERT_EQ(r.code, 0) << w.name << ": " << r.err;
    EXPECT_TRUE(begins(r.out, w.begins)) << w.name << ": " << r.out.substr(0, 80);
    if (w.same) {
      EXPECT_EQ(r.out, test::readFile(file)) << w.name;
    }
    EXPECT_FALSE(fs::exists("-") && fs::is_regular_file("-")) << w.name << ": wrote a file '-'";
  }
  // A report that is not quieted moves out of the data.
  const std::string scene = test::quote(test::scenario("one-robot/bar-slot.json"));
  const test::Outcome plan = test::runMms("plan " + scene + " --planner mms -o -");
  ASSERT_EQ(plan.code, 0) << plan.err;
  EXPECT_EQ(plan.out.rfind("{\"format\":\"mms-path/1\"", 0), 0u) << plan.out.substr(0, 80);
  EXPECT_NE(plan.err.find("mms found a path"), std::string::npos) << plan.err;
  EXPECT_EQ(plan.err.find("no path file written"), std::string::npos) << plan.err;
  // Without -o the path goes nowhere, and the report says so.
  const test::Outcome nowhere = test::runMms("plan " + scene + " --planner mms");
  ASSERT_EQ(nowhere.code, 0) << nowhere.err;
  EXPECT_NE(nowhere.out.find("no path file written: -o FILE writes one"), std::string::npos)
      << nowhere.out;
}

TEST(Outputs, APathNamingAPipeIsWrittenDirectly) {
  const std::string scene = test::quote(test::scenario("one-robot/bar-slot.json"));
  for (const std::string target : {"/dev/stdout", "/proc/self/fd/1"}) {
    // Bracketed: the redirections runCommand adds are the pipeline's, not cat's alone.
    const test::Outcome r = test::runCommand(std::string("(") + MMS_BINARY + " render " + scene +
                                             " -o " + target + " | cat)");
    ASSERT_EQ(r.code, 0) << target << ": " << r.err;
    EXPECT_EQ(r.out.rfind("<?xml", 0), 0u) << target << ": " << r.out.substr(0, 80);
    EXPECT_NE(r.out.find("</svg>"), std::string::npos) << target;
  }
  EXPECT_TRUE(fs::is_symlink("/dev/stdout")) << "a run replaced the system's /dev/stdout";
  // A file behind a descriptor is written as the descriptor writes: appended, not replaced.
  test::TempDir dir;
  const std::string log = dir.file("log", "before\n");
  const test::Outcome r = test::runCommand(std::string("(") + MMS_BINARY + " render " + scene +
                                           " -o /dev/stdout >>" + test::quote(log) + ")");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = test::readFile(log);
  EXPECT_EQ(text.rfind("before\n<?xml", 0), 0u) << text.substr(0, 80);
}

TEST(Outputs, StandardOutputTakesOneFileAndNoFolder) {
  test::TempDir dir;
  const std::string scene = test::quote(test::scenario("one-robot/bar-slot.json"));
  const test::Outcome two = test::runMms("plan " + scene + " -o - --svg -");
  EXPECT_EQ(two.code, 2);
  EXPECT_EQ(two.err, "-: (--svg): -o already writes to standard output\n");
  const test::Outcome folder = test::runMms("bench " + scene + " --planners mms --runs 1 -o -");
  EXPECT_EQ(folder.code, 2);
  EXPECT_EQ(folder.err, "-: (-o): a folder is needed here, not standard output\n");
  const std::string queries = dir.file(
      "q.json",
      R"({"format": "mms-queries/1", "queries": [{"start": [-6, 0, 1.5], "goal": [6, 0, 1.5]},
          {"start": [6, 0, 1.5], "goal": [-6, 0, 1.5]}]})");
  const test::Outcome many =
      test::runMms("plan " + scene + " --planner mms --queries " + test::quote(queries) + " -o -");
  EXPECT_EQ(many.code, 2) << many.err;
  EXPECT_NE(many.err.find("several queries write a file each"), std::string::npos) << many.err;
}
