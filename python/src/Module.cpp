// The Python module's native part, mms._mms: scenes, planning, certification and pictures over
// the planner library. The friendly surface (keyword arguments, Result, bench) is mms/__init__.py;
// this file converts data and keeps the promises that need C++: the GIL released while a planner
// works, Ctrl-C turned into the planner's cancel flag, and every InputError a mms.InputError.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "io/AnyScene.h"
#include "io/Json.h"
#include "io/PathIO.h"
#include "io/RecordIO.h"
#include "io/RunSummary.h"
#include "io/SceneIO.h"
#include "mms/mms.h"
#include "render/HtmlViewer.h"
#include "render/SvgRenderer.h"
#include "scenarios/Catalog.h"

namespace py = pybind11;

namespace mms::python {
namespace {

using Json = nlohmann::json;

/// A scene and the name its messages use (the file, or "scene" for Python data).
struct PyScene {
  std::shared_ptr<const Scene> scene;
  std::string source;
};

/// Python data in the JSON format's shape -> JSON. Only what JSON holds is accepted; a number
/// that is not finite passes through, so that the scene reader names its field.
Json toJson(const py::handle& o, const std::string& source, int depth = 0) {
  if (depth > json_in::kMaxDepth)
    throw InputError(source + ": nested deeper than " + std::to_string(json_in::kMaxDepth) +
                     " levels");
  if (o.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(o)) return o.cast<bool>();
  if (py::isinstance<py::int_>(o)) {
    // Beyond 64 bits an int is no coordinate; the reader's range check names the field.
    try {
      return o.cast<long long>();
    } catch (const py::cast_error&) {
      return o.cast<double>();
    }
  }
  if (py::isinstance<py::float_>(o)) return o.cast<double>();
  if (py::isinstance<py::str>(o)) return o.cast<std::string>();
  if (py::isinstance<py::dict>(o)) {
    Json j = Json::object();
    for (const auto& [k, v] : o.cast<py::dict>()) {
      if (!py::isinstance<py::str>(k))
        throw InputError(source + ": a key is " + std::string(py::str(py::repr(k))) +
                         ", not a string");
      j[k.cast<std::string>()] = toJson(v, source, depth + 1);
    }
    return j;
  }
  if (py::isinstance<py::list>(o) || py::isinstance<py::tuple>(o)) {
    Json j = Json::array();
    for (const auto& v : o) j.push_back(toJson(v, source, depth + 1));
    return j;
  }
  throw InputError(source + ": " + std::string(py::str(py::type::of(o).attr("__name__"))) +
                   " value " + std::string(py::str(py::repr(o))).substr(0, 60) +
                   " has no JSON form (use dicts, lists, strings and numbers)");
}

/// A file name from a str or an os.PathLike.
std::string fileName(const py::handle& o, const char* who) {
  if (py::isinstance<py::str>(o)) return o.cast<std::string>();
  if (py::hasattr(o, "__fspath__")) {
    const py::object p = o.attr("__fspath__")();
    if (py::isinstance<py::str>(p)) return p.cast<std::string>();
  }
  throw InputError(std::string(who) + ": expected a file name, not " +
                   std::string(py::str(py::type::of(o).attr("__name__"))));
}

py::object fromJson(const Json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

PyScene sceneFromData(const py::handle& data, const std::string& source) {
  const Json doc = py::isinstance<py::str>(data)
                       ? json_in::parseText(data.cast<std::string>(), source)
                       : toJson(data, source);
  auto scene = std::make_shared<const Scene>(parseScene(doc, source));
  // The same notes mms.load_scene gives for a file (angles in degrees by mistake).
  ImportNotes notes;
  noteClosedRings(doc, source, notes);
  noteAngles(*scene, source, notes);
  notes.mistakes.insert(notes.mistakes.end(), notes.warnings.begin(), notes.warnings.end());
  for (const std::string& w : notes.mistakes)
    if (PyErr_WarnEx(PyExc_UserWarning, w.c_str(), 1) != 0) throw py::error_already_set();
  return {std::move(scene), source};
}

/// Waypoints from Python: a sequence of sequences of 3 numbers per robot.
std::vector<Config> waypointsFrom(const py::handle& o, const Scene& scene, const char* who) {
  const std::string where = std::string(who) + ": path";
  if (py::isinstance<py::str>(o) || !py::isinstance<py::sequence>(o))
    throw InputError(where + ": expected a list of waypoints, each a list of numbers");
  std::vector<Config> out;
  size_t i = 0;
  for (const auto& w : o.cast<py::sequence>()) {
    const std::string at = where + "[" + std::to_string(i++) + "]";
    if (py::isinstance<py::str>(w) || !py::isinstance<py::sequence>(w))
      throw InputError(at + ": expected a list of numbers");
    Config q;
    for (const auto& x : w.cast<py::sequence>()) {
      if (py::isinstance<py::bool_>(x) ||
          !(py::isinstance<py::float_>(x) || py::isinstance<py::int_>(x)))
        throw InputError(at + ": " + std::string(py::str(py::repr(x))).substr(0, 40) +
                         " is not a number");
      q.push_back(x.cast<double>());
      if (!std::isfinite(q.back())) throw InputError(at + ": a coordinate is not finite");
    }
    if (q.size() != scene.dof())
      throw InputError(at + ": " + std::to_string(q.size()) + " numbers; the scene's " +
                       std::to_string(scene.robots.size()) + " robot(s) need " +
                       std::to_string(scene.dof()) + " (x, y, theta each)");
    out.push_back(std::move(q));
  }
  if (out.empty()) throw InputError(where + ": no waypoints");
  return out;
}

py::dict certificateDict(const PathCheckResult& c) {
  py::dict d;
  d["ok"] = c.ok;
  d["reason"] = c.reason;
  d["segment"] = c.segment;
  d["parameter"] = c.parameter;
  d["min_clearance"] = c.minClearance;
  d["evaluations"] = c.evaluations;
  d["translation"] = c.translation;
  d["rotation"] = c.rotation;
  d["makespan"] = c.makespan;
  d["makespan_bound"] = c.makespanBound;
  d["distance"] = c.distance;
  d["distance_bound"] = c.distanceBound;
  d["moving_at_once"] = c.movingAtOnce;
  return d;
}

/// One planner run as Python sees it; the scene is kept for save() and pictures.
struct PyResult {
  PyScene scene;
  PlanResult result;
  std::string planner;
  uint64_t seed = 1;
  double timeLimit = 0;
};

const ParamSpec& paramNamed(const PlannerInfo& info, const std::string& key) {
  for (const ParamSpec& s : info.params)
    if (s.key() == key || s.name == key) return s;
  std::string known;
  for (const ParamSpec& s : info.params) known += (known.empty() ? "" : ", ") + s.key();
  throw InputError("mms.plan: " + key + ": not a parameter of planner '" + info.name + "'" +
                   (known.empty() ? " (it has none)" : " (its parameters: " + known + ")"));
}

double paramValue(const ParamSpec& spec, const py::handle& v) {
  const std::string at = "mms.plan: " + spec.key();
  double x = 0;
  if (py::isinstance<py::str>(v)) {
    // Text names a choice; a number given as text is a mistake Python users do not make on
    // purpose.
    if (spec.choices.empty())
      throw InputError(at + ": " + std::string(py::str(py::repr(v))).substr(0, 40) +
                       " is not a number (give it without quotes)");
    if (const std::string why = spec.parse(v.cast<std::string>(), x); !why.empty())
      throw InputError(at + ": " + why);
    return x;
  }
  if (!(py::isinstance<py::bool_>(v) || py::isinstance<py::int_>(v) ||
        py::isinstance<py::float_>(v)))
    throw InputError(at + ": " + std::string(py::str(py::repr(v))).substr(0, 40) +
                     " is not a number");
  x = v.cast<double>();
  if (const std::string why = spec.problem(x); !why.empty()) throw InputError(at + ": " + why);
  return x;
}

/// Runs solve() on a thread of its own while this one, without the GIL, wakes every 50 ms to
/// let Python's signal handlers run: Ctrl-C sets the planner's cancel flag, the planner stops
/// at its next checkpoint, and the KeyboardInterrupt goes on from here. `progress` (a Python
/// callable or None) is called here too, with the latest statistics the planner reported, so
/// that it runs on the caller's thread with the GIL held.
PlanResult solveReleasingGil(Planner& planner, double timeLimit, const py::object& progress) {
  std::atomic<bool> cancel{false};
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  std::optional<PlanStatistics> report;  // the latest one not yet passed on
  PlanResult result;
  std::exception_ptr error;
  const Termination stop(timeLimit, &cancel);
  Planner::Progress onProgress;
  if (!progress.is_none())
    onProgress = [&](const PlanStatistics& s) {
      std::lock_guard<std::mutex> lock(m);
      report = s;
    };
  std::thread worker([&] {
    try {
      result = planner.solve(stop, onProgress);
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(m);
    done = true;
    cv.notify_all();
  });
  // Ends the worker before an exception leaves: it refers to this frame.
  auto finish = [&] {
    cancel = true;
    py::gil_scoped_release nogil;
    worker.join();
  };
  for (bool finished = false; !finished;) {
    std::optional<PlanStatistics> latest;
    {
      py::gil_scoped_release nogil;
      std::unique_lock<std::mutex> lock(m);
      finished = cv.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; });
      latest.swap(report);
    }
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (latest && !finished) progress(fromJson(toJson(*latest)));
    } catch (...) {
      finish();
      throw;
    }
  }
  {
    py::gil_scoped_release nogil;
    worker.join();
  }
  if (error) std::rethrow_exception(error);
  return result;
}

PyResult plan(const PyScene& s, const std::string& planner, uint64_t seed, double timeLimit,
              const py::dict& params, const py::object& progress, bool record) {
  const PlannerInfo* info = findPlanner(planner);
  if (!info) {
    std::string known;
    for (const PlannerInfo& p : planners()) known += (known.empty() ? "" : ", ") + p.name;
    throw InputError("mms.plan: planner '" + planner + "': unknown (known: " + known + ")");
  }
  if (!(std::isfinite(timeLimit) && timeLimit >= 0.01 && timeLimit <= 1e7))
    throw InputError("mms.plan: time_limit=" + formatNumber(timeLimit) +
                     ": not in [0.01, 1e+07] seconds");
  PlannerParams pp;
  pp.seed = seed;
  pp.record = record;
  for (const auto& [k, v] : params) {
    const ParamSpec& spec = paramNamed(*info, k.cast<std::string>());
    pp.values[spec.name] = paramValue(spec, v);
  }
  PyResult r;
  r.scene = s;
  r.planner = planner;
  r.seed = pp.seed;
  r.timeLimit = timeLimit;
  std::unique_ptr<Planner> p = makePlanner(planner, *s.scene, pp, s.source);
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw InputError("mms.plan: progress: expected a callable or None");
  r.result = solveReleasingGil(*p, timeLimit, progress);
  {
    py::gil_scoped_release nogil;
    p.reset();  // a large roadmap takes a while to free
  }
  return r;
}

std::string svgOf(const PyScene& s, const std::vector<Config>* waypoints, double width) {
  if (!(std::isfinite(width) && width >= 16 && width <= 100000))
    throw InputError("mms.render_svg: width=" + formatNumber(width) + ": not in [16, 100000]");
  SvgOptions o;
  o.widthPx = width;
  if (!waypoints) return renderSvg(*s.scene, nullptr, o);
  Path path;
  path.waypoints = *waypoints;
  return renderSvg(*s.scene, &path, o);
}

}  // namespace
}  // namespace mms::python

