#include "lab/Experiments.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

#include "lab/BoxSpace.h"
#include "lab/EuclideanMms.h"
#include "lab/KClearance.h"
#include "lab/PacmanPassage.h"
#include "lab/PrmOnBoxes.h"
#include "mms/Termination.h"
#include "render/Plot.h"
#include "util/Parallel.h"
#include "util/Random.h"

namespace mms::lab {

namespace {

using Outcome = std::optional<size_t>;  // samples to connect; none = not within the budget

std::string fmt(double v, int precision = 3) {
  std::ostringstream o;
  o << std::setprecision(precision) << v;
  return o.str();
}

void say(const LabOptions& o, const std::string& line) {
  if (o.progress) o.progress(line);
}

uint64_t trialSeed(uint64_t seed, size_t experiment, size_t trial) {
  return seed * 1000003ULL + experiment * 10007ULL + trial;
}

double failureAt(const std::vector<Outcome>& outcomes, size_t n) {
  size_t failed = 0;
  for (const Outcome& o : outcomes) failed += !o || *o > n;
  return double(failed) / double(outcomes.size());
}

// Smallest n (multiple of step) up to max whose failure rate is at most `rate`.
std::optional<size_t> samplesFor(const std::vector<Outcome>& outcomes, double rate, size_t max) {
  std::vector<size_t> ns;
  for (const Outcome& o : outcomes)
    if (o) ns.push_back(*o);
  std::sort(ns.begin(), ns.end());
  for (size_t n : ns)
    if (n <= max && failureAt(outcomes, n) <= rate) return n;
  return std::nullopt;
}

std::string orMore(const std::optional<size_t>& n, size_t max) {
  return n ? std::to_string(*n) : "> " + std::to_string(max);
}

// Least-squares slope of ln(failure) against n, over the n where at least 3 trials failed.
std::optional<double> logSlope(const std::vector<Outcome>& outcomes, size_t max) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (size_t n = 0; n <= max; ++n) {
    double f = failureAt(outcomes, n);
    if (f * double(outcomes.size()) < 3) break;
    double y = std::log(f);
    sx += double(n), sy += y, sxx += double(n) * double(n), sxy += double(n) * y, ++m;
  }
  if (m < 3) return std::nullopt;
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

std::vector<std::pair<double, double>> failureCurve(const std::vector<Outcome>& outcomes,
                                                    size_t max, size_t points) {
  std::vector<std::pair<double, double>> curve;
  size_t step = std::max<size_t>(1, max / points);
  for (size_t n = 0; n <= max; n += step) {
    double f = failureAt(outcomes, n);
    curve.emplace_back(double(n), f);
    if (f == 0) break;
  }
  return curve;
}

// Volume of the unit ball in R^m.
double unitBall(int m) { return std::pow(M_PI, m / 2.0) / std::tgamma(m / 2.0 + 1); }

// Volume of the intersection of two m-balls of radius r whose centres are D apart (Monte Carlo
// over the first ball's bounding box, a fixed seed: the theorem's eta).
double lensVolume(int m, double r, double D) {
  Random random(12345);
  const size_t samples = 400000;
  size_t inside = 0;
  std::vector<double> p(m);
  for (size_t s = 0; s < samples; ++s) {
    double a = 0, b = 0;
    for (int i = 0; i < m; ++i) {
      p[i] = random.uniform(-r, r);
      a += p[i] * p[i];
      double q = i == 0 ? p[i] - D : p[i];
      b += q * q;
    }
    inside += a <= r * r && b <= r * r;
  }
  return std::pow(2 * r, m) * double(inside) / double(samples);
}

struct DimSetup {
  int d, k;
  double rho;
};

// The manifolds per family after which Theorem 3.3's bound, with its own constants, puts the
// failure rate under 1 %: mu_A for a rho/sqrt2 ball in A, eta_B for the lens of two rho/sqrt2
// balls in B whose centres are rho apart (the worst case).
size_t theoremBound(const DimSetup& s) {
  const double r = s.rho / std::sqrt(2.0);
  const double mu = unitBall(s.k) * std::pow(r, s.k);
  const double etaB = lensVolume(s.d - s.k, r, s.rho);
  const double L = 0.6 + 0.4 * std::sqrt(double(s.d - 1));  // the path's three legs
  const double pieces = std::ceil(L / s.rho);
  size_t n = 0;
  while (n < 100000000 &&
         pieces * (std::pow(1 - mu, double(n)) + std::pow(1 - etaB, double(n))) > 0.01)
    n = n ? n * 11 / 10 + 1 : 1;
  return n;
}

// One dimension's trials of MMS and of PRM, each outcome with its time.
struct DimTrials {
  std::vector<Outcome> mms, prm;
  std::vector<double> mmsSeconds, prmSeconds;
};

DimTrials runDimTrials(const LabOptions& o, const DimSetup& s, size_t si, size_t trials,
                       size_t maxRounds, size_t maxMilestones) {
  const BoxSpace space = wallWithHole(s.d, s.rho, 2 * s.d, o.seed);
  const Point start = wallStart(s.d), goal = wallGoal(s.d);
  DimTrials t{std::vector<Outcome>(trials), std::vector<Outcome>(trials),
              std::vector<double>(trials), std::vector<double>(trials)};
  Stopwatch clock;
  EuclideanMmsSettings settings;
  settings.families = perpendicularFamilies(s.d, s.k);
  settings.maxRounds = maxRounds;
  parallelFor(trials, o.threads, [&](size_t i) {
    EuclideanMmsSettings mine = settings;
    mine.seed = trialSeed(o.seed, si, i);
    EuclideanMmsResult r = solveEuclideanMms(space, start, goal, mine);
    t.mms[i] = r.rounds;
    t.mmsSeconds[i] = r.seconds;
  });
  const double mmsWall = clock.seconds();
  parallelFor(trials, o.threads, [&](size_t i) {
    PrmSettings ps;
    ps.maxMilestones = maxMilestones;
    ps.seed = trialSeed(o.seed, 100 + si, i);
    PrmResult r = solvePrmOnBoxes(space, start, goal, ps);
    t.prm[i] = r.milestones;
    t.prmSeconds[i] = r.seconds;
  });
  say(o, "completeness d = " + std::to_string(s.d) + ": " + std::to_string(trials) +
             " MMS trials " + fmt(mmsWall, 2) + " s, PRM trials " +
             fmt(clock.seconds() - mmsWall, 2) + " s");
  return t;
}

// The dimension's row of completeness.md.
void writeCompletenessRow(std::ostream& md, const DimSetup& s, const DimTrials& t, size_t maxRounds,
                          size_t maxMilestones) {
  const double eta = std::pow(2 * s.rho, s.d - s.k);
  const double trials = double(t.mms.size());
  const size_t boundN = theoremBound(s);
  auto slope = logSlope(t.mms, maxRounds);
  double mmsMs = 0, prmMs = 0;
  for (double v : t.mmsSeconds) mmsMs += 1000 * v / trials;
  for (double v : t.prmSeconds) prmMs += 1000 * v / trials;
  md << "| " << s.d << " | " << s.k << " | " << s.rho << " | " << fmt(eta) << " | "
     << fmt(0.1 * std::pow(2 * s.rho, s.d - 1)) << " | " << (slope ? fmt(*slope) : std::string("-"))
     << " (" << fmt(std::log(1 - eta)) << ") | "
     << orMore(samplesFor(t.mms, 0.1, maxRounds), maxRounds) << " / "
     << orMore(samplesFor(t.mms, 0.01, maxRounds), maxRounds) << " | ~" << boundN << " | "
     << fmt(mmsMs) << " | " << orMore(samplesFor(t.prm, 0.1, maxMilestones), maxMilestones) << " / "
     << orMore(samplesFor(t.prm, 0.01, maxMilestones), maxMilestones) << " | " << fmt(prmMs)
     << " |\n";
}

}  // namespace

std::vector<LabFile> completenessLab(const LabOptions& o) {
  std::vector<DimSetup> setups = {
      {2, 1, 0.02}, {3, 2, 0.02}, {4, 2, 0.1}, {5, 3, 0.1}, {6, 3, 0.17}};
  if (o.quick) setups.resize(2);
  const size_t trials = o.trials ? o.trials : o.quick ? 24 : 1000;
  const size_t maxRounds = o.quick ? 60 : 250, maxMilestones = o.quick ? 1500 : 6000;

  std::ostringstream csv, md;
  csv << "method,d,k,rho,samples,failures,trials\n";
  std::vector<Series> mmsSeries, prmSeries;
  md << "| d | k | rho | eta = (2 rho)^(d-k) | hole volume 0.1 (2 rho)^(d-1) | MMS log-failure "
        "slope (ln(1 - eta)) | MMS n for <= 10 % "
        "/ 1 % failure | theorem's bound: n for 1 % | MMS ms per trial | PRM milestones for "
        "<= 10 % / 1 % | PRM ms per trial |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (size_t si = 0; si < setups.size(); ++si) {
    const DimSetup& s = setups[si];
    const DimTrials t = runDimTrials(o, s, si, trials, maxRounds, maxMilestones);
    const double eta = std::pow(2 * s.rho, s.d - s.k);
    Series m{"d = " + std::to_string(s.d), seriesColour(si), failureCurve(t.mms, maxRounds, 75)};
    Series pred{"", seriesColour(si), {}, true, false};
    for (size_t n = 0; n <= maxRounds; n += 5) {
      double f = std::pow(1 - eta, double(n));
      if (f < 0.2 / double(trials)) break;
      pred.points.emplace_back(double(n), f);
    }
    mmsSeries.push_back(m);
    mmsSeries.push_back(pred);
    prmSeries.push_back(
        {"d = " + std::to_string(s.d), seriesColour(si), failureCurve(t.prm, maxMilestones, 80)});
    for (auto [n, f] : failureCurve(t.mms, maxRounds, maxRounds))
      csv << "mms," << s.d << "," << s.k << "," << s.rho << "," << n << ","
          << size_t(std::lround(f * double(trials))) << "," << trials << "\n";
    for (auto [n, f] : failureCurve(t.prm, maxMilestones, 200))
      csv << "prm," << s.d << "," << s.k << "," << s.rho << "," << n << ","
          << size_t(std::lround(f * double(trials))) << "," << trials << "\n";

    writeCompletenessRow(md, s, t, maxRounds, maxMilestones);
  }
  std::ostringstream head;
  head << "# mms lab completeness\n\n"
       << trials << " trials per dimension, seed " << o.seed << "; MMS at most " << maxRounds
       << " manifolds per family, PRM at most " << maxMilestones
       << " milestones (k = 10). n: manifolds per family (n_A = n_B), besides the two through "
          "start and goal.\n\n";
  PlotSpec mmsPlot{"MMS: failure rate against manifolds per family (dashed: (1 - eta)^n)",
                   "manifolds per family n (n_A = n_B)", "failure rate", false, true};
  PlotSpec prmPlot{"OMPL PRM: failure rate against milestones", "milestones", "failure rate", false,
                   true};
  return {{"completeness.md", head.str() + md.str()},
          {"completeness.csv", csv.str()},
          {"completeness-mms.svg", linePlot(mmsPlot, mmsSeries)},
          {"completeness-prm.svg", linePlot(prmPlot, prmSeries)}};
}

