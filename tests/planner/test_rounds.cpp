// The round loop every MMS planner runs (planner/Rounds.h): search as soon as start and goal
// connect, complete the round after a refusal, double, give up, stop.
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include "graph/Roadmap.h"
#include "planner/Rounds.h"

using namespace mms;

namespace {

struct LoopStats {
  size_t rounds = 0, rejectedPaths = 0;
  double roundShare = 0;
  double searchSeconds = 0, motionSeconds = 0, certifySeconds = 0;
};

// A manifold of `cells` cells that meets nothing: the loop's graph needs nodes, not geometry.
class Cells final : public Manifold {
 public:
  explicit Cells(size_t cells) : cells_(cells) {}
  const ManifoldFamily& family() const override { return kFamily; }
  size_t cellCount() const override { return cells_; }
  long locate(const Config&) const override { return -1; }
  std::optional<std::vector<Config>> motion(size_t, const Config&, const Config&) const override {
    return std::nullopt;
  }

 private:
  static constexpr ManifoldFamily kFamily{"cells"};
  size_t cells_;
};

Roadmap roadmapOfCells(size_t cells) {
  Roadmap r;
  r.add(std::make_unique<Cells>(cells), 0, 0);
  return r;
}

}  // namespace

// A chain of cells 0 - 1 - ... - 5 that grows one edge per manifold: the search runs as soon
// as 0 and 5 connect; a refused candidate completes the round before the next search; a
// complete round doubles the target.
TEST(Rounds, SearchEarlyCompleteTheRoundAfterARefusalThenDouble) {
  Roadmap g = roadmapOfCells(6);
  size_t built = 0, target = 2, searches = 0, refusals = 0;
  std::vector<size_t> builtAtSearch;
  RoundHooks h;
  h.growing = [&] { return built < target; };
  h.complete = [&] { return built >= target; };
  size_t builtAtRoundStart = 0;
  h.share = [&] { return double(built - builtAtRoundStart) / double(target - builtAtRoundStart); };
  h.grow = [&] {
    if (built < 5) g.addEdge(built, built + 1);
    ++built;
  };
  h.motion = [&](const std::vector<size_t>& nodes) {
    CertifiedMotion m;
    builtAtSearch.push_back(built);
    m.ok = ++searches > 1;  // the first candidate is refused
    m.waypoints = {Config(nodes.size(), 0.0)};
    return m;
  };
  h.refused = [&] { ++refusals; };
  h.next = [&] {
    builtAtRoundStart = built;
    target *= 2;
    return true;
  };
  // What a watcher of the condition hears: each round begun, and after each step of growth
  // the share of the round's targets met.
  struct Heard final : Termination::Watcher {
    void onRound(size_t round) override { events.push_back("round " + std::to_string(round)); }
    void onGrowth(double share) override { events.push_back(std::to_string(share).substr(0, 4)); }
    std::vector<std::string> events;
  } heard;
  LoopStats stats;
  const RoundsOutcome o = runRounds(h, g, 0, 5, Termination(10).watchedBy(&heard), stats);
  ASSERT_EQ(o.end, RoundsOutcome::End::Found);
  EXPECT_EQ(o.nodes, (std::vector<size_t>{0, 1, 2, 3, 4, 5}));
  // Rounds of 2, 4, 8: connected after 5 manifolds (round 3), refused, the round completed to
  // 8, then searched again.
  EXPECT_EQ(builtAtSearch, (std::vector<size_t>{5, 8}));
  EXPECT_EQ(stats.rounds, 3u);
  EXPECT_EQ(stats.rejectedPaths, 1u);
  EXPECT_EQ(refusals, 1u);
  // Round 3 grows 4 -> 8: connected at 5 (a quarter), completed to 8 after the refusal.
  EXPECT_EQ(heard.events, (std::vector<std::string>{"round 1", "0.50", "1.00", "1.00", "round 2",
                                                    "0.50", "1.00", "1.00", "round 3", "0.25",
                                                    "0.25", "0.50", "0.75", "1.00", "1.00"}));
  EXPECT_EQ(stats.roundShare, 1.0);
}

TEST(Rounds, GiveUpAndStop) {
  Roadmap g = roadmapOfCells(2);
  size_t built = 0, target = 1, rounds = 0;
  RoundHooks h;
  h.growing = [&] { return built < target; };
  h.complete = [&] { return built >= target; };
  h.share = [] { return 0.0; };
  h.grow = [&] { ++built; };
  h.motion = [](const std::vector<size_t>&) { return CertifiedMotion{}; };
  h.next = [&] {
    target *= 2;
    return ++rounds < 3;  // a budget of rounds
  };
  LoopStats stats;
  EXPECT_EQ(runRounds(h, g, 0, 1, Termination(10), stats).end, RoundsOutcome::End::NotFound);
  EXPECT_EQ(stats.rounds, 3u);
  EXPECT_EQ(built, 4u);
  std::atomic<bool> cancel{true};
  h.next = [] { return true; };
  EXPECT_EQ(runRounds(h, g, 0, 1, Termination(10, &cancel), stats).end,
            RoundsOutcome::End::Cancelled);
}
