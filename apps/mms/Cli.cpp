// The command line's subcommands: each registers its options on the app and says what runs
// when it is the one given (one function per subcommand).
#include "Cli.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <regex>
#include <type_traits>

#include "Commands.h"
#include "mms/Errors.h"
#include "mms/Planner.h"
#include "mms/mms.h"
#include "util/AtomicFile.h"
#include "util/CommandBoundary.h"
#include "util/Interrupt.h"
#include "util/MemoryLimit.h"
#include "util/Suggest.h"

namespace mms::cli {

namespace {

// CLI11's "Failed parsing abc as a FLOAT" (and a range check's "Value abc not in range 1 to
// 16" for text that is no number at all) in the wording of the scene readers' errors; a name
// that is none of those allowed (an option, a planner, a command) with the one likely meant.
}  // namespace

std::string parseErrorLine(const CLI::ParseError& e, const CLI::App& app,
                           const std::vector<std::string>& args) {
  static const std::regex kConversion("Failed parsing (.*) as a (FLOAT|INT|UINT)");
  static const std::regex kRange("Value (.*) not in range .*");
  static const std::regex kMember("(\\S+) not in \\{(.*)\\}");
  static const std::regex kUnexpected("arguments? (was|were) not expected: (.*)");
  std::string line =
      std::regex_replace(mms::oneLine(e.what()), kConversion, "'$1' is not a number");
  std::smatch m;
  double value = 0;
  if (std::regex_search(line, m, kRange) && !CLI::detail::lexical_cast(m[1].str(), value))
    line = m.prefix().str() + "'" + m[1].str() + "' is not a number";
  else if (std::regex_search(line, m, kMember))
    line += mms::didYouMean(m[1].str(), mms::split(m[2].str(), ','));
  else if (std::regex_search(line, m, kUnexpected)) {
    std::vector<std::string> options;
    for (const CLI::App* sub : app.get_subcommands({}))
      for (const CLI::Option* o : sub->get_options())
        for (const std::string& n : o->get_lnames()) options.push_back("--" + n);
    for (const std::string& given : mms::split(m[2].str(), ' '))
      if (given.rfind("--", 0) == 0) line += mms::didYouMean(given, options);
  } else if (line.find("A subcommand is required") != std::string::npos && !args.empty() &&
             args[0].rfind('-', 0) != 0) {
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands({})) commands.push_back(sub->get_name());
    line = "'" + args[0] + "' is not a command" + mms::didYouMean(args[0], commands);
  }
  return line;
}

