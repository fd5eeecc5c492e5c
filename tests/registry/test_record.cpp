// Records of the planning (PlannerParams::record, mms-record/1): every planner's record says what
// it built and when, the slices' cells agree with the collision checker, the file reads back,
// and a run's record is bounded.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "GeometryReference.h"
#include "Support.h"
#include "geometry/CollisionChecker.h"
#include "graph/RoadmapRecord.h"
#include "io/RecordIO.h"
#include "io/SceneIO.h"
#include "mms/Errors.h"
#include "mms/Planner.h"
#include "planner/OneRobotPlanner.h"
#include "scenarios/Generators.h"
#include "util/Random.h"

using namespace mms;
using namespace mms::test;

namespace {

PlanResult recorded(const std::string& planner, const Scene& s, uint64_t seed = 1) {
  PlannerParams p;
  p.seed = seed;
  p.record = true;
  p.values["optimize"] = 0;
  return makePlanner(planner, s, p)->solve(Termination(60));
}

}  // namespace

TEST(Record, OneRobotMmsRecordsItsSlicesAndLinesAsBuilt) {
  const Scene s = keyholeScene(3);
  const PlanResult r = recorded("mms", s);
  ASSERT_TRUE(r.found());
  ASSERT_TRUE(r.record);
  const PlanRecord& rec = *r.record;
  EXPECT_EQ(rec.planner, "mms");
  EXPECT_EQ(rec.robots, 1u);
  EXPECT_EQ(rec.manifolds.size(), r.stats.manifoldsBuilt);
  ASSERT_EQ(rec.subspaces.size(), 1u);
  EXPECT_TRUE(rec.subspaces[0].held.empty());
  size_t onPath = 0, slices = 0;
  float last = 0;
  for (const RecordManifold& m : rec.manifolds) {
    EXPECT_GE(m.at, last) << "stamps in the order built";
    last = m.at;
    EXPECT_LE(m.at, rec.seconds + 1e-3);
    onPath += m.onPath;
    if (m.family == "slice") {
      ++slices;
      EXPECT_EQ(m.regions.size(), m.cells);
    } else {
      EXPECT_EQ(m.arcs.size(), m.cells) << m.family;
    }
    // A found path's manifolds are in the one component of start and goal at the last search.
    if (m.onPath) {
      EXPECT_GE(m.reached[0], 0.f);
      EXPECT_GE(m.reached[1], 0.f);
    }
  }
  EXPECT_EQ(onPath, r.stats.manifoldsUsed);
  EXPECT_GT(slices, 0u);
  // The growth's last sample counts every manifold, by family.
  size_t grown = 0;
  for (const auto& [family, n] : rec.growth.counts) {
    ASSERT_EQ(n.size(), rec.growth.at.size());
    grown += n.back();
    for (size_t i = 1; i < n.size(); ++i) EXPECT_GE(n[i], n[i - 1]);
  }
  EXPECT_EQ(grown, r.stats.manifoldsBuilt);
  ASSERT_FALSE(rec.searches.empty());
  EXPECT_TRUE(rec.searches.back().connected);
}

// The recorded cells of every slice against the collision checker at random points (brute-force
// sampling, the robot at the slice's angle): inside a cell is free, outside is not, but within a
// thousandth of a cell's edge, where the contact tolerance decides.
TEST(Record, SliceCellsAgreeWithTheCollisionChecker) {
  const Scene s = keyholeScene(1);
  const PlanResult r = recorded("mms", s);
  ASSERT_TRUE(r.record);
  const CollisionChecker checker(s);
  Random rng(7);
  size_t checked = 0, inside = 0;
  for (const RecordManifold& m : r.record->manifolds) {
    if (m.family != "slice") continue;
    for (int i = 0; i < 400; ++i) {
      const Vec2 p{rng.uniform(s.bounds.xmin, s.bounds.xmax),
                   rng.uniform(s.bounds.ymin, s.bounds.ymax)};
      double margin;
      const bool in = insideCells(m.regions, p, margin);
      if (margin < 1e-3) continue;
      ++checked;
      inside += in;
      EXPECT_EQ(in, checker.isFree({p.x, p.y, m.theta}))
          << "slice at " << m.theta << ", point " << p.x << ", " << p.y;
    }
  }
  EXPECT_GT(checked, 1000u);
  EXPECT_GT(inside, 10u);
}

