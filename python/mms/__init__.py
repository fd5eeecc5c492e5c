"""mms: motion planning via manifold samples, for planar polygonal robots.

Plan collision-free motions for rigid polygonal robots (one, two or more) among polygonal
obstacles; every path returned as found is certified collision-free as a continuous motion.
Follows *Motion Planning via Manifold Samples* (Salzman, Hemmer, Halperin); OMPL's planners run
on the same scenes and checker for comparison. docs/python.md has a walk-through.

>>> import mms
>>> scene = mms.scenario("pacman", tightness=0.5)
>>> result = mms.plan(scene, seed=1, time_limit=10)
>>> result.found, result.status
(True, 'found')
>>> result.save("pacman.path.json")          # `mms check` certifies it again
"""

from __future__ import annotations

import csv as _csv
import difflib as _difflib
import os as _os
import shutil as _shutil
import subprocess as _subprocess
import warnings as _warnings

from . import _mms
from ._mms import InputError, Scene

__version__ = _mms.__version__
InputError.__module__ = "mms"
InputError.__doc__ = (
    "Bad input: a scene, path or argument mms cannot take. A ValueError whose message is the "
    "one line the command line prints: 'FILE: FIELD: PROBLEM'."
)
Scene.__module__ = "mms"

__all__ = [
    "InputError",
    "Scene",
    "Result",
    "Check",
    "load_scene",
    "scenario",
    "scenario_names",
    "planners",
    "plan",
    "check",
    "load_path",
    "render_svg",
    "view",
    "View",
    "bench",
    "load_bench",
    "executable",
]


def _scene_repr(self: Scene) -> str:
    robots = len(self.robot_names)
    name = f" {self.name!r}" if self.name else ""
    return (f"<mms.Scene{name}: {robots} robot{'s' if robots != 1 else ''}, "
            f"{self.obstacle_count} obstacles>")


Scene.__repr__ = _scene_repr
Scene._repr_svg_ = lambda self: render_svg(self)


def load_scene(file: str | _os.PathLike) -> Scene:
    """Reads a scene file in any format mms reads: mms-scene/1 JSON, an OMPL.app .cfg problem,
    a discopygal JSON scene. What a conversion changed (and start or goal angles beyond a full
    turn, which look like degrees) is reported as a UserWarning. Raises InputError."""
    scene, notes = _mms.load_scene(_path_text(file, "mms.load_scene"))
    for note in notes:
        _warnings.warn(note, UserWarning, stacklevel=2)
    return scene


def scenario_names() -> list[str]:
    """The scene generators mms.scenario() knows, as `mms scenario` does."""
    return _mms.scenario_names()


def scenario(name: str, *, seed: int = 1, tightness: float = 0.0, slack: float | None = None,
             robots: int | None = None, obstacles: int | None = None, spacing: float | None = None,
             m_parts_only: bool = False, translate: list[str] | tuple[str, ...] = ()) -> Scene:
    """A generated scene, the same as `mms scenario NAME --seed K ...` writes.

    pacman (tightness), viking-helmet, random-polygons (seed), assembly-1 and assembly-2
    (slack), random (seed, robots, obstacles) and the generated families carry-turn (slack),
    niche-swap (slack), niche-three, discs-swap, discs-room (robots), open-clutter, bend, doors
    keyhole (slack), swallow and swallow-two (slack: in swallow-two the part is a robot too)
    (seed), and many discs: disc-grid (robots, spacing: the
    grid's centres apart in radii), disc-triangles (robots), disc-box (robots: exact discs
    packed touching in a walled box), warehouse (robots: rectangular carts among shelves) and
    round-room (robots: 3-5 discs nearly filling a round room go round to each other's places). translate names robots that only translate (each must keep its angle from
    start to goal). Raises InputError for an unknown name or a setting out of range."""
    r = _mms.ScenarioRequest()
    r.name = _text(name, "mms.scenario: name")
    r.seed = _whole(seed, "mms.scenario: seed")
    r.tightness = _number(tightness, "mms.scenario: tightness")
    if slack is not None:
        r.slack = _number(slack, "mms.scenario: slack")
        r.slack_given = True
    if robots is not None:
        r.robots = _whole(robots, "mms.scenario: robots", limit=1 << 30)
    if obstacles is not None:
        r.obstacles = _whole(obstacles, "mms.scenario: obstacles", limit=1 << 30)
    if spacing is not None:
        r.spacing = _number(spacing, "mms.scenario: spacing")
    r.m_parts_only = bool(m_parts_only)
    if isinstance(translate, str) or not isinstance(translate, (list, tuple)):
        raise InputError("mms.scenario: translate: expected a list of robot names, got "
                         + type(translate).__name__)
    r.translate = [_text(n, "mms.scenario: translate") for n in translate]
    return _mms.scenario(r)