namespace {

// --memory-limit: 0 (none) or a cap; one too small for the program itself ends as any other
// run out of memory does.
const CLI::Validator memoryLimitMb(
    [](std::string& v) -> std::string {
      double mb = -1;
      if (!CLI::detail::lexical_cast(v, mb)) return "not a number: " + v;
      return mb == 0 || (mb >= 1 && mb <= 1e7) ? "" : "must be 0 (no limit) or 1 to 1e7 MB";
    },
    "0 or 1 to 1e7");

// A parameter as the planners declare it: the first declaration, and each planner that takes
// it with its default there (planners share some, not always with one default).
struct DeclaredParam {
  mms::ParamSpec spec;
  std::vector<std::pair<std::string, double>> users;
};

// Every planner's parameters, once per name.
std::vector<DeclaredParam> declaredParams() {
  std::vector<DeclaredParam> out;
  for (const mms::PlannerInfo& p : mms::planners())
    for (const mms::ParamSpec& spec : p.params) {
      auto it = std::find_if(out.begin(), out.end(),
                             [&](const auto& e) { return e.spec.name == spec.name; });
      if (it == out.end()) it = out.insert(out.end(), {spec, {}});
      it->users.emplace_back(p.name, spec.value);
    }
  return out;
}

// "auto, mms" or "every OMPL planner" (every planner but auto and MMS's, mms*).
std::string plannerList(const std::vector<std::string>& names) {
  auto ours = [](const std::string& n) { return n == "auto" || n.rfind("mms", 0) == 0; };
  const auto& all = mms::planners();
  const size_t ompl =
      size_t(std::count_if(all.begin(), all.end(), [&](const auto& p) { return !ours(p.name); }));
  if (names.size() == ompl && std::none_of(names.begin(), names.end(), ours))
    return "every OMPL planner";
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return list;
}

// A parameter's help with the planners that take it and, where their defaults differ, each
// default with its planners in place of the declaration's one "(default X)".
std::string paramHelp(const DeclaredParam& d) {
  std::vector<std::pair<double, std::vector<std::string>>> byDefault;
  std::vector<std::string> all;
  for (const auto& [name, value] : d.users) {
    all.push_back(name);
    auto it = std::find_if(byDefault.begin(), byDefault.end(),
                           [v = value](const auto& e) { return e.first == v; });
    if (it == byDefault.end()) it = byDefault.insert(byDefault.end(), {value, {}});
    it->second.push_back(name);
  }
  std::string help = d.spec.help;
  if (byDefault.size() > 1) {
    if (const size_t at = help.rfind(" (default "); at != std::string::npos && help.back() == ')')
      help.erase(at);
    std::string defaults;
    for (const auto& [value, names] : byDefault) {
      const std::string shown =
          d.spec.choices.empty() ? mms::formatNumber(value) : d.spec.choices.at(size_t(value));
      defaults += (defaults.empty() ? "" : "; ") + shown + " for " + plannerList(names);
    }
    help += " (default " + defaults + ")";
  }
  // The planners that take it, where its group's title (paramGroup) does not say so.
  const std::string takers = plannerList(all);
  if (all.size() < mms::planners().size() && takers != "every OMPL planner" && takers != "auto" &&
      takers != "auto, mms, mms-ordered, mms-joint")
    help += " [" + takers + "]";
  return help;
}

// Where a parameter is listed in mms plan --help: by the planners that take it.
std::string paramGroup(const DeclaredParam& d) {
  auto ours = [](const std::string& n) { return n == "auto" || n.rfind("mms", 0) == 0; };
  size_t mine = 0;
  for (const auto& [name, value] : d.users) mine += ours(name) ? 1 : 0;
  if (d.users.size() == 1 && d.users[0].first == "auto") return "The default planner (auto)";
  if (mine == d.users.size()) return "MMS (auto, mms, mms-ordered, mms-joint)";
  if (mine == 0) return "OMPL's planners";
  return "Every planner: the path optimiser and the schedule";
}

std::string typeName(const mms::ParamSpec& spec) {
  if (!spec.choices.empty()) {
    std::string names;
    for (const std::string& c : spec.choices) names += (names.empty() ? "" : "|") + c;
    return names;
  }
  return (spec.type == mms::ParamSpec::Type::Integer ? "INT in [" : "FLOAT in [") +
         mms::formatNumber(spec.min) + ", " + mms::formatNumber(spec.max) + "]";
}

// A number in [lo, hi], read as a person writes it ("NUMBER in [0.01, 1e+06]"): NaN and
// infinity are refused, which CLI11's Range lets through (every comparison with NaN is false).
CLI::Option* numberIn(CLI::Option* o, double lo, double hi) {
  const std::string range = "[" + mms::formatNumber(lo) + ", " + mms::formatNumber(hi) + "]";
  return o->type_name("NUMBER in " + range)
      ->check(CLI::Validator(
          [lo, hi, range](std::string& s) -> std::string {
            double v = 0;
            if (!CLI::detail::lexical_cast(s, v)) return "'" + s + "' is not a number";
            if (!std::isfinite(v)) return "'" + s + "' is not a finite number";
            if (v < lo || v > hi) return s + " is not in " + range;
            return "";
          },
          ""));
}

CLI::Option* sceneArg(CLI::App* cmd, std::string& v, const std::string& help) {
  return cmd->add_option("SCENE", v, help + " (-: standard input)")->required()->type_name("FILE");
}
// `type`: what is written, FILE or DIR (a folder of files).
CLI::Option* outputOption(CLI::App* cmd, std::string& v, const std::string& help,
                          const char* type = "FILE") {
  return cmd->add_option("-o,--output", v, help)->required()->type_name(type);
}
CLI::Option* quietFlag(CLI::App* cmd, bool& v, const std::string& help) {
  return cmd->add_flag("-q,--quiet", v, help);
}
// A scene and, optionally, a path drawn on it or checked against it.
CLI::Option* sceneAndPath(CLI::App* cmd, std::string& scene, std::string& path,
                          const std::string& sceneHelp, const std::string& pathHelp) {
  sceneArg(cmd, scene, sceneHelp);
  return cmd->add_option("PATH", path, pathHelp + " (-: standard input)")->type_name("FILE");
}

// The file a conversion writes, and silence on success.
void convertedOutput(CLI::App* cmd, std::string& output, bool& quiet, const std::string& what) {
  outputOption(cmd, output, what + " to write (-: standard output)");
  quietFlag(cmd, quiet, "Print nothing on success");
}

CLI::Option* memoryLimitOption(CLI::App* cmd, double& v, const std::string& help) {
  return cmd->add_option("--memory-limit", v, help)
      ->capture_default_str()
      ->type_name("MB")
      ->check(memoryLimitMb);
}
CLI::Option* seedOption(CLI::App* cmd, uint64_t& v, const std::string& help) {
  // A negative seed would wrap round to a huge one silently.
  const CLI::Validator wholeNumber(
      [](std::string& s) {
        return s.find_first_not_of("0123456789") == std::string::npos && !s.empty()
                   ? std::string()
                   : "'" + s + "' is not a whole number from 0 up";
      },
      "UINT");
  return cmd->add_option("--seed", v, help)->capture_default_str()->check(wholeNumber);
}

// "-" for a file sends it to standard output and the command's report to standard error; at
// most one file can go there, and a folder never does.
void claimStandardOutput(const std::vector<std::pair<std::string, const char*>>& files,
                         const std::vector<std::pair<std::string, const char*>>& folders = {}) {
  for (const auto& [value, option] : folders)
    if (value == mms::kStandardOutput)
      throw mms::InputError(std::string("-: (") + option +
                            "): a folder is needed here, not standard output");
  const char* first = nullptr;
  for (const auto& [value, option] : files) {
    if (value != mms::kStandardOutput) continue;
    if (first)
      throw mms::InputError(std::string("-: (") + option + "): " + first +
                            " already writes to standard output");
    first = option;
  }
  if (first) mms::keepStandardOutputForData();
}

std::vector<std::string> plannerNames() {
  std::vector<std::string> names;
  for (const mms::PlannerInfo& p : mms::planners()) names.push_back(p.name);
  return names;
}

// Plans and assemblies: Ctrl-C ends them cleanly from here on, and the memory cap holds.
void startLongRun(double memoryMb) {
  mms::sigintFlag();
  if (!mms::limitMemory(memoryMb))
    throw mms::InputError("mms: --memory-limit: the system refused the limit");
}

// A subcommand: its arguments, the options `add` registers for them, and `run` once it is the
// one given. What `add` returns (an option to ask whether it was given, the planners'
// parameters) is passed to `run` after the arguments.
template <class Args, class Add, class Run>
Command command(CLI::App& app, const char* name, const std::string& help, Add add, Run run) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(name, help);
  if constexpr (std::is_void_v<std::invoke_result_t<Add, CLI::App*, Args&>>) {
    add(cmd, *args);
    return {cmd, [args, run] { return run(*args); }};
  } else {
    auto extra = add(cmd, *args);
    return {cmd, [args, run, extra] { return run(*args, extra); }};
  }
}

