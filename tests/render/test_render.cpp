// SVG pictures: well-formed, drawn where the scene says, readable by a standard renderer.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "Support.h"
#include "io/SceneIO.h"
#include "render/HtmlViewer.h"
#include "render/Palette.h"
#include "render/SvgRenderer.h"
#include "scenarios/Generators.h"

using namespace mms;
using namespace mms::test;

namespace {
size_t count(const std::string& hay, const std::string& needle) {
  size_t n = 0;
  for (size_t p = hay.find(needle); p != std::string::npos; p = hay.find(needle, p + 1)) ++n;
  return n;
}
}  // namespace

TEST(Render, SceneAloneHasObstaclesStartsAndGoals) {
  const Scene s = loadScene(scenario("two-robots/niche-swap.json"));
  const std::string svg = renderSvg(s, nullptr);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("<g id=\"obstacles\""), std::string::npos);
  EXPECT_EQ(count(svg, "<polygon"), s.obstacles.size() + 2 * s.robots.size());
  EXPECT_EQ(svg.find("animateTransform"), std::string::npos);
  // The right robot's start pose (11, 0.65) shifts its first vertex to (10.5, 0.15).
  EXPECT_NE(svg.find("10.5,0.15"), std::string::npos);
}

TEST(Render, PathAddsGhostsTracesAndAnimation) {
  const Scene s = loadScene(scenario("one-robot/bar-slot.json"));
  const Path p = loadPath(scenario("one-robot/bar-slot.path.json"), s);
  SvgOptions o;
  o.ghosts = 10;
  const std::string svg = renderSvg(s, &p, o);
  EXPECT_EQ(count(svg, "<animateTransform"), 2u);  // translate and rotate of the one robot
  EXPECT_NE(svg.find("values=\"-6 0;-6 0;6 0;6 0\""), std::string::npos);
  EXPECT_NE(svg.find("values=\"90;0;0;90\""), std::string::npos);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  EXPECT_EQ(count(svg, "<polygon"), s.obstacles.size() + 2 + (o.ghosts - 1) + 1);
}

TEST(Render, CommandWritesAnSvgThatRsvgConvertRenders) {
  TempDir dir;
  const std::string svg = dir.path("out.svg"), png = dir.path("out.png");
  Outcome r = runMms("render " + quote(scenario("translating/cup.json")) + " " +
                     quote(scenario("translating/cup.path.json")) + " -o " + quote(svg));
  ASSERT_EQ(r.code, 0) << r.err;
  r = runCommand("rsvg-convert " + quote(svg) + " -o " + quote(png));
  ASSERT_EQ(r.code, 0) << "rsvg-convert (librsvg2-bin, installed by scripts/setup.sh): " << r.err;
  const std::string bytes = readFile(png);
  ASSERT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
}

TEST(Render, UnwritableOutputLeavesNoFileAndExitsTwo) {
  TempDir dir;
  const Outcome r = runMms("render " + quote(scenario("translating/cup.json")) + " -o " +
                           quote(dir.path("no/such/dir/out.svg")));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("out.svg: (output): cannot create"), std::string::npos) << r.err;
}

TEST(Render, BadPathLeavesNoOutputFile) {
  TempDir dir;
  const std::string out = dir.path("out.svg");
  const Outcome r = runMms("render " + quote(scenario("translating/cup.json")) + " " +
                           quote(dir.file("p.json", "{}")) + " -o " + quote(out));
  EXPECT_EQ(r.code, 2);
  EXPECT_FALSE(std::filesystem::exists(out));
}

// Many robots: each has a colour of its own (traces, the animated robot) and its name in a legend
// above the scene, in the SVG and in the viewer; one robot needs no legend.
TEST(Render, EachRobotHasItsColourAndItsNameInALegend) {
  const Scene s = discsRoomScene(2, 12);
  Path p;
  p.waypoints = {startConfig(s), goalConfig(s)};
  const std::string svg = renderSvg(s, &p);
  const size_t legend = svg.find("<g id=\"legend\"");
  ASSERT_NE(legend, std::string::npos);
  std::set<std::string> colours;
  for (size_t i = 0; i < s.robots.size(); ++i) {
    colours.insert(robotColour(i));
    EXPECT_NE(svg.find(">" + s.robots[i].name + "</text>", legend), std::string::npos) << i;
    EXPECT_NE(svg.find("<polyline fill=\"none\" stroke=\"" + std::string(robotColour(i))),
              std::string::npos)
        << i;
    EXPECT_NE(svg.find("<polygon fill=\"" + std::string(robotColour(i))), std::string::npos) << i;
  }
  EXPECT_EQ(colours.size(), s.robots.size());
  // The legend wraps: twelve names do not fit one row of the picture.
  std::set<std::string> rows;
  const std::string block = svg.substr(legend, svg.find("</g>", legend) - legend);
  for (size_t at = block.find("<rect"); at != std::string::npos; at = block.find("<rect", at + 1)) {
    const size_t y = block.find(" y=\"", at) + 4;
    rows.insert(block.substr(y, block.find('"', y) - y));
  }
  EXPECT_GT(rows.size(), 1u);
  const std::string html = renderHtmlViewer(s, &p);
  for (size_t i = 0; i < s.robots.size(); ++i) {
    EXPECT_NE(html.find(std::string("background:") + robotColour(i)), std::string::npos) << i;
    EXPECT_NE(html.find(">" + s.robots[i].name + "</span>"), std::string::npos) << i;
  }
  const Scene one = loadScene(scenario("one-robot/bar-slot.json"));
  EXPECT_EQ(renderSvg(one, nullptr).find("id=\"legend\""), std::string::npos);
  EXPECT_EQ(renderHtmlViewer(one, nullptr).find("id=\"legend\""), std::string::npos);
}