namespace {

// Flume and tunnel: PRM and MMS solving each, success and time against eps; rows of
// passages.csv and passages.md, and the success and time series.
void flumeAndTunnel(const LabOptions& o, const std::vector<double>& epsilons, std::ostream& csv,
                    std::ostream& md, std::vector<Series>& success, std::vector<Series>& times) {
  const size_t trials = o.trials ? o.trials : o.quick ? 4 : 50;
  const size_t maxRounds = o.quick ? 40 : 400, maxMilestones = o.quick ? 2000 : 50000;
  csv << "space,eps,planner,trial,solved,samples,seconds\n";
  // PRM, MMS with planes and lines in every axis direction, and MMS with the theorem's one
  // perpendicular pair whose lines run through the wall (planes fixing x, lines along x): the
  // pair that does not lie along either passage.
  const char* planners[] = {"PRM", "MMS, all axes", "MMS, x pair only"};
  md << "## Flume and tunnel: success and time\n\n"
     << trials << " trials per cell; PRM at most " << maxMilestones
     << " milestones (k = 10); MMS at most " << maxRounds
     << " rounds (a manifold of each family per round), with the planes fixing x through start "
        "and goal. All axes: planes and lines in every axis direction (six families); x pair: "
        "planes fixing x and lines along x. Cells: solved, median time and samples (milestones "
        "or manifolds) of the solved trials.\n\n| passage | eps | volume 0.3 eps^2 | PRM | "
        "MMS, all axes | MMS, x pair only |\n|---|---|---|---|---|---|\n";
  const char* spaces[] = {"flume", "tunnel"};
  for (size_t sp = 0; sp < 2; ++sp) {
    std::vector<Series> ok, tm;
    for (size_t pl = 0; pl < 3; ++pl) {
      ok.push_back({std::string(planners[pl]) + ", " + spaces[sp], seriesColour(pl), {}, sp == 1});
      tm.push_back(ok.back());
    }
    for (size_t ei = 0; ei < epsilons.size(); ++ei) {
      const double eps = epsilons[ei];
      const BoxSpace space = sp == 0 ? flume(eps) : tunnel(eps);
      const Point start = passageStart(), goal = passageGoal();
      std::vector<std::vector<Outcome>> out(3, std::vector<Outcome>(trials));
      std::vector<std::vector<double>> sec(3, std::vector<double>(trials));
      parallelFor(3 * trials, o.threads, [&](size_t i) {
        size_t pl = i / trials, t = i % trials;
        uint64_t seed = trialSeed(o.seed, 1000 + 100 * pl + 10 * sp + ei, t);
        if (pl == 0) {
          PrmSettings ps;
          ps.maxMilestones = maxMilestones;
          ps.seed = seed;
          PrmResult r = solvePrmOnBoxes(space, start, goal, ps);
          out[pl][t] = r.milestones;
          sec[pl][t] = r.seconds;
          return;
        }
        EuclideanMmsSettings ms;
        ms.families = pl == 1 ? linesAndPlanes3d() : std::vector<std::vector<int>>{{0}, {1, 2}};
        ms.queryFamilies = {0};
        ms.maxRounds = maxRounds;
        ms.seed = seed;
        EuclideanMmsResult m = solveEuclideanMms(space, start, goal, ms);
        out[pl][t] = m.rounds ? std::optional<size_t>(m.manifolds) : std::nullopt;
        sec[pl][t] = m.seconds;
      });
      md << "| " << spaces[sp] << " | " << eps << " | " << fmt(0.3 * eps * eps);
      std::string line = std::string("passages ") + spaces[sp] + " eps = " + fmt(eps) + ":";
      for (size_t pl = 0; pl < 3; ++pl) {
        std::vector<double> s, n;
        for (size_t t = 0; t < trials; ++t) {
          if (out[pl][t]) s.push_back(sec[pl][t]), n.push_back(double(*out[pl][t]));
          csv << spaces[sp] << "," << eps << "," << planners[pl] << "," << t << ","
              << bool(out[pl][t]) << "," << (out[pl][t] ? *out[pl][t] : 0) << "," << sec[pl][t]
              << "\n";
        }
        std::sort(s.begin(), s.end());
        std::sort(n.begin(), n.end());
        md << " | " << s.size() << "/" << trials;
        if (!s.empty())
          md << ", " << fmt(1000 * s[s.size() / 2]) << " ms, " << fmt(n[n.size() / 2]);
        ok[pl].points.emplace_back(eps, double(s.size()) / double(trials));
        if (!s.empty()) tm[pl].points.emplace_back(eps, s[s.size() / 2]);
        line += std::string(" ") + planners[pl] + " " + std::to_string(s.size()) + "/" +
                std::to_string(trials) + ";";
      }
      md << " |\n";
      say(o, line);
    }
    success.insert(success.end(), ok.begin(), ok.end());
    times.insert(times.end(), tm.begin(), tm.end());
  }
}

// The k-clearance sequences of both passages against eps, with the paper's values.
std::string kClearanceOfPassages(const LabOptions& o, const std::vector<double>& epsilons,
                                 std::vector<Series>& kSeries) {
  const char* spaces[] = {"flume", "tunnel"};
  std::ostringstream kmd;
  kmd << "\n## k-clearance of flume and tunnel\n\nEstimated radius of the largest k-disk "
         "along the best path (bottleneck over the free arrangement cells, each split 5 times "
         "per axis; rays capped at 1, the cube's faces not counted as walls); in brackets the "
         "exact values for these boxes. Dimension: the largest k < 3 "
         "whose k-clearance is at least 10 times the 3-clearance (0: none is).\n\n"
         "| passage | eps | 3-clearance | 2-clearance | 1-clearance | dimension |\n"
         "|---|---|---|---|---|---|\n";
  std::vector<std::vector<std::vector<double>>> seq(
      2, std::vector<std::vector<double>>(epsilons.size()));
  parallelFor(2 * epsilons.size(), o.threads, [&](size_t i) {
    size_t sp = i / epsilons.size(), ei = i % epsilons.size();
    const BoxSpace space = sp == 0 ? flume(epsilons[ei]) : tunnel(epsilons[ei]);
    DiskSearch ds;
    ds.seed = o.seed;
    seq[sp][ei] = kClearanceSequence(space, passageStart(), passageGoal(), o.quick ? 3 : 5, ds);
  });
  for (size_t sp = 0; sp < 2; ++sp) {
    for (int k = 3; k >= 1; --k) {
      Series s{std::string(spaces[sp]) + ", k = " + std::to_string(k),
               seriesColour(3 * sp + 3 - k),
               {},
               sp == 1};
      for (size_t ei = 0; ei < epsilons.size(); ++ei)
        s.points.emplace_back(epsilons[ei], seq[sp][ei][3 - k]);
      kSeries.push_back(s);
    }
    for (size_t ei = 0; ei < epsilons.size(); ++ei) {
      double e = epsilons[ei];
      const auto& q = seq[sp][ei];
      std::string exact3 = sp == 0 ? fmt(e * e / 2) : fmt(e / 2);
      std::string exact2 = sp == 0 ? ">= 1" : fmt(e / std::sqrt(2.0));
      kmd << "| " << spaces[sp] << " | " << e << " | " << fmt(q[0]) << " (" << exact3 << ") | "
          << fmt(q[1]) << " (" << exact2 << ") | " << fmt(q[2]) << " | " << passageDimension(q, 10)
          << " |\n";
    }
  }
  say(o, "passages: k-clearance of flume and tunnel done");

  return kmd.str();
}

// The Pacman's passage, a sampled proxy of its k-clearance against tightness: its table, and
// its plot added to `files`.
std::string pacmanPassages(const LabOptions& o, std::vector<LabFile>& files) {
  std::string pacmanMd;
  if (o.pacman) {
    std::vector<double> tightness = {0, 0.5, 0.8, 0.9, 0.95, 0.98};
    if (o.quick) tightness = {0, 0.9};
    std::vector<PacmanPassage> pac(tightness.size());
    parallelFor(tightness.size(), o.threads, [&](size_t i) {
      PacmanPassageSettings ps;
      ps.seed = o.seed;
      if (o.quick)
        ps.pathSamples = 30, ps.climbSteps = 10, ps.disk.randomFrames = 4, ps.disk.refineSteps = 4,
        ps.disk.directions = 12;
      pac[i] = measurePacmanPassage(tightness[i], ps);
    });
    std::ostringstream pm;
    pm << "\n## Pacman: a sampled proxy of the k-clearance\n\nPer tightness: MMS's path (seed "
       << o.seed
       << "), its configuration of least clearance, moved within the path's normal hyperplane "
          "to the widest point near it; there, the estimated radius of the largest k-disk (k = "
          "6..1) in C-space, angles scaled by each robot's radius. Dimension: the largest k < 6 "
          "whose value is at least 10 times the 6-clearance (0: none is, not a narrow passage at "
          "this cap).\n\n| tightness | path | k = 6 | 5 | "
          "4 | 3 | 2 | 1 | dimension |\n|---|---|---|---|---|---|---|---|---|\n";
    std::vector<Series> ps;
    for (int k = 6; k >= 1; --k) {
      Series s{"k = " + std::to_string(k), seriesColour(6 - k), {}};
      for (size_t i = 0; i < tightness.size(); ++i)
        if (pac[i].found) s.points.emplace_back(tightness[i], pac[i].sequence[6 - k]);
      ps.push_back(s);
    }
    for (size_t i = 0; i < tightness.size(); ++i) {
      pm << "| " << tightness[i] << " | "
         << (pac[i].found ? fmt(pac[i].planSeconds, 2) + " s" : std::string("not found"));
      for (int j = 0; j < 6; ++j)
        pm << " | " << (pac[i].found ? fmt(pac[i].sequence[j]) : std::string("-"));
      pm << " | " << (pac[i].found ? std::to_string(passageDimension(pac[i].sequence, 10)) : "-")
         << " |\n";
    }
    pacmanMd = pm.str();
    PlotSpec spec{"Pacman: k-disk radius at the path's tightest point", "tightness",
                  "radius (scene units)", false, true};
    files.push_back({"passages-pacman.svg", linePlot(spec, ps)});
    say(o, "passages: Pacman proxy done");
  }

  return pacmanMd;
}

}  // namespace

