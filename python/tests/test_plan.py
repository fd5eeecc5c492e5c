"""Planning from Python: every planner by name, parameters as keyword arguments checked against
the planner's declared list, certified paths that the command line certifies again."""

import pytest

import mms
from conftest import box_scene, cli, source


def test_planners_are_the_registry():
    names = [p["name"] for p in mms.planners()]
    assert names[:2] == ["auto", "mms"]
    assert {"rrtconnect", "prm", "kpiece"} <= set(names)
    run = cli("plan", "--help")
    for name in names:
        assert name in run.stdout
    params = {p["name"]: p for p in next(p for p in mms.planners() if p["name"] == "mms")["params"]}
    assert params["n_theta"]["option"] == "--n-theta"
    assert params["objective"]["choices"] == ["length", "clearance"]
    assert params["objective"]["default"] == "length"


def test_one_robot_path_is_certified_and_saved(bar_slot, tmp_path):
    r = mms.plan(bar_slot, "mms", seed=3, time_limit=30)
    assert r.found and r.status == "found"
    assert r.planner == "mms" and r.seed == 3 and r.solved_by == "mms"
    assert r.path[0] == bar_slot.start and r.path[-1] == pytest.approx(bar_slot.goal)
    assert r.certificate and r.certificate.translation > 0
    assert mms.check(bar_slot, r)
    assert r.stats["seconds"] == r.seconds > 0
    assert any(name == "optimize" for name in r.stats["phases"])
    assert r.parameters["n_theta"] == 16 and r.parameters["optimize"] == 1
    file = tmp_path / "bar.path.json"
    r.save(file)
    assert cli("check", source("scenes", "one-robot", "bar-slot.json"), file).returncode == 0
    again = mms.load_path(bar_slot, file)
    assert len(again) == len(r.path)
    assert all(a == pytest.approx(b, abs=1e-9) for a, b in zip(again, r.path))
    assert mms.check(bar_slot, str(file))
    assert len(r.robot_path(0)) == len(r.path) == len(r.robot_path(bar_slot.robot_names[0]))
    # One robot's poses are lists, as the waypoints are: the same values, the same type.
    assert r.robot_path(0) == [w[0:3] for w in r.path]
    assert all(type(p) is list for p in r.robot_path(0))


def test_same_seed_same_path(bar_slot):
    a = mms.plan(bar_slot, "mms", seed=5, time_limit=30)
    b = mms.plan(bar_slot, "mms", seed=5, time_limit=30)
    assert a.found and a.path == b.path


def test_two_robots_and_a_sampler(tmp_path):
    two = mms.scenario("random-polygons", seed=13)
    r = mms.plan(two, seed=1, time_limit=60)
    assert r.found and len(r.path[0]) == 6
    assert r.solved_by in {p["name"] for p in mms.planners()}
    file = tmp_path / "two.path.json"
    r.save(file)
    scene_file = tmp_path / "two.json"
    two.save(scene_file)
    assert cli("check", scene_file, file).returncode == 0
    s = mms.plan(mms.Scene(box_scene(wall=False)), "rrtconnect", time_limit=10, simplify=1)
    assert s.found and mms.check(s.scene, s.path)


def test_parameters_as_keywords(bar_slot):
    r = mms.plan(bar_slot, "mms", time_limit=30, n_theta=8, objective="clearance", optimize=True)
    assert r.found
    assert r.parameters["n_theta"] == 8 and r.parameters["objective"] == "clearance"
    assert type(r.parameters["n_theta"]) is int
    with pytest.raises(mms.InputError, match=r"n_theta: '8' is not a number"):
        mms.plan(bar_slot, "mms", n_theta="8")
    with pytest.raises(mms.InputError, match=r"timelimit: .*did you mean time_limit="):
        mms.plan(bar_slot, "mms", timelimit=3)
    with pytest.raises(mms.InputError, match=r"unknown; did you mean 'rrtconnect'"):
        mms.plan(bar_slot, "rrtconect")
    with pytest.raises(mms.InputError, match="not a parameter of planner 'mms'.*n_theta"):
        mms.plan(bar_slot, "mms", bogus=1)
    with pytest.raises(mms.InputError, match=r"^mms.plan: n_theta: 0 is not in \[1, "):
        mms.plan(bar_slot, "mms", n_theta=0)
    with pytest.raises(mms.InputError, match="objective: 'shortest' is not one of length, clearance"):
        mms.plan(bar_slot, "mms", objective="shortest")
    with pytest.raises(mms.InputError, match=r"n_theta: \[8\] is not a number"):
        mms.plan(bar_slot, "mms", n_theta=[8])
    with pytest.raises(mms.InputError, match="unknown"):
        mms.plan(bar_slot, "astar")
    with pytest.raises(mms.InputError, match="time_limit"):
        mms.plan(bar_slot, time_limit=0)
    with pytest.raises(mms.InputError, match="seed"):
        mms.plan(bar_slot, seed=-1)
    with pytest.raises(mms.InputError, match="mms.Scene"):
        mms.plan("bar-slot.json")