// A fleet keeps its robots apart by colour: none repeats among the first 2000 (in a scene of 20
// discs two pairs once shared one), and the first 64 stay as far apart as the hand-chosen
// sixteen (the "redmean" distance between colours, a cheap approximation of how far apart the
// eye sees them).
TEST(Render, HundredsOfRobotsKeepTheirColoursApart) {
  auto rgb = [](const std::string& c) {
    EXPECT_EQ(c.size(), 7u) << c;
    return std::array<int, 3>{std::stoi(c.substr(1, 2), nullptr, 16),
                              std::stoi(c.substr(3, 2), nullptr, 16),
                              std::stoi(c.substr(5, 2), nullptr, 16)};
  };
  auto apart = [](const std::array<int, 3>& a, const std::array<int, 3>& b) {
    const double mean = (a[0] + b[0]) / 2.0, dr = a[0] - b[0], dg = a[1] - b[1], db = a[2] - b[2];
    return std::sqrt((2 + mean / 256) * dr * dr + 4 * dg * dg + (2 + (255 - mean) / 256) * db * db);
  };
  std::set<std::string> seen;
  for (size_t i = 0; i < 2000; ++i) EXPECT_TRUE(seen.insert(robotColour(i)).second) << i;
  double closest = 1e9;
  for (size_t i = 0; i < 64; ++i)
    for (size_t j = i + 1; j < 64; ++j)
      closest = std::min(closest, apart(rgb(robotColour(i)), rgb(robotColour(j))));
  EXPECT_GE(closest, 20);
}

// The viewer's picture follows the window: sized on load and on every resize; fixed only when
// the link asks for it (#fit=0, for screenshots at a known scale).
TEST(Render, ViewerCanvasFollowsTheWindow) {
  const Scene s = loadScene(scenario("one-robot/bar-slot.json"));
  const std::string html = renderHtmlViewer(s, nullptr);
  EXPECT_NE(html.find("window.addEventListener('resize', fit)"), std::string::npos);
  EXPECT_NE(html.find("(window.innerWidth - beside) / W"), std::string::npos);
  const size_t fixed = html.find("cv.style.width = W + 'px'");
  ASSERT_NE(fixed, std::string::npos);
  const size_t asked = html.rfind("get('fit') === '0'", fixed);
  ASSERT_NE(asked, std::string::npos);
  EXPECT_LT(fixed - asked, 80u) << "the fixed size only in the branch #fit=0 takes";
}

// Robots moving one at a time: each robot's animation keeps only the waypoints where it starts,
// stops or bends, so the picture grows with the robots and the waypoints, not their product.
TEST(Render, ManyRobotsMovingInTurnAnimateWithTheirOwnKeyFrames) {
  const Scene s = discGridScene(3, 60, 10);
  Path path;
  path.waypoints.push_back(startConfig(s));
  for (size_t i = 0; i < s.robots.size(); ++i) {
    Config q = path.waypoints.back();
    q[3 * i] = s.robots[i].goal.x;
    q[3 * i + 1] = s.robots[i].goal.y;
    path.waypoints.push_back(q);
  }
  const std::string svg = renderSvg(s, &path);
  size_t animations = 0, at = 0;
  while ((at = svg.find("type=\"translate\" values=\"", at)) != std::string::npos) {
    at += 26;
    const std::string values = svg.substr(at, svg.find('"', at) - at);
    // The first waypoint, the move's two ends, the last: at most four frames.
    EXPECT_LE(std::count(values.begin(), values.end(), ';'), 3) << values;
    ++animations;
  }
  EXPECT_EQ(animations, s.robots.size());
}

// Exact discs are drawn as circles, robots (start, goal, ghosts, the moving one) and obstacles
// alike; polygons stay polygons.
TEST(Render, DiscsAreDrawnAsCircles) {
  Scene s = discBoxScene(3, 6);
  s.addObstacleDisc({{s.bounds.xmin + 0.5, s.bounds.ymin + 0.5}, 0.25});
  Path p;
  p.waypoints = {startConfig(s), goalConfig(s)};  // drawn, not checked
  SvgOptions o;
  o.ghosts = 3;
  const std::string svg = renderSvg(s, &p, o);
  size_t circles = 0, polygons = 0;
  for (size_t at = 0; (at = svg.find("<circle", at)) != std::string::npos; ++at) ++circles;
  for (size_t at = 0; (at = svg.find("<polygon", at)) != std::string::npos; ++at) ++polygons;
  // Six robots at start and goal, as ghosts (two each) and moving, and one disc obstacle.
  EXPECT_EQ(circles, 6u * 5 + 1) << svg.substr(0, 400);
  EXPECT_EQ(polygons, 4u) << "the box's four walls";
}