def planners() -> list[dict]:
    """Every planner mms.plan() takes ("auto" first, then "mms", then OMPL's), each a dict:
    name, summary, multi_query and params (name, option, type, min, max, default, choices,
    help). The keyword arguments of mms.plan() are the params' names."""
    return _mms.planners()


class Check:
    """What the continuous path checker says of a path. True when certified; otherwise
    `reason` says why and `segment` (index of the segment's first waypoint) and `parameter`
    (along it, in [0, 1]) say where. translation, rotation (radians, summed over robots) and
    min_clearance measure the motion; for a fleet, makespan and distance (the sum of the
    robots' distances) with their lower bounds makespan_bound and distance_bound, and
    moving_at_once, the robots in motion in the mean (at unit speed: |dp| + radius |dtheta|)."""

    __slots__ = ("ok", "reason", "segment", "parameter", "min_clearance", "evaluations",
                 "translation", "rotation", "makespan", "makespan_bound", "distance",
                 "distance_bound", "moving_at_once")

    def __init__(self, d: dict):
        for k in self.__slots__:
            setattr(self, k, d[k])

    def __bool__(self) -> bool:
        return self.ok

    def __repr__(self) -> str:
        if self.ok:
            return (f"<mms.Check certified: translation {self.translation:.4g}, rotation "
                    f"{self.rotation:.4g} rad, min clearance {self.min_clearance:.4g}>")
        return f"<mms.Check rejected: {self.reason}>"


class Result:
    """One planner run. `found` is True only for a certified path; `status` is one of found,
    not_found, uncertified, cancelled. `path` holds the waypoints, each a list with every
    robot's x, y, theta in scene order (linear interpolation between them is the motion);
    `stats` the run's statistics (phases, manifolds, graph) as `mms plan --stats-json` writes
    them; `certificate` the checker's verdict on the path. Notebooks show it as a picture."""

    def __init__(self, native):
        self._r = native

    found = property(lambda self: self._r.found)
    status = property(lambda self: self._r.status)
    path = property(lambda self: self._r.waypoints)
    planner = property(lambda self: self._r.planner)
    seed = property(lambda self: self._r.seed)
    time_limit = property(lambda self: self._r.time_limit)
    scene = property(lambda self: self._r.scene)
    stats = property(lambda self: self._r.stats)
    parameters = property(lambda self: self._r.parameters)
    record = property(lambda self: self._r.record, doc="""What the planner built and when (mms-record/1 as a
        dict, docs/formats.md), when planned with record=True; else None.""")
    certificate = property(lambda self: Check(self._r.certificate))

    @property
    def seconds(self) -> float:
        """Planning time to the first certified path (optimisation after it not included)."""
        return self.stats["seconds"]

    @property
    def solved_by(self) -> str | None:
        """The portfolio member ("mms" or a sampler) whose path this is; the planner otherwise;
        None when no path was found."""
        if not self.found:
            return None
        return self.stats.get("solved_by") or self.planner

    def robot_path(self, robot: int | str) -> list[list[float]]:
        """One robot's poses [x, y, theta] along the path, by index or name (lists, as the
        waypoints of `path` are)."""
        names = self.scene.robot_names
        i = names.index(robot) if isinstance(robot, str) and robot in names else robot
        if not isinstance(i, int) or isinstance(i, bool) or not 0 <= i < len(names):
            raise InputError(f"robot_path: {robot!r}: not one of the robots {names}")
        return [list(w[3 * i:3 * i + 3]) for w in self.path]

    def save(self, file: str | _os.PathLike) -> None:
        """Writes the path as an mms-path/1 file (atomically) with the planner, seed, parameters
        and statistics; `mms check SCENE FILE` certifies it. Raises InputError when no path
        was found."""
        self._r.save(_path_text(file, "Result.save"))

    def svg(self, width: float = 800) -> str:
        """The scene with the path (animated), or the scene alone when none was found."""
        return render_svg(self.scene, self.path if self.found else None, width=width)

    def _repr_svg_(self) -> str:
        return self.svg(width=480)

    def __repr__(self) -> str:
        s = f"<mms.Result {self.planner} seed {self.seed}: {self.status}"
        if self.found:
            c = self.certificate
            s += (f" in {self.seconds:.3g} s by {self.solved_by}, {len(self.path)} waypoints, "
                  f"translation {c.translation:.4g}, rotation {c.rotation:.4g} rad")
        return s + ">"