PYBIND11_MODULE(_mms, m) {
  using namespace mms;
  using namespace mms::python;
  m.doc() = "mms's native part; import mms, not this module (docs/python.md).";
  m.attr("__version__") = version();
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

  py::class_<PyScene>(m, "Scene",
                      "A planning problem: bounds, obstacles and robots with start and goal "
                      "poses.\n\nScene(data, source='scene'): `data` is a dict in the shape of "
                      "the mms-scene/1 JSON format (docs/formats.md) or its JSON text; `source` "
                      "names the scene in error messages. Files: mms.load_scene(); generated "
                      "scenes: mms.scenario().")
      .def(py::init([](const py::object& data, const std::string& source) {
             return sceneFromData(data, source);
           }),
           py::arg("data"), py::arg("source") = "scene")
      .def_property_readonly("source", [](const PyScene& s) { return s.source; })
      .def_property_readonly("name", [](const PyScene& s) { return s.scene->name; })
      .def_property_readonly("robot_names",
                             [](const PyScene& s) {
                               std::vector<std::string> names;
                               for (const Robot& r : s.scene->robots) names.push_back(r.name);
                               return names;
                             })
      .def_property_readonly("obstacle_count",
                             [](const PyScene& s) { return s.scene->obstacles.size(); })
      .def_property_readonly("dof", [](const PyScene& s) { return s.scene->dof(); })
      .def_property_readonly("start", [](const PyScene& s) { return startConfig(*s.scene); })
      .def_property_readonly("goal", [](const PyScene& s) { return goalConfig(*s.scene); })
      .def("to_json", [](const PyScene& s) { return sceneToJson(*s.scene).dump(1); })
      .def("to_dict", [](const PyScene& s) { return fromJson(sceneToJson(*s.scene)); })
      .def("save", [](const PyScene& s, const py::object& file) {
        saveScene(*s.scene, fileName(file, "Scene.save"));
      });

  m.def("load_scene", [](const std::string& file) {
    ImportNotes notes;
    PyScene s{std::make_shared<const Scene>(loadAnyScene(file, notes)), file};
    std::vector<std::string> all = notes.mistakes;
    all.insert(all.end(), notes.warnings.begin(), notes.warnings.end());
    return py::make_tuple(s, all);
  });
  m.def("scenario_names", [] { return scenarioNames(); });
  m.def("scenario", [](const ScenarioRequest& r) {
    return PyScene{std::make_shared<const Scene>(makeScenario(r, "mms.scenario: ")), r.name};
  });
  py::class_<ScenarioRequest>(m, "ScenarioRequest")
      .def(py::init<>())
      .def_readwrite("name", &ScenarioRequest::name)
      .def_readwrite("tightness", &ScenarioRequest::tightness)
      .def_readwrite("seed", &ScenarioRequest::seed)
      .def_readwrite("slack", &ScenarioRequest::slack)
      .def_readwrite("slack_given", &ScenarioRequest::slackGiven)
      .def_readwrite("m_parts_only", &ScenarioRequest::mPartsOnly)
      .def_readwrite("robots", &ScenarioRequest::robots)
      .def_readwrite("spacing", &ScenarioRequest::spacing)
      .def_readwrite("obstacles", &ScenarioRequest::obstacles)
      .def_readwrite("translate", &ScenarioRequest::translate);

  m.def("planners", [] {
    py::list out;
    for (const PlannerInfo& info : planners()) {
      py::list params;
      for (const ParamSpec& s : info.params) {
        py::dict p;
        p["name"] = s.key();
        p["option"] = "--" + s.name;
        p["type"] = s.type == ParamSpec::Type::Integer ? "int"
                    : s.type == ParamSpec::Type::Flag  ? "flag"
                                                       : "float";
        p["min"] = s.min;
        p["max"] = s.max;
        p["default"] =
            s.choices.empty() ? py::cast(s.value) : py::cast(s.choices.at(size_t(s.value)));
        p["choices"] = s.choices;
        p["help"] = s.help;
        params.append(p);
      }
      py::dict d;
      d["name"] = info.name;
      d["summary"] = info.summary;
      d["multi_query"] = info.multiQuery;
      d["params"] = params;
      out.append(d);
    }
    return out;
  });

  py::class_<PyResult>(m, "PlanResult")
      .def_property_readonly("found", [](const PyResult& r) { return r.result.found(); })
      .def_property_readonly("status", [](const PyResult& r) { return toString(r.result.status); })
      .def_property_readonly("waypoints", [](const PyResult& r) { return r.result.waypoints; })
      .def_property_readonly("planner", [](const PyResult& r) { return r.planner; })
      .def_property_readonly("seed", [](const PyResult& r) { return r.seed; })
      .def_property_readonly("time_limit", [](const PyResult& r) { return r.timeLimit; })
      .def_property_readonly("scene", [](const PyResult& r) { return r.scene; })
      .def_property_readonly("stats",
                             [](const PyResult& r) { return fromJson(toJson(r.result.stats)); })
      .def_property_readonly("parameters",
                             [](const PyResult& r) { return fromJson(parametersJson(r.result)); })
      .def_property_readonly(
          "certificate", [](const PyResult& r) { return certificateDict(r.result.certificate); })
      .def_property_readonly("record",
                             [](const PyResult& r) -> py::object {
                               if (!r.result.record) return py::none();
                               return fromJson(recordToJson(*r.result.record, r.result.stats));
                             })
      // The viewer's page (mms view): the scene, the path when found, the record when kept.
      .def("view_html",
           [](const PyResult& r) {
             Path path;
             path.waypoints = r.result.waypoints;
             std::optional<RecordFile> record;
             if (r.result.record) record = RecordFile{*r.result.record, r.result.stats};
             return renderHtmlViewer(*r.scene.scene, r.result.found() ? &path : nullptr,
                                     record ? &*record : nullptr);
           })
      .def("save", [](const PyResult& r, const std::string& file) {
        if (!r.result.found())
          throw InputError(file + ": no path to save (the run's status is " +
                           toString(r.result.status) + ")");
        writePathFile(*r.scene.scene, r.result, r.planner, r.seed, file);
      });

  m.def("plan", &plan);
  m.def("check", [](const PyScene& s, const py::object& path) {
    const std::vector<Config> w = waypointsFrom(path, *s.scene, "mms.check");
    PathCheckResult c;
    {
      py::gil_scoped_release nogil;
      c = certify(*s.scene, w);
    }
    return certificateDict(c);
  });
  m.def("load_path",
        [](const PyScene& s, const std::string& file) { return readPathFile(file, *s.scene); });
  m.def("render_svg", [](const PyScene& s, const py::object& path, double width) {
    if (path.is_none()) return svgOf(s, nullptr, width);
    const std::vector<Config> w = waypointsFrom(path, *s.scene, "mms.render_svg");
    return svgOf(s, &w, width);
  });
}
