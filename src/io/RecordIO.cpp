#include "io/RecordIO.h"

#include <cmath>

#include "io/Json.h"
#include "io/RunSummary.h"
#include "util/AtomicFile.h"

namespace mms {

namespace {

using json_in::Node;
using nlohmann::json;

double rounded(double v) { return std::round(v * 1e6) / 1e6; }

// A ring as [x0, y0, x1, y1, ...]: half the brackets of pairs, in the largest part of a file.
json flat(const Ring& ring) {
  json a = json::array();
  for (const Vec2& p : ring) {
    a.push_back(rounded(p.x));
    a.push_back(rounded(p.y));
  }
  return a;
}

json manifoldJson(const RecordManifold& m) {
  json j = {{"index", m.index},
            {"family", m.family},
            {"at", rounded(m.at)},
            {"round", m.round},
            {"subspace", m.subspace},
            {"cells", m.cells},
            {"reached", {rounded(m.reached[0]), rounded(m.reached[1])}},
            {"path", m.onPath}};
  if (m.family.find("slice") != std::string::npos) {
    j["theta"] = rounded(m.theta);
    j["vertices"] = m.vertices;
    json regions = json::array();
    for (const auto& cell : m.regions) {
      json rings = json::array();
      for (const Ring& r : cell) rings.push_back(flat(r));
      regions.push_back(std::move(rings));
    }
    j["regions"] = std::move(regions);
  } else {
    j["point"] = {rounded(m.point.x), rounded(m.point.y)};
    json arcs = json::array();
    for (const auto& [lo, hi] : m.arcs) arcs.push_back({rounded(lo), rounded(hi)});
    j["arcs"] = std::move(arcs);
  }
  return j;
}

// Items one by one into `out` as a JSON array: a record's document is never built whole (a
// DOM of a 50 MB file would take ten times that).
template <class Items, class ToJson>
void appendArray(std::string& out, const Items& items, const ToJson& toJson) {
  out += '[';
  bool first = true;
  for (const auto& item : items) {
    if (!first) out += ',';
    first = false;
    out += toJson(item).dump();
  }
  out += ']';
}

void appendTree(std::string& out, const RecordTree& t) {
  out += "{\"total_states\":" + std::to_string(t.totalStates) +
         ",\"total_edges\":" + std::to_string(t.totalEdges) + ",\"states\":";
  appendArray(out, t.states, [](const Config& q) {
    json s = json::array();
    for (double v : q) s.push_back(rounded(v));
    return s;
  });
  json at = json::array();
  for (float a : t.at) at.push_back(rounded(a));
  out += ",\"at\":" + at.dump() + ",\"edges\":";
  appendArray(out, t.edges, [](const std::array<uint32_t, 2>& e) { return json{e[0], e[1]}; });
  out += '}';
}

json growthJson(const RecordGrowth& g) {
  json at = json::array(), counts = json::object();
  for (float a : g.at) at.push_back(rounded(a));
  for (const auto& [kind, n] : g.counts) counts[kind] = n;
  return {{"at", std::move(at)}, {"counts", std::move(counts)}};
}

json headJson(const PlanRecord& r, const PlanStatistics& stats) {
  json subspaces = json::array(), searches = json::array();
  for (const RecordSubspace& s : r.subspaces) {
    json held = json::array();
    for (const auto& [robot, p] : s.held)
      held.push_back({robot, rounded(p.x), rounded(p.y), rounded(p.theta)});
    json j = {{"moving", s.moving}, {"held", std::move(held)}};
    if (s.attached >= 0) j["attached"] = s.attached;
    subspaces.push_back(std::move(j));
  }
  for (const RecordSearch& s : r.searches)
    searches.push_back({{"at", rounded(s.at)},
                        {"round", s.round},
                        {"manifolds", s.manifolds},
                        {"nodes", s.nodes},
                        {"edges", s.edges},
                        {"connected", s.connected}});
  return {{"format", kRecordFormat},
          {"planner", r.planner},
          {"robots", r.robots},
          {"seconds", rounded(r.seconds)},
          {"record_seconds", rounded(r.recordSeconds)},
          {"statistics", toJson(stats)},
          {"subspaces", std::move(subspaces)},
          {"growth", growthJson(r.growth)},
          {"searches", std::move(searches)}};
}

}  // namespace

std::string recordText(const PlanRecord& r, const PlanStatistics& stats) {
  std::string out = headJson(r, stats).dump();
  out.pop_back();  // the head's closing brace: the large arrays follow
  out += ",\"manifolds\":";
  appendArray(out, r.manifolds, manifoldJson);
  if (!r.tree.states.empty() || r.tree.totalStates > 0) {
    out += ",\"tree\":";
    appendTree(out, r.tree);
  }
  return out + '}';
}

json recordToJson(const PlanRecord& r, const PlanStatistics& stats) {
  return json::parse(recordText(r, stats));
}

void saveRecord(const PlanRecord& record, const PlanStatistics& stats, const std::string& file) {
  writeFileAtomically(file, recordText(record, stats) + "\n");
}

namespace {

constexpr size_t kMaxItems = 100'000'000;

bool flag(const Node& n) {
  if (!n.json().is_boolean())
    n.fail(std::string("expected true or false, found ") + json_in::typeName(n.json()));
  return n.json().get<bool>();
}

size_t count(const Node& n, size_t limit = kMaxItems) {
  const double v = n.number(double(limit));
  if (v < 0 || v != std::floor(v))
    n.fail("expected a whole number from 0, found " + formatNumber(v));
  return size_t(v);
}

float time(const Node& n) {
  const double v = n.number(1e9);
  if (v < 0 && v != -1) n.fail("expected seconds from 0 (or -1: never), found " + formatNumber(v));
  return float(v);
}

// A flat ring [x0, y0, ...]: checked number by number without a Node each (a record holds
// millions); the one that fails is named.
Ring flatRing(const Node& n) {
  const size_t size = n.arraySize(6, 2 * json_in::kMaxVertices);
  if (size % 2)
    n.fail("expected x, y pairs: an even count of numbers, found " + std::to_string(size));
  Ring r(size / 2);
  for (size_t i = 0; i < size; ++i) {
    const json& v = n.json()[i];
    const double x = v.is_number() ? v.get<double>() : NAN;
    if (!std::isfinite(x) || std::fabs(x) > json_in::kMaxCoordinate)
      n[i].number(json_in::kMaxCoordinate);
    (i % 2 ? r[i / 2].y : r[i / 2].x) = x;
  }
  return r;
}

RecordSubspace subspaceOf(const Node& n, size_t robots) {
  n.allowOnly({"moving", "held", "attached"});
  RecordSubspace s;
  s.moving = count(n["moving"], robots - 1);
  if (n.has("attached")) s.attached = long(count(n["attached"], robots - 1));
  const Node held = n["held"];
  for (size_t i = 0, k = held.arraySize(0, robots); i < k; ++i) {
    const Node h = held[i];
    h.arraySize(4, 4);
    s.held.emplace_back(count(h[size_t(0)], robots - 1),
                        Pose{h[size_t(1)].number(json_in::kMaxCoordinate),
                             h[size_t(2)].number(json_in::kMaxCoordinate),
                             h[size_t(3)].number(json_in::kMaxAngle)});
  }
  return s;
}

RecordManifold manifoldOf(const Node& n, size_t subspaces) {
  n.allowOnly({"index", "family", "at", "round", "subspace", "cells", "reached", "path", "theta",
               "vertices", "regions", "point", "arcs"});
  RecordManifold m;
  m.index = count(n["index"]);
  m.family = n["family"].string();
  m.at = time(n["at"]);
  m.round = uint32_t(count(n["round"], 1u << 30));
  m.subspace = uint32_t(count(n["subspace"], subspaces == 0 ? 0 : subspaces - 1));
  if (subspaces == 0) n["subspace"].fail("no subspaces are listed");
  m.cells = count(n["cells"]);
  const Node reached = n["reached"];
  reached.arraySize(2, 2);
  m.reached = {time(reached[size_t(0)]), time(reached[size_t(1)])};
  m.onPath = flag(n["path"]);
  if (n.has("theta")) m.theta = n["theta"].number(json_in::kMaxAngle);
  if (n.has("vertices")) m.vertices = count(n["vertices"]);
  if (n.has("point")) m.point = n["point"].point(json_in::kMaxCoordinate);
  if (n.has("regions")) {
    const Node regions = n["regions"];
    for (size_t c = 0, k = regions.arraySize(0, kMaxItems); c < k; ++c) {
      const Node cell = regions[c];
      auto& rings = m.regions.emplace_back();
      for (size_t i = 0, r = cell.arraySize(1, kMaxItems); i < r; ++i)
        rings.push_back(flatRing(cell[i]));
    }
  }
  if (n.has("arcs")) {
    const Node arcs = n["arcs"];
    for (size_t a = 0, k = arcs.arraySize(0, kMaxItems); a < k; ++a) {
      const Node arc = arcs[a];
      arc.arraySize(2, 2);
      m.arcs.emplace_back(arc[size_t(0)].number(json_in::kMaxAngle),
                          arc[size_t(1)].number(json_in::kMaxAngle));
    }
  }
  return m;
}

RecordTree treeOf(const Node& n, size_t robots) {
  n.allowOnly({"states", "at", "edges", "total_states", "total_edges"});
  RecordTree t;
  const Node states = n["states"], at = n["at"], edges = n["edges"];
  const size_t k = states.arraySize(0, kMaxItems);
  at.arraySize(k, k);
  for (size_t i = 0; i < k; ++i) {
    const Node s = states[i];
    s.arraySize(3 * robots, 3 * robots);
    Config q(3 * robots);
    for (size_t c = 0; c < q.size(); ++c)
      q[c] = s[c].number(c % 3 == 2 ? json_in::kMaxAngle : json_in::kMaxCoordinate);
    t.states.push_back(std::move(q));
    t.at.push_back(time(at[i]));
  }
  for (size_t e = 0, m = edges.arraySize(0, kMaxItems); e < m; ++e) {
    const Node edge = edges[e];
    edge.arraySize(2, 2);
    if (k == 0) edge.fail("an edge, but no states");
    t.edges.push_back(
        {uint32_t(count(edge[size_t(0)], k - 1)), uint32_t(count(edge[size_t(1)], k - 1))});
  }
  t.totalStates = count(n["total_states"]);
  t.totalEdges = count(n["total_edges"]);
  return t;
}

RecordGrowth growthOf(const Node& n) {
  n.allowOnly({"at", "counts"});
  RecordGrowth g;
  const Node at = n["at"], counts = n["counts"];
  const size_t k = at.arraySize(0, kMaxItems);
  for (size_t i = 0; i < k; ++i) g.at.push_back(time(at[i]));
  counts.requireObject();
  for (const auto& [kind, values] : counts.json().items()) {
    const Node v(values, counts.file(), counts.where() + "." + kind);
    v.arraySize(k, k);
    auto& c = g.counts.emplace_back(kind, std::vector<size_t>{});
    for (size_t i = 0; i < k; ++i) c.second.push_back(count(v[i]));
  }
  return g;
}

}  // namespace

RecordFile parseRecord(const json& doc, const std::string& source, size_t robots) {
  const Node root(doc, source, "");
  root.allowOnly({"format", "planner", "robots", "seconds", "record_seconds", "statistics",
                  "subspaces", "growth", "manifolds", "searches", "tree"});
  if (root["format"].string() != kRecordFormat)
    root["format"].fail("expected \"" + std::string(kRecordFormat) + "\", found \"" +
                        root["format"].string() + "\"");
  RecordFile f;
  PlanRecord& r = f.record;
  r.planner = root["planner"].string();
  r.robots = count(root["robots"]);
  if (r.robots != robots)
    root["robots"].fail("the record is of " + std::to_string(r.robots) + " robots, the scene has " +
                        std::to_string(robots));
  r.seconds = root["seconds"].number(1e9);
  r.recordSeconds = root["record_seconds"].number(1e9);
  try {
    f.stats = statisticsFromJson(root["statistics"].json());
  } catch (const std::exception& e) {
    root["statistics"].fail(e.what());
  }
  const Node subspaces = root["subspaces"], manifolds = root["manifolds"],
             searches = root["searches"];
  for (size_t i = 0, k = subspaces.arraySize(0, kMaxItems); i < k; ++i)
    r.subspaces.push_back(subspaceOf(subspaces[i], robots));
  for (size_t i = 0, k = manifolds.arraySize(0, kMaxItems); i < k; ++i)
    r.manifolds.push_back(manifoldOf(manifolds[i], r.subspaces.size()));
  for (size_t i = 0, k = searches.arraySize(0, kMaxItems); i < k; ++i) {
    const Node s = searches[i];
    s.allowOnly({"at", "round", "manifolds", "nodes", "edges", "connected"});
    r.searches.push_back({time(s["at"]), uint32_t(count(s["round"], 1u << 30)),
                          count(s["manifolds"]), count(s["nodes"]), count(s["edges"]),
                          flag(s["connected"])});
  }
  r.growth = growthOf(root["growth"]);
  if (root.has("tree")) r.tree = treeOf(root["tree"], robots);
  return f;
}

RecordFile loadRecord(const std::string& file, size_t robots) {
  return parseRecord(json_in::parseFile(file), file, robots);
}

}  // namespace mms