// A subcommand that writes one file, which "-o -" sends to standard output.
template <class Args, class Add>
Command withOneFile(CLI::App& app, const char* name, const std::string& help,
                    int (*run)(const Args&), Add add) {
  return command<Args>(app, name, help, add, [run](Args& a) {
    claimStandardOutput({{a.output, "-o"}});
    return run(a);
  });
}

// The options that need checking beyond CLI11's before a benchmark starts.
struct BenchOptions : BenchArgs {
  // By default the portfolio, MMS and the four OMPL planners the benchmarks compare against (all
  // fourteen at 12 runs of 60 s would take up to 2.8 h per scene).
  std::string planners = "auto,mms,prm,prm-bridge,rrtconnect,kpiece";
  std::string shard = "1/1";
};

}  // namespace

// Every planner's declared parameters, each one option of mms plan; which planner takes which
// is checked once the planner is known (mms::makePlanner).
class PlannerParamOptions {
 public:
  explicit PlannerParamOptions(CLI::App* cmd) {
    for (const DeclaredParam& d : declaredParams()) {
      const mms::ParamSpec& spec = d.spec;
      const std::string help = paramHelp(d);
      CLI::Option* o = spec.type == mms::ParamSpec::Type::Flag
                           ? cmd->add_flag("--" + spec.name, flag_[spec.name], help)
                           : cmd->add_option("--" + spec.name, text_[spec.name], help)
                                 ->type_name(typeName(spec));
      o->group(paramGroup(d));
      options_.emplace_back(spec, o);
    }
  }
  /// The parameters given, by name; throws InputError for a value out of its range.
  std::map<std::string, double> given() const {
    std::map<std::string, double> values;
    for (const auto& [spec, option] : options_) {
      if (option->count() == 0) continue;
      double v = 1;  // a flag given
      if (spec.type != mms::ParamSpec::Type::Flag)
        if (const std::string why = spec.parse(text_.at(spec.name), v); !why.empty())
          throw mms::InputError("mms: --" + spec.name + ": " + why + " (see mms plan --help)");
      values[spec.name] = v;
    }
    return values;
  }

