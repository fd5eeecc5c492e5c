#include "io/Trajectories.h"

#include <cmath>
#include <cstdio>

#include "check/PathChecker.h"

namespace mms {

namespace {

// Whether the robot moves through pose `mid` (at tm) at one velocity from a (ta) to b (tb), or
// stands at all three: then the row at `mid` says nothing the rows around it do not.
bool passedThrough(const Pose& a, double ta, const Pose& mid, double tm, const Pose& b, double tb) {
  const double s = tb > ta ? (tm - ta) / (tb - ta) : 0;
  auto on = [&](double u, double m, double v) {
    return std::abs(m - (u + s * (v - u))) <= 1e-9 * (1 + std::abs(m));
  };
  return on(a.x, mid.x, b.x) && on(a.y, mid.y, b.y) && on(a.theta, mid.theta, b.theta);
}

}  // namespace

std::string trajectoriesCsv(const Scene& scene, const std::vector<Config>& waypoints) {
  const CollisionChecker checker(scene);
  std::vector<double> at{0};  // each waypoint's time
  for (size_t k = 1; k < waypoints.size(); ++k) {
    double segment = 0;
    for (size_t i = 0; i < scene.robots.size(); ++i)
      segment = std::max(
          segment, poseCost(checker, i, poseOf(waypoints[k - 1], i), poseOf(waypoints[k], i)));
    at.push_back(at.back() + segment);
  }
  std::string csv = "robot,name,t,x,y,theta\n";
  char row[192];
  for (size_t i = 0; i < scene.robots.size(); ++i) {
    const std::string name = scene.robots[i].name;
    size_t last = 0;  // the last row written
    for (size_t k = 0; k < waypoints.size(); ++k) {
      const bool ends = k == 0 || k + 1 == waypoints.size();
      if (!ends && passedThrough(poseOf(waypoints[last], i), at[last], poseOf(waypoints[k], i),
                                 at[k], poseOf(waypoints[k + 1], i), at[k + 1]))
        continue;
      const Pose p = poseOf(waypoints[k], i);
      std::snprintf(row, sizeof row, "%zu,", i);
      csv += row;
      // A name with a comma or a quote is quoted, CSV's way.
      if (name.find_first_of(",\"\n") == std::string::npos) {
        csv += name;
      } else {
        csv += '"';
        for (const char c : name) csv += c == '"' ? std::string("\"\"") : std::string(1, c);
        csv += '"';
      }
      std::snprintf(row, sizeof row, ",%.17g,%.17g,%.17g,%.17g\n", at[k], p.x, p.y, p.theta);
      csv += row;
      last = k;
    }
  }
  return csv;
}

}  // namespace mms