def plan(scene: Scene, planner: str = "auto", *, seed: int = 1, time_limit: float = 60.0,
         progress=None, record: bool = False, **params) -> Result:
    """Plans a certified path for every robot of `scene` from start to goal.

    planner: a name from mms.planners() ("auto": MMS racing RRT-Connect, "mms", "prm",
    "rrtconnect", "kpiece", ...). seed: same seed, same result. time_limit: seconds for the
    whole run. params: the planner's parameters by name, e.g. n_theta=32, optimize=0,
    objective="clearance"; each is checked against the planner's declared range.
    progress: called with the statistics so far (a dict, as Result.stats) after each of the
    planner's rounds, at most every 50 ms, on the calling thread; an exception it raises
    stops the planner and propagates. record: keep what the planner built and when
    (Result.record, mms.view).

    The GIL is released while the planner works; Ctrl-C stops it at its next manifold and
    raises KeyboardInterrupt. Raises InputError for a bad argument or a scene the planner
    cannot take. A path is returned as found only once the continuous checker certified it."""
    if not isinstance(scene, Scene):
        raise InputError(f"mms.plan: scene: expected an mms.Scene, not {type(scene).__name__}")
    _check_keywords(_text(planner, "mms.plan: planner"), params)
    return Result(_mms.plan(scene, _text(planner, "mms.plan: planner"),
                            _whole(seed, "mms.plan: seed"),
                            _number(time_limit, "mms.plan: time_limit"), params, progress,
                            _flag(record, "mms.plan: record")))


class View:
    """The viewer's page for a result (as `mms view` writes it): the scene, the path, and with
    a record its growth. `html` is the self-contained page; notebooks show it inline (in an
    iframe of its own, so that several views do not share one document)."""

    def __init__(self, html: str, height: int = 900):
        self.html = html
        self.height = height

    def save(self, file: str | _os.PathLike) -> None:
        """Writes the page to `file`."""
        with open(_path_text(file, "View.save"), "w", encoding="utf-8") as f:
            f.write(self.html)

    def _repr_html_(self) -> str:
        import html as _html
        return (f'<iframe srcdoc="{_html.escape(self.html, quote=True)}" '
                f'style="width:100%;height:{int(self.height)}px;border:0"></iframe>')


def view(result: Result, *, height: int = 900) -> View:
    """The viewer's page for `result`: plays its path and, when planned with record=True,
    steps through what the planner built (docs/record.md)."""
    if not isinstance(result, Result):
        raise InputError(f"mms.view: result: expected an mms.Result, not {type(result).__name__}")
    return View(result._r.view_html(), _whole(height, "mms.view: height", 100000))


def _check_keywords(planner: str, params: dict) -> None:
    """Refuses a keyword no parameter of `planner` has, naming the nearest known one."""
    info = next((p for p in planners() if p["name"] == planner), None)
    if info is None:
        close = _difflib.get_close_matches(planner, [p["name"] for p in planners()], n=1)
        hint = f"; did you mean '{close[0]}'?" if close else ""
        raise InputError(f"mms.plan: planner '{planner}': unknown" + hint)
    names = [p["name"] for p in info["params"]]
    for key in params:
        if key in names or key.replace("-", "_") in names:
            continue
        close = _difflib.get_close_matches(key, names + ["time_limit", "seed", "progress"], n=1)
        known = ", ".join(names) if names else "none"
        hint = f"; did you mean {close[0]}=?" if close else ""
        raise InputError(f"mms.plan: {key}: not a parameter of planner '{planner}' "
                         f"(its parameters: {known}){hint}")


def check(scene: Scene, path) -> Check:
    """Certifies a path as a continuous collision-free motion from the scene's start to its
    goal. `path`: a Result, a list of waypoints (each every robot's x, y, theta) or a path
    file's name. Returns a Check: true when certified, else with the reason."""
    if isinstance(path, Result):
        path = path.path
    elif isinstance(path, (str, _os.PathLike)):
        path = load_path(scene, path)
    return Check(_mms.check(scene, path))


def load_path(scene: Scene, file: str | _os.PathLike) -> list[list[float]]:
    """The waypoints of a path file (mms-path/1 JSON, or OMPL.app .path text) for `scene`."""
    return _mms.load_path(scene, _path_text(file, "mms.load_path"))


def render_svg(scene: Scene, path=None, *, width: float = 800) -> str:
    """SVG text of the scene (obstacles blue, starts green, goals red) and, when given (a
    Result or waypoints), the path with faint poses along it and an animated robot."""
    if isinstance(path, Result):
        path = path.path if path.found else None
    return _mms.render_svg(scene, path, _number(width, "mms.render_svg: width"))