 private:
  std::map<std::string, std::string> text_;
  std::map<std::string, bool> flag_;
  std::vector<std::pair<mms::ParamSpec, CLI::Option*>> options_;
};

Command addPlan(CLI::App& app) {
  auto run = [](PlanArgs& a, const std::shared_ptr<PlannerParamOptions>& params) {
    claimStandardOutput({{a.output, "-o"}, {a.svg, "--svg"}, {a.statsJson, "--stats-json"}});
    startLongRun(a.memoryMb);
    a.params.values = params->given();
    return plan(a);
  };
  return command<PlanArgs>(
      app, "plan",
      "Plan a certified motion with MMS (manifold samples: fixed-angle slices, fixed-position\n"
      "lines). Exit 0 path found and certified, 1 no path within the time limit, 2 bad input",
      [](CLI::App* planCmd, PlanArgs& pa) {
        sceneArg(planCmd, pa.scene, "Scene file");
        std::string plannerHelp =
            std::string("The planner (default ") + mms::kDefaultPlanner + "):";
        for (const mms::PlannerInfo& p : mms::planners())
          plannerHelp += "\n  " + p.name + ": " + p.summary;
        planCmd->add_option("--planner", pa.planner, plannerHelp)
            ->check(CLI::IsMember(plannerNames()))
            ->group("Planner");
        seedOption(planCmd, pa.seed, "Random seed (same seed, same path)")->group("Planner");
        numberIn(planCmd->add_option("--time-limit", pa.timeLimit, "Seconds before giving up")
                     ->capture_default_str()
                     ->group("Limits"),
                 0.01, 1e6);
        memoryLimitOption(
            planCmd, pa.memoryMb,
            "MB of address space; beyond it the run ends with \'out of memory\' (0: none)")
            ->group("Limits");
        planCmd
            ->add_option("-o,--output", pa.output,
                         "Write the path (mms-path/1) here (-: standard output)")
            ->type_name("FILE")
            ->group("Outputs");
        planCmd
            ->add_option("--svg", pa.svg,
                         "Write an animated SVG of the scene and path here (-: standard output)")
            ->type_name("FILE")
            ->group("Outputs");
        quietFlag(planCmd, pa.quiet, "No progress messages on stderr")->group("Outputs");
        planCmd
            ->add_option(
                "--stats-json", pa.statsJson,
                "Write a JSON summary of the run (status, times, sizes) here (-: standard output)")
            ->type_name("FILE")
            ->group("Outputs");
        planCmd
            ->add_flag("--svg-roadmap", pa.svgRoadmap,
                       "In the SVG, also draw the lines' points and the free-space cells of the "
                       "slices the path uses (one robot: auto then runs MMS alone)")
            ->group("Outputs");
        planCmd
            ->add_flag("--save-roadmap", pa.saveRoadmap,
                       "One robot: keep the free-space cells the path uses and the lines' points "
                       "in the path file, for mms view (auto then runs MMS alone)")
            ->group("Outputs");
        planCmd
            ->add_option(
                "--record", pa.record,
                "Write a record of the planning (mms-record/1): what the planner built and when "
                "(MMS: its slices' cells, lines' arcs, subspaces and components; OMPL: its tree "
                "or graph), for mms view --record; with several queries, numbered files")
            ->type_name("FILE")
            ->group("Outputs");
        planCmd
            ->add_option("--queries", pa.queries,
                         "Answer several queries on one roadmap: a JSON file {\"format\": "
                         "\"mms-queries/1\", \"queries\": [{\"start\": [x,y,theta], \"goal\": "
                         "[x,y,theta]}, ...]}; with -o/--svg, files are numbered (out.0.json, ...)")
            ->type_name("FILE")
            ->group("Planner");
        auto params = std::make_shared<PlannerParamOptions>(planCmd);
        return params;
      },
      run);
}

