// The theory lab (src/lab): exact FSCs of axis-aligned subspaces against a rasterised
// reference, Euclidean MMS and PRM on box spaces, the k-clearance estimator against the exact
// values of flume and tunnel, and the `mms lab` command.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <queue>

#include "Support.h"
#include "lab/BoxSpace.h"
#include "lab/EuclideanMms.h"
#include "lab/KClearance.h"
#include "lab/PrmOnBoxes.h"
#include "lab/SubspaceCells.h"
#include "util/Random.h"

namespace mms::lab {
namespace {

// Random boxes with faces on the 1/20 grid: every gap between them is at least 1/20 wide, so a
// raster of pitch 1/100 resolves every component.
BoxSpace gridBoxes(int d, int n, uint64_t seed) {
  Random r(seed);
  std::vector<Box> boxes;
  for (int i = 0; i < n; ++i) {
    Box b{Point(d), Point(d)};
    for (int a = 0; a < d; ++a) {
      int lo = int(r.below(18)), len = 1 + int(r.below(8));
      b.lo[a] = lo / 20.0;
      b.hi[a] = std::min(20, lo + len) / 20.0;
    }
    boxes.push_back(b);
  }
  return BoxSpace(d, boxes);
}

TEST(Lab, SubspaceCellsMatchARasterisedReference) {
  const int pitch = 100;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    const BoxSpace space = gridBoxes(3, 9, seed);
    Random r(seed + 100);
    for (std::vector<int> freeAxes : {std::vector<int>{0, 1}, {1, 2}, {0, 2}, {1}}) {
      AxisSubspace s{freeAxes, Point(3)};
      for (double& v : s.point) v = (int(r.below(20)) + 0.37) / 20.0;  // off the face grid
      const SubspaceCells cells(space, s);
      // Raster the subspace at cell centres of a pitch-1/100 grid; flood-fill 4-neighbours.
      const int k = int(freeAxes.size());
      const int n = k == 2 ? pitch * pitch : pitch;
      std::vector<int> component(n, -1);
      auto pointOf = [&](int i) {
        Point p = s.point;
        p[freeAxes[0]] = (i % pitch + 0.5) / pitch;
        if (k == 2) p[freeAxes[1]] = (i / pitch + 0.5) / pitch;
        return p;
      };
      int components = 0;
      for (int i = 0; i < n; ++i) {
        if (component[i] >= 0 || !space.isFree(pointOf(i))) continue;
        std::queue<int> q;
        q.push(i);
        component[i] = components;
        while (!q.empty()) {
          int c = q.front();
          q.pop();
          int x = c % pitch, y = c / pitch;
          std::vector<int> next;
          if (x > 0) next.push_back(c - 1);
          if (x + 1 < pitch) next.push_back(c + 1);
          if (k == 2 && y > 0) next.push_back(c - pitch);
          if (k == 2 && y + 1 < pitch) next.push_back(c + pitch);
          for (int m : next)
            if (component[m] < 0 && space.isFree(pointOf(m))) component[m] = components, q.push(m);
        }
        ++components;
      }
      // Free iff located; raster components and FSCs correspond one to one.
      std::map<int, int> fscOf;
      std::map<int, int> componentOf;
      for (int i = 0; i < n; ++i) {
        const int label = cells.locate(pointOf(i));
        ASSERT_EQ(label >= 0, component[i] >= 0) << "seed " << seed;
        if (label < 0) continue;
        auto [a, newA] = fscOf.emplace(component[i], label);
        auto [b, newB] = componentOf.emplace(label, component[i]);
        ASSERT_EQ(a->second, label) << "one raster component in two FSCs, seed " << seed;
        ASSERT_EQ(b->second, component[i]) << "one FSC over two raster components, seed " << seed;
      }
      EXPECT_EQ(size_t(components), cells.components()) << "seed " << seed;
      for (size_t c = 0; c < cells.components(); ++c) {
        EXPECT_TRUE(space.isFree(cells.representatives()[c]));
        EXPECT_EQ(cells.locate(cells.representatives()[c]), int(c));
      }
    }
  }
}

TEST(Lab, SegmentsAndRaysAgreeWithDenseSampling) {
  const BoxSpace space = gridBoxes(3, 8, 7);
  Random r(3);
  int blocked = 0;
  for (int t = 0; t < 400; ++t) {
    Point a(3), b(3);
    for (int i = 0; i < 3; ++i) a[i] = r.uniform(0.01, 0.99), b[i] = r.uniform(0.01, 0.99);
    if (!space.isFree(a)) continue;
    bool sampledFree = true;
    for (int s = 0; s <= 4000 && sampledFree; ++s) {
      Point p(3);
      for (int i = 0; i < 3; ++i) p[i] = a[i] + (b[i] - a[i]) * s / 4000.0;
      sampledFree = space.isFree(p);
    }
    // Sampling can miss a corner the exact test sees, never the reverse.
    if (space.segmentFree(a.data(), b.data()))
      EXPECT_TRUE(sampledFree);
    else
      blocked++;
    Point u(3);
    double len = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                           (b[2] - a[2]) * (b[2] - a[2]));
    for (int i = 0; i < 3; ++i) u[i] = (b[i] - a[i]) / len;
    const double reach = space.rayFree(a.data(), u.data(), 2.0);
    for (double f : {0.25, 0.5, 0.9, 0.999}) {
      Point p(3);
      for (int i = 0; i < 3; ++i) p[i] = a[i] + f * reach * u[i];
      EXPECT_TRUE(space.isFree(p)) << "inside the ray's reach";
    }
    Point beyond(3);
    for (int i = 0; i < 3; ++i) beyond[i] = a[i] + (reach + 1e-9) * u[i];
    EXPECT_FALSE(space.isFree(beyond)) << "just past the ray's reach";
  }
  EXPECT_GT(blocked, 50);
}