def executable() -> str:
    """The `mms` command line mms.bench() runs: $MMS_EXECUTABLE, else the one installed or
    built beside this module, else `mms` on PATH."""
    given = _os.environ.get("MMS_EXECUTABLE")
    if given:
        return given
    here = _os.path.dirname(_os.path.abspath(__file__))
    for rel in ("../../mms",               # build tree: build/python/mms -> build/mms
                "../../../../bin/mms"):    # installed: P/lib/pythonX.Y/site-packages/mms
        candidate = _os.path.normpath(_os.path.join(here, rel))
        if _os.path.isfile(candidate) and _os.access(candidate, _os.X_OK):
            return candidate
    found = _shutil.which("mms")
    if not found:
        raise FileNotFoundError("mms.bench: no `mms` executable beside the module or on PATH; "
                                "set MMS_EXECUTABLE")
    return found


def bench(scenes, planners, output: str | _os.PathLike, *, runs: int = 12,
          time_limit: float = 60.0, memory_limit: float = 4096, jobs: int = 1,
          params: dict | None = None, quiet: bool = True) -> list[dict]:
    """Runs `mms bench` (each run in its own process, under the limits) and returns its
    results.csv rows (mms.load_bench). scenes: scene files, or Scenes (saved into OUTPUT);
    planners: names; params: {planner: "--option value ..."} extra options of one planner.
    A second call with the same OUTPUT resumes. Raises InputError when `mms bench` refuses
    its input (the one-line message), KeyboardInterrupt on Ctrl-C (the runs recorded so far
    are kept)."""
    out = _path_text(output, "mms.bench: output")
    _os.makedirs(out, exist_ok=True)
    files = []
    for i, s in enumerate([scenes] if isinstance(scenes, (str, Scene)) else scenes):
        if isinstance(s, Scene):
            file = _os.path.join(out, f"scene-{i + 1}-{s.name or 'unnamed'}.json".replace(" ", "-"))
            s.save(file)
            files.append(file)
        else:
            files.append(_path_text(s, "mms.bench: scenes"))
    names = [planners] if isinstance(planners, str) else list(planners)
    cmd = [executable(), "bench", *files, "--planners", ",".join(names), "-o", out,
           "--runs", str(_whole(runs, "mms.bench: runs")),
           "--time-limit", repr(_number(time_limit, "mms.bench: time_limit")),
           "--memory-limit", repr(_number(memory_limit, "mms.bench: memory_limit")),
           "--jobs", str(_whole(jobs, "mms.bench: jobs"))]
    for planner, args in (params or {}).items():
        cmd += ["--param", f"{planner}={args}"]
    proc = _subprocess.run(cmd, stdout=_subprocess.DEVNULL if quiet else None,
                           stderr=_subprocess.PIPE, text=True)
    if proc.returncode == 130:
        raise KeyboardInterrupt
    if proc.returncode == 2:
        raise InputError(proc.stderr.strip().splitlines()[-1] if proc.stderr.strip() else
                         "mms bench: bad input")
    if proc.returncode != 0:
        raise RuntimeError(f"mms bench failed (exit {proc.returncode}): {proc.stderr.strip()}")
    return load_bench(out)


def load_bench(output: str | _os.PathLike) -> list[dict]:
    """The rows of a `mms bench` folder's results.csv, one per run (scene, planner, seed),
    with counts (seed, graph size) as ints, other numbers as
    floats and empty fields (nothing measured) as None."""
    file = _os.path.join(_path_text(output, "mms.load_bench"), "results.csv")
    if not _os.path.isfile(file):
        raise InputError(f"{file}: no such file (not a `mms bench` folder?)")
    rows = []
    with open(file, newline="") as f:
        for row in _csv.DictReader(f):
            rows.append({k: _cell(v, k in _COUNT_COLUMNS) for k, v in row.items()})
    return rows


# The columns of results.csv that count things: ints, whatever the CSV wrote.
_COUNT_COLUMNS = {"seed", "graph_size"}


def _cell(v: str, count: bool):
    if v == "":
        return None
    try:
        number = float(v)
    except ValueError:
        return v
    return int(number) if count and number.is_integer() else number


def _path_text(file, who: str) -> str:
    if isinstance(file, _os.PathLike):
        file = _os.fspath(file)
    if not isinstance(file, str):
        raise InputError(f"{who}: expected a file name, not {type(file).__name__}")
    return file


def _text(v, who: str) -> str:
    if not isinstance(v, str):
        raise InputError(f"{who}: expected a string, not {type(v).__name__}")
    return v


def _whole(v, who: str, limit: int = (1 << 64) - 1) -> int:
    if isinstance(v, bool) or not isinstance(v, int):
        raise InputError(f"{who}={v!r}: expected a whole number")
    if not 0 <= v <= limit:
        raise InputError(f"{who}={v!r}: must be in [0, {limit}]")
    return v


def _flag(v, who: str) -> bool:
    if not isinstance(v, bool):
        raise InputError(f"{who}={v!r}: expected True or False")
    return v


def _number(v, who: str) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise InputError(f"{who}={v!r}: expected a number")
    return float(v)