Command addValidate(CLI::App& app) {
  return command<ValidateArgs>(
      app, "validate", "Load and validate a scene (mms-scene/1); print a summary",
      [](CLI::App* cmd, ValidateArgs& a) {
        sceneArg(cmd, a.scene, "Scene file");
        quietFlag(cmd, a.quiet, "Print nothing when valid");
      },
      [](ValidateArgs& a) { return validate(a); });
}

Command addCheck(CLI::App& app) {
  return command<CheckArgs>(
      app, "check",
      "Certify a path (mms-path/1) as a continuous collision-free motion from start to goal.\n"
      "Exit 0 certified, 1 rejected (first failing segment, parameter and reason), 2 bad input",
      [](CLI::App* cmd, CheckArgs& a) {
        sceneAndPath(cmd, a.scene, a.path, "Scene file", "Path file")->required();
        cmd->add_option("--max-evaluations", a.maxEvaluations,
                        "Poses the checker may evaluate before giving up")
            ->capture_default_str()
            ->check(CLI::PositiveNumber);
      },
      [](CheckArgs& a) { return check(a); });
}

Command addRender(CLI::App& app) {
  return withOneFile<RenderArgs>(
      app, "render",
      "Draw a scene (and a path, animated) as SVG: start poses green, goal poses red", render,
      [](CLI::App* cmd, RenderArgs& a) {
        sceneAndPath(cmd, a.scene, a.path, "Scene file", "Path file to draw and animate");
        outputOption(cmd, a.output, "SVG file to write (-: standard output)");
        numberIn(
            cmd->add_option("--width", a.width, "Picture width in pixels")->capture_default_str(),
            50, 20000);
        cmd->add_option("--ghosts", a.ghosts, "Faint robot poses drawn along the path")
            ->capture_default_str()
            ->check(CLI::Range(0, 1000));
        cmd->add_flag("--no-animation", a.noAnimation, "Leave out the animated robot");
      });
}

Command addView(CLI::App& app) {
  return withOneFile<ViewArgs>(
      app, "view",
      "Write one self-contained HTML file that draws the scene and plays the path (play/pause,\n"
      "time slider, speed, traces, the planner's cells with --save-roadmap paths). Open it in\n"
      "any browser; FILE.html#t=0.5 opens it half-way through the motion",
      view, [](CLI::App* cmd, ViewArgs& a) {
        sceneAndPath(cmd, a.scene, a.path, "Scene file (any format mms reads)",
                     "Path file to play");
        outputOption(cmd, a.output, "HTML file to write (-: standard output)");
        cmd->add_option("--record", a.record,
                        "A record of the planning (mms plan --record): a second slider steps "
                        "through what the planner built, with layers and its phases")
            ->type_name("FILE");
      });
}

Command addImport(CLI::App& app) {
  return withOneFile<ImportArgs>(
      app, "import",
      "Convert a scene to mms-scene/1: an OMPL.app problem (FILE.cfg and the COLLADA meshes it\n"
      "names) or a discopygal JSON scene. Notes on stderr say what the conversion changed.\n"
      "(plan, validate, check, render and view read these files directly too)",
      importScene, [](CLI::App* cmd, ImportArgs& a) {
        cmd->add_option("FILE", a.input, "OMPL.app .cfg or discopygal .json")
            ->required()
            ->type_name("FILE");
        convertedOutput(cmd, a.output, a.quiet, "Scene file");
        cmd->add_option(
            "--bounds", a.bounds,
            "XMIN,YMIN,XMAX,YMAX: the workspace, instead of the one the file gives "
            "(discopygal scenes give none: by default the box around obstacles and "
            "robots, grown on every side by the largest robot's diameter and 10 % more)");
      });
}

Command addExport(CLI::App& app) {
  return withOneFile<ExportArgs>(
      app, "export",
      "Write a scene as discopygal JSON (--to discopygal), a path as OMPL.app's .path text\n"
      "(--to ompl-path, one rigid robot) or as timed trajectories, one per robot (--to\n"
      "trajectories: CSV robot,name,t,x,y,theta at unit speed, for fleet software)",
      exportScene, [](CLI::App* cmd, ExportArgs& a) {
        sceneAndPath(cmd, a.scene, a.path, "Scene file",
                     "Path file (for --to ompl-path and trajectories)");
        cmd->add_option("--to", a.to, "discopygal, ompl-path or trajectories")
            ->required()
            ->check(CLI::IsMember({"discopygal", "ompl-path", "trajectories"}));
        cmd->add_flag("--force", a.force,
                      "--to discopygal: write robots that rotate as translating ones at their "
                      "start angle (discopygal's polygon robots only translate)");
        convertedOutput(cmd, a.output, a.quiet, "File");
      });
}

