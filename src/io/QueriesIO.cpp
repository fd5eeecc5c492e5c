#include "io/QueriesIO.h"

#include "geometry/CollisionChecker.h"
#include "io/Json.h"
#include "util/Number.h"

namespace mms {

std::vector<Query> loadQueries(const std::string& file, const Scene& scene) {
  return parseQueries(json_in::parseFile(file), file, scene);
}

std::vector<Query> parseQueries(const nlohmann::json& doc, const std::string& file,
                                const Scene& scene) {
  using json_in::Node;
  const Node root(doc, file, "");
  root.allowOnly({"format", "queries"});
  if (root["format"].string() != kQueriesFormat)
    root["format"].fail("unsupported format '" + root["format"].string() +
                        "' (expected mms-queries/1)");
  const Node qs = root["queries"];
  const size_t n = qs.arraySize(1, 100000);
  const CollisionChecker checker(scene);
  std::vector<Query> out;
  for (size_t i = 0; i < n; ++i) {
    qs[i].allowOnly({"start", "goal"});
    Query q;
    Pose* ends[2] = {&q.start, &q.goal};
    const char* names[2] = {"start", "goal"};
    for (int e = 0; e < 2; ++e) {
      const Node p = qs[i][names[e]];
      p.arraySize(3, 3);
      *ends[e] = {p[size_t(0)].number(json_in::kMaxCoordinate),
                  p[size_t(1)].number(json_in::kMaxCoordinate),
                  p[size_t(2)].number(json_in::kMaxAngle)};
      const Contact c = checker.robotContact(0, *ends[e]);
      if (c.kind != Contact::Kind::None)
        p.fail("robot '" + scene.robots[0].name + "' collides with " + c.describe(scene));
      if (scene.robots[0].motion == Motion::Translate &&
          ends[e]->theta != scene.robots[0].start.theta)
        p.fail("a translate robot keeps its angle " + formatNumber(scene.robots[0].start.theta));
    }
    out.push_back(q);
  }
  return out;
}

}  // namespace mms