TEST(Record, TwoRobotMmsRecordsItsSubspaces) {
  const Scene s = loadScene(scenario("two-robots/pacman-0.5.json"));
  const PlanResult r = recorded("mms", s);
  ASSERT_TRUE(r.found());
  ASSERT_TRUE(r.record);
  const PlanRecord& rec = *r.record;
  EXPECT_EQ(rec.robots, 2u);
  ASSERT_GE(rec.subspaces.size(), 2u);
  for (const RecordSubspace& sub : rec.subspaces) {
    ASSERT_LT(sub.moving, 2u);
    if (sub.attached >= 0) continue;  // a compound: the pair moves, none is held
    ASSERT_EQ(sub.held.size(), 1u);
    EXPECT_NE(sub.held[0].first, sub.moving);
  }
  size_t onPath = 0;
  for (const RecordManifold& m : rec.manifolds) {
    ASSERT_LT(m.subspace, rec.subspaces.size());
    onPath += m.onPath;
  }
  EXPECT_EQ(rec.manifolds.size(), r.stats.manifoldsBuilt);
  EXPECT_EQ(onPath, r.stats.manifoldsUsed);
}

TEST(Record, SamplersRecordTheirTreeWithItsTimes) {
  const Scene s = keyholeScene(1, 0.3);
  const PlanResult r = recorded("rrtconnect", s);
  ASSERT_TRUE(r.found());
  ASSERT_TRUE(r.record);
  const RecordTree& t = r.record->tree;
  ASSERT_GT(t.states.size(), 2u);
  EXPECT_EQ(t.states.size(), t.totalStates) << "below the budget nothing is thinned";
  EXPECT_EQ(t.at.size(), t.states.size());
  // Two trees, an edge per state but their roots, and the edge that joined them.
  EXPECT_GE(t.edges.size(), t.states.size() - 2);
  EXPECT_LE(t.edges.size(), t.states.size() - 1);
  EXPECT_EQ(t.totalEdges, t.edges.size());
  const CollisionChecker checker(s);
  for (size_t i = 0; i < t.states.size(); ++i) {
    EXPECT_TRUE(checker.isFree(t.states[i])) << i;
    EXPECT_GE(t.at[i], 0.f);
    EXPECT_LE(t.at[i], r.record->seconds + 1e-3);
  }
  // The start is a root of the tree.
  bool start = false;
  for (const Config& q : t.states)
    start = start || (std::abs(q[0] - s.robots[0].start.x) < 1e-9 &&
                      std::abs(q[1] - s.robots[0].start.y) < 1e-9);
  EXPECT_TRUE(start);
}

TEST(Record, EveryPlannerGivesOne) {
  const Scene s = keyholeScene(2, 0.3);
  for (const char* planner : {"auto", "mms-ordered", "prm"}) {
    const PlanResult r = recorded(planner, s);
    ASSERT_TRUE(r.record) << planner;
    EXPECT_FALSE(r.record->planner.empty()) << planner;
    if (std::string(planner) == "prm") {
      EXPECT_GT(r.record->tree.states.size(), 0u) << planner;
    }
  }
  PlannerParams p;
  EXPECT_FALSE(makePlanner("mms", s, p)->solve(Termination(60)).record) << "only when asked";
}

// Past the budget, every k-th manifold is kept, spread over the run; the path's
// manifolds always are, and the growth still counts them all.
TEST(Record, ARecordIsThinnedToItsBudget) {
  const Scene s = keyholeScene(4);
  OneRobotSettings settings;
  settings.record = true;
  OneRobotPlanner planner(s, 0, settings);
  ASSERT_EQ(planner.solve(s.robots[0].start, s.robots[0].goal, Termination(60)).status,
            PlanStatus::Found);
  PlanRecord full, thin;
  appendRoadmap(planner.roadmap(), RecordBudget{}, full);
  size_t vertices = 0, lines = 0, onPath = 0, bytes = 0;
  for (const RecordManifold& m : full.manifolds) {
    vertices += m.vertices;
    lines += m.family != "slice";
    onPath += m.onPath;
    bytes += 130 + 18 * m.vertices + 20 * m.cells;
  }
  ASSERT_GT(lines, 10u);
  ASSERT_EQ(full.manifolds.size(), planner.roadmap().manifoldCount());
  RecordBudget budget;
  budget.bytes = bytes / 4;  // every fourth manifold
  appendRoadmap(planner.roadmap(), budget, thin);
  size_t keptLines = 0, keptVertices = 0, keptOnPath = 0, last = 0;
  for (const RecordManifold& m : thin.manifolds) {
    const RecordManifold& same = full.manifolds[m.index];
    EXPECT_EQ(same.family, m.family);
    EXPECT_EQ(same.at, m.at);
    EXPECT_EQ(same.cells, m.cells);
    EXPECT_GE(m.index, last);
    last = m.index;
    keptOnPath += m.onPath;
    if (m.family == "slice")
      keptVertices += m.vertices;
    else
      ++keptLines;
  }
  EXPECT_EQ(keptOnPath, onPath);
  EXPECT_LT(keptLines, lines / 3 + onPath + 1);
  EXPECT_LT(keptVertices, vertices);
  EXPECT_LE(thin.manifolds.size(), full.manifolds.size() / 4 + 1 + onPath);
  EXPECT_GT(thin.manifolds.back().index, full.manifolds.size() / 2) << "spread over the run";
  ASSERT_EQ(thin.growth.counts.size(), full.growth.counts.size());
  for (size_t k = 0; k < thin.growth.counts.size(); ++k)
    EXPECT_EQ(thin.growth.counts[k].second, full.growth.counts[k].second);
}