TEST(Lab, EuclideanMmsConnectsThroughTheHoleOnly) {
  // No hole: a full wall. Never connected, however many manifolds.
  const BoxSpace closed(2, {Box{{0.45, 0.0}, {0.55, 1.0}}});
  EuclideanMmsSettings s;
  s.families = perpendicularFamilies(2, 1);
  s.maxRounds = 200;
  EXPECT_FALSE(solveEuclideanMms(closed, wallStart(2), wallGoal(2), s).rounds);
  const BoxSpace open = wallWithHole(4, 0.1, 8, 3);
  s.families = perpendicularFamilies(4, 2);
  const auto a = solveEuclideanMms(open, wallStart(4), wallGoal(4), s);
  const auto b = solveEuclideanMms(open, wallStart(4), wallGoal(4), s);
  ASSERT_TRUE(a.rounds);
  EXPECT_EQ(a.rounds, b.rounds) << "same seed, same result";
  EXPECT_EQ(a.manifolds, b.manifolds);
}

TEST(Lab, EuclideanMmsFailureDecaysAsTheHoleProbabilityPredicts) {
  // d = 2, no clutter: MMS fails after n rounds exactly when none of the n horizontal lines
  // passes the hole (width 2 rho = 0.1), so failure(n) = 0.9^n in expectation.
  const BoxSpace space = wallWithHole(2, 0.05, 0, 1);
  EuclideanMmsSettings s;
  s.families = perpendicularFamilies(2, 1);
  s.maxRounds = 100;
  const int trials = 400;
  int failedAt10 = 0, failedAt30 = 0;
  for (int t = 0; t < trials; ++t) {
    s.seed = 1000 + t;
    auto r = solveEuclideanMms(space, wallStart(2), wallGoal(2), s);
    failedAt10 += !r.rounds || *r.rounds > 10;
    failedAt30 += !r.rounds || *r.rounds > 30;
  }
  // 0.9^10 = 0.349, 0.9^30 = 0.042; five standard deviations either side.
  EXPECT_NEAR(failedAt10 / double(trials), 0.349, 5 * std::sqrt(0.349 * 0.651 / trials));
  EXPECT_NEAR(failedAt30 / double(trials), 0.042, 5 * std::sqrt(0.042 * 0.958 / trials));
}

TEST(Lab, PrmOnBoxesConnectsThroughTheHoleOnly) {
  const BoxSpace closed(2, {Box{{0.45, 0.0}, {0.55, 1.0}}});
  PrmSettings s;
  s.maxMilestones = 600;
  EXPECT_FALSE(solvePrmOnBoxes(closed, wallStart(2), wallGoal(2), s).milestones);
  const BoxSpace open = wallWithHole(2, 0.15, 0, 1);
  const auto a = solvePrmOnBoxes(open, wallStart(2), wallGoal(2), s);
  const auto b = solvePrmOnBoxes(open, wallStart(2), wallGoal(2), s);
  ASSERT_TRUE(a.milestones);
  EXPECT_GT(*a.milestones, 0u) << "the wall hides start from goal";
  EXPECT_EQ(a.milestones, b.milestones) << "same seed, same roadmap";
}

