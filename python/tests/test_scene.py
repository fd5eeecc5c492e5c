"""Scenes from files, from Python data and from the generators; the same messages as the
command line."""

import json
import math
import warnings

import pytest

import mms
from conftest import box_scene, cli, source


def test_load_scene_reads_every_format(bar_slot):
    assert bar_slot.name == "bar-slot"
    assert bar_slot.robot_names == ["bar"] or len(bar_slot.robot_names) == 1
    assert bar_slot.dof == 3
    assert len(bar_slot.start) == 3 and len(bar_slot.goal) == 3
    two = mms.load_scene(source("scenes", "two-robots", "pacman-0.5.json"))
    assert two.dof == 6 and len(two.robot_names) == 2
    assert "2 robots" in repr(two)


def test_python_data_round_trips(bar_slot):
    data = bar_slot.to_dict()
    assert data["format"] == "mms-scene/1"
    again = mms.Scene(data)
    assert again.to_json() == bar_slot.to_json()
    assert json.loads(bar_slot.to_json()) == data
    from_text = mms.Scene(bar_slot.to_json(), source="text")
    assert from_text.to_dict() == data and from_text.source == "text"


def test_scene_built_by_hand():
    s = mms.Scene(box_scene(wall=False))
    assert s.robot_names == ["r"]
    assert s.obstacle_count == 0
    assert s.start == [2, 5, 0] and s.goal == [8, 5, 0]


@pytest.mark.parametrize("change, field", [
    (lambda d: d.pop("bounds"), "bounds"),
    (lambda d: d["robots"][0].update(start=[2, 5]), "robots[0].start"),
    (lambda d: d["robots"][0]["shape"][1].__setitem__(0, math.nan), "robots[0].shape"),
    (lambda d: d["robots"][0].update(colour="red"), "colour"),
    (lambda d: d["robots"][0].update(start=[0.2, 5, 0]), "robots[0].start"),
])
def test_bad_data_raises_the_cli_message(tmp_path, change, field):
    data = box_scene(wall=False)
    change(data)
    with pytest.raises(mms.InputError) as from_data:
        mms.Scene(data)
    message = str(from_data.value)
    assert field in message and "\n" not in message
    assert isinstance(from_data.value, ValueError)
    # The same scene as a file: the command line's one line, word for word.
    file = tmp_path / "bad.json"
    file.write_text(json.dumps(data))
    with pytest.raises(mms.InputError) as from_file:
        mms.load_scene(file)
    run = cli("validate", file)
    assert run.returncode == 2
    assert run.stderr.strip() == "mms: " + str(from_file.value) or \
        run.stderr.strip().endswith(str(from_file.value))


def test_values_without_json_form_are_refused():
    data = box_scene(wall=False)
    data["robots"][0]["start"] = {2, 5, 0}
    with pytest.raises(mms.InputError, match="no JSON form"):
        mms.Scene(data)
    with pytest.raises(mms.InputError, match="not a string"):
        mms.Scene({1: 2})
    deep = []
    for _ in range(200):
        deep = [deep]
    with pytest.raises(mms.InputError, match="nested deeper"):
        mms.Scene({"format": "mms-scene/1", "bounds": deep})
    with pytest.raises(mms.InputError):
        mms.Scene("{not json", source="text")


def test_angles_in_degrees_are_noted(tmp_path):
    data = box_scene(wall=False)
    data["robots"][0]["goal"] = [8, 5, 90]
    file = tmp_path / "degrees.json"
    file.write_text(json.dumps(data))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mms.load_scene(file)
    assert any("angles are in radians" in str(w.message) for w in caught)
    # A scene made from Python data gets the same note, naming its source.
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        mms.Scene(data, source="mine")
    assert any("mine: robots[0].goal: angle 90" in str(w.message) for w in caught)
    # Warnings as errors: the note becomes the exception, not a crash.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(UserWarning, match="radians"):
            mms.Scene(data)


def test_scenarios_match_the_command_line(tmp_path):
    assert mms.scenario_names()[0] == "pacman"
    for name, kwargs, args in [
        ("pacman", {"tightness": 0.5}, ["--tightness", "0.5"]),
        ("carry-turn", {"seed": 7}, ["--seed", "7"]),
        ("niche-swap", {"seed": 3, "slack": 0.2}, ["--seed", "3", "--slack", "0.2"]),
        ("random", {"seed": 4, "robots": 2, "obstacles": 5},
         ["--seed", "4", "--robots", "2", "--obstacles", "5"]),
        ("niche-three", {"seed": 2, "translate": ["oncoming"]},
         ["--seed", "2", "--translate", "oncoming"]),
    ]:
        file = tmp_path / f"{name}.json"
        cli("scenario", name, *args, "-o", file, check=True)
        assert mms.scenario(name, **kwargs).to_dict() == json.loads(file.read_text()), name


@pytest.mark.parametrize("kwargs, match", [
    ({"name": "nope"}, "unknown"),
    ({"name": "pacman", "tightness": 1.5}, "tightness"),
    ({"name": "assembly-1", "slack": 0.5}, "largest play"),
    ({"name": "random", "robots": 3}, "1 or 2"),
    ({"name": "carry-turn", "seed": -1}, "seed"),
    ({"name": "carry-turn", "seed": 1.5}, "whole number"),
    ({"name": "niche-three", "translate": ["nobody"]}, "no robot 'nobody'.*oncoming"),
    ({"name": "niche-three", "translate": "oncoming"}, "list of robot names"),
    ({"name": "carry-turn", "translate": ["part"]}, "turns from start to goal"),
])
def test_bad_scenario_settings(kwargs, match):
    with pytest.raises(mms.InputError, match=match):
        mms.scenario(**kwargs)


def test_missing_file_and_folder(tmp_path):
    with pytest.raises(mms.InputError, match="nothing.json"):
        mms.load_scene(tmp_path / "nothing.json")
    with pytest.raises(mms.InputError):
        mms.load_scene(tmp_path)
    with pytest.raises(mms.InputError, match="file name"):
        mms.load_scene(42)


def test_exact_discs_touch_plan_and_refuse_a_bad_radius():
    # Three discs of radius 0.5 touching in a row along the bottom wall, beside a disc obstacle.
    robots = [{"name": f"d{i}", "disc": 0.5, "start": [0.5 + i, 0.5, 0],
               "goal": [0.5 + i, 3.5, 0]} for i in range(3)]
    data = {"format": "mms-scene/1", "bounds": [0, 0, 6, 4],
            "obstacles": [{"center": [4.5, 2], "radius": 0.8}], "robots": robots}
    s = mms.Scene(data)
    back = s.to_dict()
    assert back["robots"][1]["disc"] == 0.5 and "shape" not in back["robots"][1]
    assert back["obstacles"][0] == {"center": [4.5, 2], "radius": 0.8}
    result = mms.plan(s, seed=1, time_limit=20)
    assert result.found and result.certificate.ok
    assert mms.check(s, result.path).ok
    for i in range(3):
        x, y, _ = result.robot_path(i)[-1]
        assert (x, y) == (0.5 + i, 3.5)
    bad = json.loads(json.dumps(data))
    bad["robots"][0]["disc"] = -0.5
    with pytest.raises(mms.InputError, match=r"robots\[0\]\.disc: radius must be positive"):
        mms.Scene(bad)
    bad["robots"][0]["disc"] = float("nan")
    with pytest.raises(mms.InputError, match=r"disc"):
        mms.Scene(bad)
