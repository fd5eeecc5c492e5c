#include "io/OmplAppCfg.h"

#include <boost/property_tree/ini_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "mms/Errors.h"

namespace mms {

namespace {

// The [problem] section only: OMPL.app's [planner] sections repeat keys (aps=, cforest=),
// which an INI reader rightly refuses.
std::map<std::string, std::string> problemSection(const std::string& text,
                                                  const std::string& file) {
  std::istringstream in(text);
  std::ostringstream section;
  std::string line;
  bool inside = false, found = false;
  while (std::getline(in, line)) {
    std::string t = line;
    t.erase(0, t.find_first_not_of(" \t\r"));
    if (!t.empty() && t[0] == '[') {
      inside = t.rfind("[problem]", 0) == 0;
      found = found || inside;
    }
    if (inside) section << line << "\n";
  }
  if (!found) throw InputError(file + ": [problem]: no such section");
  boost::property_tree::ptree pt;
  std::istringstream sectionText(section.str());
  try {
    boost::property_tree::ini_parser::read_ini(sectionText, pt);
  } catch (const boost::property_tree::ini_parser_error& e) {
    throw InputError(file + ": [problem] line " + std::to_string(e.line()) + ": " + e.message());
  }
  // "[problem]" begins the line, but the INI reader may read the name on as something else
  // ("[problem]x]", a NUL): no such section then, rather than an exception from the tree.
  const auto problem = pt.get_child_optional("problem");
  if (!problem) throw InputError(file + ": [problem]: no such section");
  std::map<std::string, std::string> kv;
  for (const auto& [key, value] : *problem) kv[key] = value.data();
  return kv;
}

double number(const std::map<std::string, std::string>& kv, const std::string& key,
              const std::string& file) {
  auto it = kv.find(key);
  if (it == kv.end()) throw InputError(file + ": [problem] " + key + ": missing");
  std::istringstream in(it->second);
  in.imbue(std::locale::classic());
  double v;
  std::string rest;
  if (!(in >> v) || (in >> rest) || !std::isfinite(v))
    throw InputError(file + ": [problem] " + key + ": not a number: '" + it->second + "'");
  return v;
}

std::string text(const std::map<std::string, std::string>& kv, const std::string& key,
                 const std::string& file) {
  auto it = kv.find(key);
  if (it == kv.end() || it->second.empty())
    throw InputError(file + ": [problem] " + key + ": missing");
  return it->second;
}

}  // namespace

OmplAppProblem parseOmplAppProblem(const std::string& cfg, const std::string& source) {
  const auto kv = problemSection(cfg, source);
  OmplAppProblem p;
  if (auto n = kv.find("name"); n != kv.end()) p.name = n->second;
  if (auto c = kv.find("control"); c != kv.end()) p.control = c->second;
  if (auto o = kv.find("objective"); o != kv.end()) p.objective = o->second;
  p.robotMesh = text(kv, "robot", source);
  p.worldMesh = text(kv, "world", source);
  p.start = {number(kv, "start.x", source), number(kv, "start.y", source),
             number(kv, "start.theta", source)};
  p.goal = {number(kv, "goal.x", source), number(kv, "goal.y", source),
            number(kv, "goal.theta", source)};
  p.volume = {number(kv, "volume.min.x", source), number(kv, "volume.min.y", source),
              number(kv, "volume.max.x", source), number(kv, "volume.max.y", source)};
  return p;
}

OmplAppProblem readOmplAppProblem(const std::string& cfgFile) {
  std::ifstream in(cfgFile);
  if (!in) throw InputError(cfgFile + ": (file): cannot open");
  std::ostringstream text;
  text << in.rdbuf();
  return parseOmplAppProblem(text.str(), cfgFile);
}

}  // namespace mms