TEST(Lab, KClearanceSeparatesFlumeFromTunnel) {
  for (double eps : {0.2, 0.05}) {
    DiskSearch ds;
    const auto f = kClearanceSequence(flume(eps), passageStart(), passageGoal(), 3, ds);
    const auto t = kClearanceSequence(tunnel(eps), passageStart(), passageGoal(), 3, ds);
    // Exact: flume eps^2/2, >= 1 (capped), 1; tunnel eps/2, eps/sqrt(2), 1.
    EXPECT_NEAR(f[0], eps * eps / 2, 0.02 * eps * eps / 2);
    EXPECT_DOUBLE_EQ(f[1], 1.0);
    EXPECT_NEAR(t[0], eps / 2, 0.02 * eps / 2);
    EXPECT_NEAR(t[1], eps / std::sqrt(2.0), 0.02 * eps / std::sqrt(2.0));
    EXPECT_DOUBLE_EQ(t[2], 1.0);
    EXPECT_EQ(passageDimension(f, 10), 2);
    EXPECT_EQ(passageDimension(t, 5), 1);
  }
}

TEST(Lab, DiskSearchFindsAPassageAlongNoAxis) {
  // Free: the slab |n . x| < w with n = (1, 1, 1)/sqrt(3), a 2-D passage no coordinate plane
  // lies in. Analytic rays from the origin.
  const double w = 0.01, s3 = std::sqrt(3.0);
  RayFunction ray = [&](const Point& x, const Point& u, double cap) {
    double px = (x[0] + x[1] + x[2]) / s3, pu = (u[0] + u[1] + u[2]) / s3;
    if (std::abs(px) >= w) return 0.0;
    if (std::abs(pu) < 1e-15) return cap;
    return std::min(cap, ((pu > 0 ? w : -w) - px) / pu);
  };
  DiskSearch ds;
  const Point o(3, 0.0);
  // Sampled directions bound the ball from above; the normal itself is not among them.
  const double ball = diskRadius(3, 3, o, ray, ds);
  EXPECT_GE(ball, w * (1 - 1e-12));
  EXPECT_LE(ball, w * 1.01);
  EXPECT_GT(diskRadius(3, 2, o, ray, ds), 0.5) << "the disk in the slab's plane";
  EXPECT_DOUBLE_EQ(diskRadius(3, 1, o, ray, ds), 1.0);
}

TEST(Lab, CommandWritesEveryPlotAndRejectsBadInput) {
  test::TempDir dir;
  const std::string out = dir.path("lab");
  auto c = test::runMms("lab completeness --quick -q --threads 2 -o " + test::quote(out));
  ASSERT_EQ(c.code, 0) << c.err;
  auto p = test::runMms("lab passages --quick -q -o " + test::quote(out));
  ASSERT_EQ(p.code, 0) << p.err;
  for (const char* f : {"completeness-mms.svg", "completeness-prm.svg", "passages-success.svg",
                        "passages-time.svg", "passages-kclearance.svg", "passages-pacman.svg"}) {
    const std::string svg = test::readFile(out + "/" + f);
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u) << f;
    EXPECT_NE(svg.find("<polyline"), std::string::npos) << f;
    EXPECT_NE(svg.find("</svg>"), std::string::npos) << f;
  }
  EXPECT_NE(test::readFile(out + "/passages.md").find("| flume | 0.1 |"), std::string::npos);
  // Same seed, same counts whatever the thread count (the CSV holds no times).
  const std::string csv = test::readFile(out + "/completeness.csv");
  auto one = test::runMms("lab completeness --quick -q --threads 1 -o " + test::quote(out));
  ASSERT_EQ(one.code, 0);
  EXPECT_EQ(test::readFile(out + "/completeness.csv"), csv);

  // --no-pacman leaves the two-robot proxy out.
  const std::string noPacman = dir.path("no-pacman");
  auto np = test::runMms("lab passages --quick -q --no-pacman -o " + test::quote(noPacman));
  ASSERT_EQ(np.code, 0) << np.err;
  EXPECT_FALSE(std::filesystem::exists(noPacman + "/passages-pacman.svg"));
  EXPECT_EQ(test::readFile(noPacman + "/passages.md").find("Pacman"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(noPacman + "/passages-kclearance.svg"));

  auto bad = test::runMms("lab nonsense");
  EXPECT_EQ(bad.code, 2);
  // Without -o the report would land in the current folder unnoticed: -o is required.
  auto nowhere = test::runMms("lab completeness --quick -q");
  EXPECT_EQ(nowhere.code, 2);
  EXPECT_NE(nowhere.err.find("--output"), std::string::npos) << nowhere.err;
  auto file = dir.file("plain", "x");
  auto notDir = test::runMms("lab completeness --quick -o " + test::quote(file + "/sub"));
  EXPECT_EQ(notDir.code, 2);
  EXPECT_NE(notDir.err.find("--output"), std::string::npos) << notDir.err;
  EXPECT_EQ(std::count(notDir.err.begin(), notDir.err.end(), '\n'), 1) << notDir.err;
}

}  // namespace
}  // namespace mms::lab