def test_check_says_why(bar_slot):
    straight = [bar_slot.start, bar_slot.goal]
    c = mms.check(bar_slot, straight)
    assert not c and c.reason and 0 <= c.parameter <= 1
    assert "rejected" in repr(c)
    with pytest.raises(mms.InputError, match=r"path\[1\]: 2 numbers"):
        mms.check(bar_slot, [bar_slot.start, [0, 0]])
    with pytest.raises(mms.InputError, match="not a number"):
        mms.check(bar_slot, [bar_slot.start, ["a", 0, 0]])
    with pytest.raises(mms.InputError, match="no waypoints"):
        mms.check(bar_slot, [])


def test_unsolvable_scene_ends_at_the_limit():
    r = mms.plan(mms.Scene(box_scene(wall=True)), "mms", time_limit=0.5)
    assert not r.found and r.status == "not_found"
    assert r.solved_by is None
    assert r.path == []
    with pytest.raises(mms.InputError, match="no path to save"):
        r.save("never-written.json")


def test_a_proof_that_no_path_exists_is_named():
    scene = box_scene(wall=True)
    scene["robots"][0]["motion"] = "translate"  # its one slice is exact: the wall cuts it off
    r = mms.plan(mms.Scene(scene), time_limit=60)
    assert not r.found and r.status == "not_found"
    assert r.stats["no_path"].startswith("robot 'r' only translates")
    assert r.seconds < 30  # ended by the proof, not by the limit


def test_pictures(bar_slot):
    r = mms.plan(bar_slot, "mms", time_limit=30)
    svg = mms.render_svg(bar_slot, r)
    assert svg.startswith("<svg") or "<svg" in svg[:200]
    assert "<animate" in svg
    assert "<svg" in r._repr_svg_() and "<svg" in bar_slot._repr_svg_()
    assert "<animate" not in mms.render_svg(bar_slot)
    with pytest.raises(mms.InputError, match="width"):
        mms.render_svg(bar_slot, width=0)


def test_many_discs_are_planned_one_at_a_time_and_certified():
    scene = mms.scenario("disc-grid", seed=3, robots=60, spacing=3)
    assert len(scene.robot_names) == 60
    r = mms.plan(scene, "mms", time_limit=30)
    assert r.found and r.planner == "mms"
    assert r.stats["counts"]["moves"] == 60  # the ordered planner: each disc once
    assert mms.check(scene, r.path).ok
    with pytest.raises(mms.InputError):
        mms.scenario("disc-grid", robots=20, spacing=1.0)


def test_a_fleet_moves_at_once_and_is_measured():
    scene = mms.scenario("disc-grid", seed=2, robots=30, spacing=6)
    at_once, in_turn = mms.plan(scene, time_limit=30), mms.plan(scene, time_limit=30, concurrent=0)
    assert at_once.found and in_turn.found
    c, d = at_once.certificate, in_turn.certificate
    assert c.makespan_bound > 0 and c.makespan >= c.makespan_bound * (1 - 1e-9)
    assert c.makespan < 0.5 * d.makespan  # the moves overlap in time
    assert c.moving_at_once > 2 and abs(d.moving_at_once - 1) < 1e-9
    assert abs(c.distance - d.distance) < 1e-6 * d.distance  # each robot's own motion as planned
    checked = mms.check(scene, at_once.path)
    assert checked.ok and abs(checked.makespan - c.makespan) < 1e-9 * c.makespan