std::vector<LabFile> passagesLab(const LabOptions& o) {
  std::vector<double> epsilons = {0.2, 0.1, 0.05, 0.025, 0.0125};
  if (o.quick) epsilons = {0.2, 0.1};
  std::ostringstream csv, md;
  std::vector<Series> success, times, kSeries;
  flumeAndTunnel(o, epsilons, csv, md, success, times);
  const std::string kmd = kClearanceOfPassages(o, epsilons, kSeries);
  std::vector<LabFile> files;
  const std::string pacmanMd = pacmanPassages(o, files);
  PlotSpec s1{"Success rate: flume (solid) vs tunnel (dashed)", "eps", "solved share", true, false};
  PlotSpec s2{"Median time of solved trials", "eps", "seconds", true, true};
  PlotSpec s3{"k-clearance: flume (solid) vs tunnel (dashed)", "eps", "k-clearance", true, true};
  files.push_back({"passages-success.svg", linePlot(s1, success)});
  files.push_back({"passages-time.svg", linePlot(s2, times)});
  files.push_back({"passages-kclearance.svg", linePlot(s3, kSeries)});
  files.push_back({"passages.csv", csv.str()});
  files.push_back({"passages.md", "# mms lab passages\n\nSeed " + std::to_string(o.seed) + ".\n\n" +
                                      md.str() + kmd + pacmanMd});
  return files;
}

}  // namespace mms::lab