Command addLab(CLI::App& app) {
  // Ctrl-C keeps its default (the lab writes its files only at the end, atomically).
  auto run = [](LabArgs& a) {
    claimStandardOutput({}, {{a.output, "-o"}});
    return lab(a);
  };
  return command<LabArgs>(
      app, "lab",
      "Measure the paper's theory (docs/theory.md): 'completeness' (failure rate of MMS and PRM\n"
      "against samples in R^2..R^6, Theorem 3.3) or 'passages' (flume vs tunnel, k-clearance,\n"
      "the Pacman's passage). Writes SVG plots, CSV and a Markdown summary",
      [](CLI::App* labCmd, LabArgs& la) {
        labCmd->add_option("EXPERIMENT", la.experiment, "completeness or passages")
            ->required()
            ->check(CLI::IsMember({"completeness", "passages"}));
        labCmd
            ->add_option("-o,--output", la.output,
                         "Folder for the report (created if missing; docs/theory in a checkout "
                         "rewrites the docs' plots)")
            ->required()
            ->type_name("DIR");
        seedOption(labCmd, la.seed, "Random seed (same seed, same report)");
        labCmd
            ->add_option("--trials", la.trials, "Trials per setting (0: the experiment's default)")
            ->check(CLI::Range(0, 1000000));
        labCmd->add_option("--threads", la.threads, "Threads for trials (0: all cores)")
            ->capture_default_str()
            ->check(CLI::Range(0u, 256u));
        labCmd->add_flag("--quick", la.quick, "Small settings: a smoke run in seconds");
        labCmd->add_flag("--no-pacman", la.noPacman, "passages: leave out the Pacman proxy");
        quietFlag(labCmd, la.quiet, "No progress messages");
      },
      run);
}

Command addAssemble(CLI::App& app) {
  auto run = [](AssembleArgs& a) {
    claimStandardOutput({{a.svg, "--svg"}}, {{a.output, "-o"}});
    startLongRun(a.memoryMb);
    return assemble(a);
  };
  return command<AssembleArgs>(
      app, "assemble",
      "Three-handed disassembly: remove every part (robot) from the static part (the obstacles),\n"
      "one part or two at a time while the others stay put (a translating part alone exactly, a\n"
      "rigid part alone and pairs by MMS, with budgets of rounds that grow pass by pass). Parts\n"
      "whose goal equals their start\n"
      "leave the obstacles' bounding box; the others go to their goals. Writes "
      "DIR/step-K.scene.json\n"
      "and step-K.path.json per step, DIR/disassembly.{scene,path}.json (the whole motion, "
      "certified)\n"
      "and DIR/disassembly.json (the sequence). Exit 1 when parts remain stuck.",
      [](CLI::App* assembleCmd, AssembleArgs& aa) {
        sceneArg(assembleCmd, aa.scene, "Scene file (mms-scene/1)");
        outputOption(assembleCmd, aa.output, "Directory for the files", "DIR");
        assembleCmd
            ->add_option("--svg", aa.svg,
                         "Write an animated SVG of the whole disassembly (-: standard output)")
            ->type_name("FILE");
        seedOption(assembleCmd, aa.seed, "Random seed");
        numberIn(
            assembleCmd->add_option("--time-limit", aa.timeLimit, "Seconds for the whole sequence")
                ->capture_default_str(),
            0.01, 1e7);
        memoryLimitOption(
            assembleCmd, aa.memoryMb,
            "MB of address space; beyond it the run ends with \'out of memory\' (0: none)");
        assembleCmd->add_flag(
            "--no-pairs", aa.noPairs,
            "Two hands only: move one part at a time (exact for translating parts)");
        quietFlag(assembleCmd, aa.quiet, "No progress messages on stderr");
      },
      run);
}

