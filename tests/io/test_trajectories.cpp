// Timed trajectories for fleet software (mms export --to trajectories): at unit speed, each
// robot's rows where it starts, stops or changes its way, the motion between them linear; read
// back, they give every robot's pose at every waypoint's time.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

#include "Support.h"
#include "geometry/CollisionChecker.h"
#include "io/PathIO.h"
#include "io/SceneIO.h"
#include "io/Trajectories.h"

using namespace mms;

namespace {

struct Row {
  double t, x, y, theta;
};

// The CSV's rows by robot index.
std::map<size_t, std::vector<Row>> readRows(const std::string& csv) {
  std::map<size_t, std::vector<Row>> rows;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "robot,name,t,x,y,theta");
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::string field;
    std::istringstream cells(line);
    while (std::getline(cells, field, ',')) f.push_back(field);
    EXPECT_EQ(f.size(), 6u) << line;
    if (f.size() != 6) continue;
    rows[std::stoul(f[0])].push_back(
        {std::stod(f[2]), std::stod(f[3]), std::stod(f[4]), std::stod(f[5])});
  }
  return rows;
}

// A robot's pose at time t, linear between its rows.
Pose at(const std::vector<Row>& rows, double t) {
  for (size_t k = 1; k < rows.size(); ++k)
    if (t <= rows[k].t) {
      const Row &a = rows[k - 1], &b = rows[k];
      const double s = b.t > a.t ? (t - a.t) / (b.t - a.t) : 1;
      return {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.theta + s * (b.theta - a.theta)};
    }
  return {rows.back().x, rows.back().y, rows.back().theta};
}

}  // namespace

// A bar that turns a quarter on the spot (its radius times pi/2 of time) while a disc waits,
// then the disc goes 3 to the right while the bar stands.
TEST(Trajectories, EachRobotsRowsGiveItsPoseAtEveryMoment) {
  Scene s;
  s.name = "two";
  s.bounds = {0, 0, 20, 20};
  Robot bar;
  bar.name = "bar";
  bar.shape = {{-1.5, -0.1}, {1.5, -0.1}, {1.5, 0.1}, {-1.5, 0.1}};
  bar.start = {5, 5, 0};
  bar.goal = {5, 5, M_PI / 2};
  Robot disc;
  disc.name = "disc, \"the\" one";
  disc.disc = 1;
  disc.shape = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  disc.start = {12, 12, 0};
  disc.goal = {15, 12, 0};
  disc.motion = Motion::Translate;
  s.robots = {bar, disc};
  const std::vector<Config> w = {{5, 5, 0, 12, 12, 0},
                                 {5, 5, M_PI / 4, 12, 12, 0},
                                 {5, 5, M_PI / 2, 12, 12, 0},
                                 {5, 5, M_PI / 2, 15, 12, 0}};
  const std::string csv = trajectoriesCsv(s, w);
  EXPECT_NE(csv.find("1,\"disc, \"\"the\"\" one\","), std::string::npos) << csv;
  // Rows without the quoted name's commas: read the numbers from the last four fields.
  std::string plain;
  std::istringstream lines(csv);
  for (std::string line; std::getline(lines, line);) {
    const size_t quote = line.find('"');
    plain += (quote == std::string::npos
                  ? line
                  : line.substr(0, quote) + "disc" + line.substr(line.rfind('"') + 1)) +
             "\n";
  }
  const auto rows = readRows(plain);
  ASSERT_EQ(rows.size(), 2u);
  // The bar: at 0 and once turned (the waypoint half-way through its turn says nothing more),
  // and at the end. The disc: at 0, when it sets off and at the end.
  EXPECT_EQ(rows.at(0).size(), 3u);
  EXPECT_EQ(rows.at(1).size(), 3u);
  // The bar's points move at most its radius (about its reference point) times its turn.
  const double turn = CollisionChecker(s).radius(0) * M_PI / 2;
  EXPECT_NEAR(rows.at(1)[1].t, turn, 1e-12);
  EXPECT_NEAR(rows.at(1)[2].t, turn + 3, 1e-12);
  for (size_t k = 0; k < w.size(); ++k) {
    const double t = k == 0 ? 0 : k == 1 ? turn / 2 : k == 2 ? turn : turn + 3;
    for (size_t i = 0; i < 2; ++i) {
      const Pose p = at(rows.at(i), t), q = poseOf(w[k], i);
      EXPECT_NEAR(p.x, q.x, 1e-9) << "robot " << i << " waypoint " << k;
      EXPECT_NEAR(p.y, q.y, 1e-9);
      EXPECT_NEAR(p.theta, q.theta, 1e-9);
    }
  }
}

// The command: a path file to CSV; without a path, one line and exit 2.
TEST(Trajectories, ExportWritesThemAndNeedsAPath) {
  test::TempDir dir;
  const std::string scene = test::quote(test::scenario("translating/cup.json")),
                    path = test::quote(test::scenario("translating/cup.path.json")),
                    out = dir.path("t.csv");
  const test::Outcome r =
      test::runMms("export " + scene + " " + path + " --to trajectories -o " + test::quote(out));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string csv = test::readFile(out);
  EXPECT_EQ(csv.rfind("robot,name,t,x,y,theta\n", 0), 0u);
  EXPECT_EQ(readRows(csv).size(), 2u);
  const test::Outcome none =
      test::runMms("export " + scene + " --to trajectories -o " + test::quote(dir.path("u.csv")));
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("--to trajectories needs a path file"), std::string::npos) << none.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path("u.csv")));
}
