#include "planner/MmsPlanner.h"

#include <cmath>

#include "geometry/PolygonOps.h"
#include "path/CellRoute.h"

namespace mms {

Scene singleRobotScene(const Scene& scene, size_t robot) {
  Scene s = scene;
  s.robots = {scene.robots[robot]};
  return s;
}

MmsPlanner::MmsPlanner(const Scene& scene, size_t robot, MmsSettings settings)
    : scene_(singleRobotScene(scene, robot)),
      settings_(settings),
      checker_(scene_),
      sliceWorld_(scene_, 0),
      lineWorld_(scene_, 0),
      rng_(settings.seed),
      angleShift_(rng_.uniform(0, 2 * M_PI)) {}

MmsPlanner::~MmsPlanner() = default;

// Angles come in levels: n evenly spaced with a random shift, then the midpoints between
// them, and so on, so every prefix covers the circle evenly.
double MmsPlanner::nextAngle() {
  const size_t n = std::max<size_t>(1, settings_.nTheta);
  const size_t k = angleCount_++;
  double fraction;
  if (k < n) {
    fraction = double(k) / n;
  } else {
    size_t level = 1, start = n;  // level L holds n * 2^(L-1) angles
    while (k >= start + (n << (level - 1))) start += n << (level - 1), ++level;
    const size_t j = k - start;
    fraction = double(2 * j + 1) / double(n << level);
  }
  return std::remainder(angleShift_ + 2 * M_PI * fraction, 2 * M_PI);
}

Vec2 MmsPlanner::nextLinePoint() {
  const Box& b = scene_.bounds;
  auto uniform = [&] { return Vec2{rng_.uniform(b.xmin, b.xmax), rng_.uniform(b.ymin, b.ymax)}; };
  // Half the points where some slice has room for the robot: lines there can connect.
  if (!slices_.empty() && rng_.uniform() < settings_.freeLineShare) {
    for (int attempt = 0; attempt < 20; ++attempt) {
      const Slice& s = slices_[rng_.below(slices_.size())];
      const Vec2 p = uniform();
      if (s.locate(p) >= 0) return p;
    }
  }
  return uniform();
}

void MmsPlanner::addSlice(double theta) {
  Stopwatch watch;
  slices_.emplace_back(sliceWorld_, exact::rationalAngleNear(theta, 30), settings_.pointLocation);
  const Slice& s = slices_.back();
  stats_.sliceSeconds += watch.seconds();
  const uint32_t k = uint32_t(slices_.size() - 1);
  std::vector<size_t> nodes;
  for (size_t f = 0; f < s.fscCount(); ++f)
    nodes.push_back(graph_.addNode({ConnectivityGraph::Kind::SliceCell, k, uint32_t(f)}));
  sliceNodes_.push_back(std::move(nodes));
  stats_.sliceCells += s.fscCount();
  Stopwatch connect;
  for (size_t l = 0; l < lines_.size(); ++l) {
    const int a = lines_[l].arcContaining(s.theta());
    if (a < 0) continue;
    const int f = s.locate(lines_[l].point());
    if (f >= 0) graph_.addEdge(sliceNodes_[k][f], lineNodes_[l][a]);
  }
  stats_.connectSeconds += connect.seconds();
}

size_t MmsPlanner::addLine(Vec2 p) {
  Stopwatch watch;
  lines_.emplace_back(lineWorld_, checker_, 0, p, &stats_.lineStats);
  const Line& line = lines_.back();
  stats_.lineSeconds += watch.seconds();
  const uint32_t l = uint32_t(lines_.size() - 1);
  std::vector<size_t> nodes;
  for (size_t a = 0; a < line.arcs().size(); ++a)
    nodes.push_back(graph_.addNode({ConnectivityGraph::Kind::LineArc, l, uint32_t(a)}));
  lineNodes_.push_back(std::move(nodes));
  stats_.lineArcs += line.arcs().size();
  Stopwatch connect;
  if (!line.arcs().empty())
    for (size_t k = 0; k < slices_.size(); ++k) {
      const int a = line.arcContaining(slices_[k].theta());
      if (a < 0) continue;
      const int f = slices_[k].locate(p);
      if (f >= 0) graph_.addEdge(sliceNodes_[k][f], lineNodes_[l][a]);
    }
  stats_.connectSeconds += connect.seconds();
  return l;
}

// Turns a graph path (line arc, slice cell, line arc, ..., line arc) into waypoints: rotate
// inside each arc to the next slice's angle, translate inside each slice cell to the next
// line's point.
std::vector<Config> MmsPlanner::motion(const std::vector<size_t>& nodes, const Pose& start,
                                       const Pose& goal) {
  std::vector<Config> w{{start.x, start.y, start.theta}};
  double theta = start.theta;
  Vec2 at{start.x, start.y};
  for (size_t i = 0; i < nodes.size(); ++i) {
    const ConnectivityGraph::Node& n = graph_.node(nodes[i]);
    if (n.kind == ConnectivityGraph::Kind::LineArc) {
      const Arc& arc = lines_[n.manifold].arcs()[n.cell];
      const double target = i + 1 < nodes.size() ? slices_[graph_.node(nodes[i + 1]).manifold].theta() : goal.theta;
      // Inside a partial arc the direction is forced; on a full circle take the short way.
      theta += arc.full() ? std::remainder(target - theta, 2 * M_PI) : arc.unwrap(target) - arc.unwrap(theta);
      w.push_back({at.x, at.y, theta});
    } else {
      const Slice& s = slices_[n.manifold];
      const Vec2 to = lines_[graph_.node(nodes[i + 1]).manifold].point();
      const auto route = routeInCell(s.cell(n.cell), [&](Vec2 p) { return s.locate(p) == int(n.cell); }, at, to);
      if (!route) return {};
      for (size_t j = 1; j < route->size(); ++j) w.push_back({(*route)[j].x, (*route)[j].y, theta});
      at = to;
    }
  }
  return w;
}

// Random shortcuts: replace the stretch between two waypoints by the straight motion when the
// checker certifies it. Deterministic for a seed (attempt count, not time, bounds it).
void MmsPlanner::shortcut(std::vector<Config>& w) {
  PathCheckSettings quick;
  quick.maxEvaluations = 20000;
  for (size_t attempt = 0; attempt < settings_.shortcutAttempts && w.size() > 2; ++attempt) {
    size_t i = rng_.below(w.size()), j = rng_.below(w.size());
    if (i > j) std::swap(i, j);
    if (j < i + 2) continue;
    if (checkMotion(scene_, checker_, {w[i], w[j]}, quick).ok) w.erase(w.begin() + i + 1, w.begin() + j);
  }
}

// A translate-only robot has a 2-D C-space: the one slice at its angle is its exact free
// space, so start and goal are connected iff they lie in the same cell. Complete, no sampling.
MmsResult::Status MmsPlanner::solveTranslation(const Pose& start, const Pose& goal, MmsResult& result) {
  if (slices_.empty()) addSlice(start.theta);
  const Slice& s = slices_.front();
  const int a = s.locate({start.x, start.y}), b = s.locate({goal.x, goal.y});
  if (a < 0 || a != b) return MmsResult::Status::NotFound;
  const auto route = routeInCell(s.cell(a), [&](Vec2 p) { return s.locate(p) == a; }, {start.x, start.y},
                                 {goal.x, goal.y});
  if (!route) return MmsResult::Status::NotFound;
  std::vector<Config> w;
  for (Vec2 p : *route) w.push_back({p.x, p.y, start.theta});
  shortcut(w);
  Path path;
  path.waypoints = w;
  result.certificate = checkPath(scene_, checker_, path);
  if (!result.certificate.ok) {
    ++stats_.rejectedPaths;
    return MmsResult::Status::NotFound;
  }
  stats_.pathCells = 1;
  result.waypoints = std::move(w);
  return MmsResult::Status::Found;
}

MmsResult MmsPlanner::solve(const Pose& start, const Pose& goal, const Termination& stop,
                            const std::function<void(const MmsStats&)>& progress) {
  Stopwatch total;
  MmsResult result;
  scene_.robots[0].start = start;
  scene_.robots[0].goal = goal;
  auto finish = [&](MmsResult::Status st) {
    stats_.graphNodes = graph_.nodeCount();
    stats_.graphEdges = graph_.edgeCount();
    stats_.slices = slices_.size();
    stats_.lines = lines_.size();
    stats_.totalSeconds += total.seconds();
    result.status = st;
    result.stats = stats_;
    return result;
  };
  if (scene_.robots[0].motion == Motion::Translate) return finish(solveTranslation(start, goal, result));
  // Start and goal enter through lines at their positions (a line holds every angle).
  const size_t startLine = addLine({start.x, start.y}), goalLine = addLine({goal.x, goal.y});
  const int startArc = lines_[startLine].arcContaining(start.theta);
  const int goalArc = lines_[goalLine].arcContaining(goal.theta);
  if (startArc < 0 || goalArc < 0) return finish(MmsResult::Status::NotFound);  // not free
  const size_t from = lineNodes_[startLine][startArc], to = lineNodes_[goalLine][goalArc];

  size_t targetSlices = std::max(slices_.size(), settings_.nTheta);
  size_t targetLines = std::max(lines_.size(), settings_.nLines);
  Stopwatch sinceReport;
  auto report = [&](bool force) {
    if (!progress || (!force && sinceReport.seconds() < 1.0)) return;
    stats_.slices = slices_.size();
    stats_.lines = lines_.size();
    stats_.graphNodes = graph_.nodeCount();
    stats_.graphEdges = graph_.edgeCount();
    progress(stats_);
    sinceReport = Stopwatch();
  };
  while (true) {
    ++stats_.rounds;
    while (slices_.size() < targetSlices && !stop()) addSlice(nextAngle()), report(false);
    while (lines_.size() < targetLines && !stop()) addLine(nextLinePoint()), report(false);
    Stopwatch search;
    const auto nodes = graph_.path(from, to);
    stats_.searchSeconds += search.seconds();
    if (nodes) {
      Stopwatch build;
      std::vector<Config> w = motion(*nodes, start, goal);
      stats_.motionSeconds += build.seconds();
      Stopwatch certify;
      if (!w.empty()) {
        shortcut(w);
        Path path;
        path.waypoints = w;
        result.certificate = checkPath(scene_, checker_, path);
      }
      stats_.certifySeconds += certify.seconds();
      if (!w.empty() && result.certificate.ok) {
        stats_.pathCells = nodes->size();
        for (size_t v : *nodes) result.cells.push_back(graph_.node(v));
        result.waypoints = std::move(w);
        return finish(MmsResult::Status::Found);
      }
      ++stats_.rejectedPaths;
    }
    report(true);
    if (stop()) return finish(stop.cancelled() ? MmsResult::Status::Cancelled : MmsResult::Status::NotFound);
    targetSlices *= 2;
    targetLines *= 2;
  }
}

}  // namespace mms