// The families, one a line: "  keyhole (--seed, --slack): a key passes ...".
std::string scenarioList() {
  std::string list = "The scene to write:";
  for (const mms::ScenarioInfo& f : mms::scenarios()) {
    std::string settings = f.seeded ? "--seed" : "";
    for (const std::string& s : f.settings) settings += (settings.empty() ? "--" : ", --") + s;
    list += "\n  " + f.name + (settings.empty() ? "" : " (" + settings + ")") + ": " + f.summary;
  }
  return list;
}

Command addScenario(CLI::App& app) {
  auto run = [](ScenarioArgs& a, const CLI::Option* slackOption) {
    claimStandardOutput({{a.output, "-o"}});
    a.slackGiven = slackOption->count() > 0;
    return scenario(a);
  };
  return command<ScenarioArgs>(
      app, "scenario",
      "Write a scene file: one of the paper's scenes or a generated family's (NAME below lists "
      "them, each with the settings it takes)",
      [](CLI::App* scenarioCmd, ScenarioArgs& sa) {
        scenarioCmd->add_option("NAME", sa.name, scenarioList())
            ->required()
            ->check(CLI::IsMember(mms::scenarioNames()))
            ->type_name("NAME");
        outputOption(scenarioCmd, sa.output, "Scene file to write (-: standard output)");
        numberIn(scenarioCmd
                     ->add_option("--tightness", sa.tightness,
                                  "pacman: 0 = the base scene, towards 1 = the square exactly "
                                  "fits the mouth")
                     ->capture_default_str(),
                 0, 0.999);
        seedOption(scenarioCmd, sa.seed,
                   "random-polygons, random and the generated families: the seed of the geometry");
        scenarioCmd
            ->add_option(
                "--robots", sa.robots,
                "random: 1 or 2 robots (default: from the seed); discs-room: how many discs "
                "(default 10, at most 16); round-room: how many discs (default 3-5 from the seed, "
                "2-16); disc-grid, disc-triangles: how many discs (default "
                "20, at most 2000); disc-box: how many discs (default 29), warehouse: how "
                "many carts (default 20), at most 2000")
            ->check(CLI::Range(1, 2000));
        numberIn(scenarioCmd->add_option(
                     "--spacing", sa.spacing,
                     "disc-grid: centres of neighbouring discs apart, in radii (3: dense, "
                     "10: sparse; default 3, 5 or 10 from the seed)"),
                 2.05, 100);
        scenarioCmd
            ->add_option("--obstacles", sa.obstacles,
                         "random: how many obstacles (default: from the seed)")
            ->check(CLI::Range(0, 100000));
        auto* slackOption = numberIn(
            scenarioCmd
                ->add_option(
                    "--slack", sa.slack,
                    "assembly-1/2: the play between parts and walls, at most 0.15 (the "
                    "smaller, the tighter); niche-swap and carry-turn: the play around a robot, "
                    "a share of its size (default: 0.04-0.1 from the seed; 0.5 is roomy); "
                    "keyhole, swallow and swallow-two: what the chamber's (the bay's) inscribed "
                    "circle clears "
                    "the turning circle by (default: 0.03-0.12 from the seed)")
                ->capture_default_str(),
            0.001, 1.0);
        scenarioCmd
            ->add_option(
                "--translate", sa.translate,
                "robots (by name, comma-separated) that only translate, e.g. niche-three's "
                "oncoming; each must keep its angle from start to goal")
            ->delimiter(',');
        scenarioCmd->add_flag(
            "--m-parts-only", sa.mPartsOnly,
            "assembly-2: only the two M parts, with goals outside (the 4-D problem "
            "left once the triangles are out)");
        return slackOption;
      },
      run);
}

Command addMerge(CLI::App& app) {
  using Folders = std::pair<std::vector<std::string>, std::string>;  // (shards, merged)
  auto run = [](Folders& f) {
    claimStandardOutput({}, {{f.second, "-o"}});
    return benchMerge(f.first, f.second);
  };
  return command<Folders>(
      app, "bench-merge",
      "Merge the runs of several mms bench folders (shards) into one, with reports",
      [](CLI::App* cmd, Folders& f) {
        cmd->add_option("DIRS", f.first, "Benchmark folders")->required()->type_name("DIR");
        outputOption(cmd, f.second, "Merged folder", "DIR");
      },
      run);
}

