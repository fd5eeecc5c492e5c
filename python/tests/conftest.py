"""Shared helpers: the source tree, the `mms` command line built beside the module, and scenes
the tests write themselves."""

import os
import subprocess

import pytest

SOURCE = os.environ.get("MMS_SOURCE_DIR",
                        os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..")))


def source(*parts):
    return os.path.join(SOURCE, *parts)


def cli(*args, check=False):
    """Runs the `mms` command line; returns the CompletedProcess (text)."""
    exe = os.environ.get("MMS_EXECUTABLE", "mms")
    return subprocess.run([exe, *map(str, args)], capture_output=True, text=True, check=check)


def square(half):
    return [[-half, -half], [half, -half], [half, half], [-half, half]]


def box_scene(wall=True):
    """A unit square robot crossing a 10 x 10 room; with `wall`, a wall from floor to ceiling
    whose one slit (0.95) is narrower than the robot leaves no way through, and none that the
    planner can prove (a disc inside the robot passes): the planner runs to its time limit."""
    obstacles = [[[4.5, 0], [5.5, 0], [5.5, 4.525], [4.5, 4.525]],
                 [[4.5, 5.475], [5.5, 5.475], [5.5, 10], [4.5, 10]]] if wall else []
    return {"format": "mms-scene/1", "name": "walled" if wall else "open",
            "bounds": [0, 0, 10, 10], "obstacles": obstacles,
            "robots": [{"name": "r", "shape": square(0.5), "start": [2, 5, 0],
                        "goal": [8, 5, 0]}]}


@pytest.fixture
def bar_slot():
    import mms
    return mms.load_scene(source("scenes", "one-robot", "bar-slot.json"))
