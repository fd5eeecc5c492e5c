"""The planner releases the GIL while it works, and Ctrl-C stops it with KeyboardInterrupt."""

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import mms
from conftest import box_scene


def test_other_threads_run_while_planning():
    walled = mms.Scene(box_scene(wall=True))
    ticks = 0
    done = threading.Event()

    def count():
        nonlocal ticks
        while not done.is_set():
            ticks += 1
            time.sleep(0.005)

    counter = threading.Thread(target=count, daemon=True)
    counter.start()
    start = time.monotonic()
    try:
        r = mms.plan(walled, "mms", time_limit=1.0)
        elapsed = time.monotonic() - start
    finally:
        done.set()
        counter.join()
    assert not r.found and elapsed >= 0.9
    # With the GIL held for the whole second, the counter would not have run at all.
    assert ticks >= 20


CHILD = textwrap.dedent("""
    import sys, time
    import mms
    sys.path.insert(0, {tests!r})
    from conftest import box_scene
    walled = mms.Scene(box_scene(wall=True))
    print("planning", flush=True)
    try:
        mms.plan(walled, {planner!r}, time_limit=120)
        print("ended without interrupt", flush=True)
    except KeyboardInterrupt:
        print("interrupted", flush=True)
    # The module still works after an interrupted run.
    r = mms.plan(mms.Scene(box_scene(wall=False)), "mms", time_limit=30)
    print("after", r.status, flush=True)
""")


def interrupt(planner):
    code = CHILD.format(tests=os.path.dirname(__file__), planner=planner)
    child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "planning"
    time.sleep(1.0)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=60)
    return out, err, child.returncode, time.monotonic() - sent


def test_ctrl_c_stops_mms():
    out, err, code, seconds = interrupt("mms")
    assert code == 0, err
    assert out.split("\n")[:2] == ["interrupted", "after found"], out + err
    assert seconds < 30


def test_ctrl_c_stops_the_portfolio_and_ompl():
    for planner in ("auto", "prm"):
        out, err, code, _ = interrupt(planner)
        assert code == 0, err
        assert out.startswith("interrupted\nafter found"), planner + ": " + out + err


def test_progress_reports_on_the_calling_thread():
    walled = mms.Scene(box_scene(wall=True))
    seen = []
    caller = threading.get_ident()

    def progress(stats):
        assert threading.get_ident() == caller
        seen.append(stats)

    r = mms.plan(walled, "mms", time_limit=1.5, progress=progress)
    assert not r.found and seen
    assert [s["rounds"] for s in seen] == sorted(s["rounds"] for s in seen)
    assert all("phases" in s for s in seen)
    # The time so far, as the result's: one definition of seconds.
    assert all(0 < s["seconds"] <= r.stats["seconds"] for s in seen), seen


def test_ompl_planners_report_progress_too():
    pacman = mms.scenario("pacman", tightness=0.9)
    seen = []
    r = mms.plan(pacman, "rrtconnect", time_limit=2.5, progress=seen.append)
    assert seen, "no progress from an OMPL planner"
    assert all(s["seconds"] >= 1 and s["graph_nodes"] > 0 for s in seen), seen
    assert r.stats["graph_nodes"] >= seen[-1]["graph_nodes"] > 0
    assert r.stats["graph_edges"] > 0


def test_an_exception_in_progress_stops_the_planner():
    walled = mms.Scene(box_scene(wall=True))

    def progress(stats):
        raise RuntimeError("enough")

    start = time.monotonic()
    try:
        mms.plan(walled, "mms", time_limit=60, progress=progress)
        raise AssertionError("the exception did not propagate")
    except RuntimeError as e:
        assert str(e) == "enough"
    assert time.monotonic() - start < 30
    try:
        mms.plan(walled, "mms", progress=42)
        raise AssertionError("a progress that is no callable was taken")
    except mms.InputError as e:
        assert "progress" in str(e)