// The benchmark's settings from its options: the command that ran it (quoted where a shell
// would split it, so that the logged command runs again), the planners and the shard checked.
BenchArgs benchSettings(const BenchOptions& o, const std::vector<std::string>& argv) {
  BenchArgs b = o;
  for (const std::string& arg : argv) {
    const bool plain = !arg.empty() && arg.find_first_of(" \t'\"$\\") == std::string::npos;
    if (!b.command.empty()) b.command += ' ';
    b.command += plain ? arg : "'" + arg + "'";
  }
  const std::vector<std::string> names = plannerNames();
  b.planners.clear();
  for (const std::string& p : mms::split(o.planners, ',')) {
    if (std::find(names.begin(), names.end(), p) == names.end())
      throw mms::InputError("--planners: unknown planner '" + p + "'" + mms::didYouMean(p, names));
    b.planners.push_back(p);
  }
  if (b.planners.empty()) throw mms::InputError("--planners: no planner given");
  unsigned k = 0, n = 0;
  char extra = 0;
  if (std::sscanf(o.shard.c_str(), "%u/%u%c", &k, &n, &extra) != 2 || n == 0 || k == 0 || k > n)
    throw mms::InputError("--shard: expected K/N with 1 <= K <= N, found '" + o.shard + "'");
  b.shardIndex = k;
  b.shardCount = n;
  return b;
}

Command addBench(CLI::App& app, const std::vector<std::string>& argv) {
  auto run = [argv](BenchOptions& o) {
    claimStandardOutput({}, {{o.output, "-o"}});
    return bench(benchSettings(o, argv));
  };
  return command<BenchOptions>(
      app, "bench",
      "Run planners on scenes, N seeds each, every run in its own "
      "process under a time and memory limit.\n"
      "Writes DIR/runs.jsonl as runs finish (rerun to resume), "
      "then DIR/report.md (Markdown table),\n"
      "DIR/results.csv, DIR/ompl/*.log (for "
      "ompl_benchmark_statistics / Planner Arena) and, with a\n"
      "sweep, DIR/tightness.svg",
      [](CLI::App* benchCmd, BenchOptions& ba) {
        benchCmd->add_option("SCENES", ba.scenes, "Scene files")
            ->check(CLI::ExistingFile)
            ->type_name("FILE");
        outputOption(benchCmd, ba.output, "Results folder", "DIR");
        benchCmd
            ->add_option("--planners", ba.planners,
                         "Comma-separated planners (see mms plan --help for every name)")
            ->capture_default_str();
        benchCmd->add_option("--runs", ba.runs, "Runs per scene and planner (seeds 1..N)")
            ->capture_default_str()
            ->check(CLI::Range(1, 100000));
        numberIn(benchCmd->add_option("--time-limit", ba.timeLimit, "Seconds per run")
                     ->capture_default_str(),
                 0.01, 1e6);
        memoryLimitOption(benchCmd, ba.memoryMb, "MB of address space per run (0: none)");
        benchCmd->add_option(
            "--sweep-pacman", ba.sweepPacman,
            "Comma-separated Pacman tightness values to add as generated scenes, e.g. 0,0.5,0.9");
        benchCmd->add_option(
            "--param", ba.params,
            "Extra mms plan options for one planner, e.g. --param \"prm=--k 10\" (repeatable)");
        benchCmd
            ->add_option("--shard", ba.shard,
                         "K/N: run only the K-th of N disjoint parts of the run list (merge with "
                         "mms bench-merge)")
            ->capture_default_str();
        benchCmd
            ->add_option(
                "--jobs", ba.jobs,
                "Cores to fill: runs at a time, an mms run with --threads N taking N of them "
                "(timings are noisier above 1)")
            ->capture_default_str()
            ->check(CLI::Range(1, 256));
        benchCmd->add_flag(
            "--stop-decided", ba.stopDecided,
            "Stop running a planner's seeds on a scene once half of them failed (its "
            "median is then decided as unsolved); the rest are recorded as not run");
        benchCmd->add_flag("--report-only", ba.reportOnly,
                           "Only rewrite the reports from the runs recorded in DIR");
      },
      run);
}

void refuseNonFiniteNumbers(CLI::App& app) {
  const CLI::Validator finite(
      [](std::string& s) -> std::string {
        double v = 0;
        return CLI::detail::lexical_cast(s, v) && !std::isfinite(v)
                   ? "'" + s + "' is not a finite number"
                   : "";
      },
      "");
  for (CLI::App* sub : app.get_subcommands({}))
    for (CLI::Option* o : sub->get_options())
      if (o->get_type_name().rfind("FLOAT", 0) == 0) o->check(finite);
}

}  // namespace mms::cli