TEST(Record, TheFileReadsBackAndBadOnesAreNamed) {
  const Scene s = keyholeScene(1);
  const PlanResult r = recorded("mms", s);
  ASSERT_TRUE(r.record);
  const nlohmann::json j = recordToJson(*r.record, r.stats);
  const RecordFile back = parseRecord(j, "r.json", 1);
  ASSERT_EQ(back.record.manifolds.size(), r.record->manifolds.size());
  for (size_t i = 0; i < back.record.manifolds.size(); ++i) {
    const RecordManifold &a = r.record->manifolds[i], &b = back.record.manifolds[i];
    EXPECT_EQ(a.family, b.family);
    EXPECT_NEAR(a.at, b.at, 1e-6);
    EXPECT_EQ(a.cells, b.cells);
    EXPECT_EQ(a.onPath, b.onPath);
    ASSERT_EQ(a.regions.size(), b.regions.size());
    for (size_t c = 0; c < a.regions.size(); ++c)
      for (size_t k = 0; k < a.regions[c].size(); ++k)
        for (size_t v = 0; v < a.regions[c][k].size(); ++v)
          EXPECT_NEAR(a.regions[c][k][v].x, b.regions[c][k][v].x, 1e-6);
  }
  EXPECT_EQ(back.stats.manifoldsBuilt, r.stats.manifoldsBuilt);
  auto refusal = [&](nlohmann::json doc, size_t robots = 1) {
    try {
      parseRecord(doc, "r.json", robots);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  nlohmann::json bad = j;
  bad["format"] = "mms-path/1";
  EXPECT_EQ(refusal(bad), "r.json: format: expected \"mms-record/1\", found \"mms-path/1\"");
  EXPECT_NE(refusal(j, 2).find("r.json: robots: the record is of 1 robots, the scene has 2"),
            std::string::npos);
  bad = j;
  bad["manifolds"][0]["subspace"] = 5;
  EXPECT_NE(refusal(bad).find("r.json: manifolds[0].subspace:"), std::string::npos) << refusal(bad);
  bad = j;
  for (auto& m : bad["manifolds"])
    if (m.contains("regions") && !m["regions"].empty()) {
      m["regions"][0][0][1] = "x";
      break;
    }
  EXPECT_NE(refusal(bad).find(".regions[0][0][1]: expected a number"), std::string::npos)
      << refusal(bad);
}

// On the command line: a record goes with its scene; a bad one is named in one line, exit 2,
// and no page is written.
TEST(Record, TheCommandLineNamesABadRecordAndWritesNoPage) {
  TempDir dir;
  const std::string one = scenario("one-robot/bar-slot.json"),
                    two = scenario("two-robots/pacman-0.5.json"), rec = dir.path("r.json"),
                    page = dir.path("v.html");
  auto plan = runMms("plan " + quote(one) + " --planner mms -q --record " + quote(rec));
  ASSERT_EQ(plan.code, 0) << plan.err;
  EXPECT_EQ(runMms("view " + quote(one) + " --record " + quote(rec) + " -o " + quote(page)).code,
            0);
  std::filesystem::remove(page);
  auto other = runMms("view " + quote(two) + " --record " + quote(rec) + " -o " + quote(page));
  EXPECT_EQ(other.code, 2);
  EXPECT_EQ(other.err, rec + ": robots: the record is of 1 robots, the scene has 2\n");
  EXPECT_FALSE(std::filesystem::exists(page));
  const std::string badFile = dir.file("bad.json", "{\"format\": \"mms-record/1\"}");
  auto bad = runMms("view " + quote(one) + " --record " + quote(badFile) + " -o " + quote(page));
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(bad.err, badFile + ": planner: missing\n");
  EXPECT_FALSE(std::filesystem::exists(page));
}
