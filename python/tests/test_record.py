"""Records of the planning from Python: result.record is the mms-record/1 document the command
line writes, and mms.view gives the viewer's page with the record's layer."""

import json

import pytest

import mms
from conftest import cli, source


def test_a_record_says_what_mms_built_and_when(bar_slot, tmp_path):
    r = mms.plan(bar_slot, "mms", seed=2, time_limit=30, record=True)
    assert r.found
    rec = r.record
    assert rec["format"] == "mms-record/1" and rec["planner"] == "mms" and rec["robots"] == 1
    assert len(rec["manifolds"]) == r.stats["manifolds_built"]
    stamps = [m["at"] for m in rec["manifolds"]]
    assert stamps == sorted(stamps) and stamps[-1] <= rec["seconds"] + 1e-3
    assert sum(m["path"] for m in rec["manifolds"]) == r.stats["manifolds_used"]
    slices = [m for m in rec["manifolds"] if m["family"] == "slice"]
    assert slices and all(len(m["regions"]) == m["cells"] for m in slices)
    # The same document as `mms plan --record` (same seed, same manifolds).
    file = tmp_path / "r.json"
    assert cli("plan", source("scenes", "one-robot", "bar-slot.json"), "--planner", "mms",
               "--seed", 2, "-q", "--record", file).returncode == 0
    written = json.loads(file.read_text())
    assert [(m["family"], m["cells"]) for m in written["manifolds"]] == \
        [(m["family"], m["cells"]) for m in rec["manifolds"]]


def test_a_sampler_records_its_tree_and_the_view_shows_it(bar_slot, tmp_path):
    r = mms.plan(bar_slot, "rrtconnect", seed=1, time_limit=30, record=True)
    assert r.found
    tree = r.record["tree"]
    assert len(tree["states"]) == len(tree["at"]) == tree["total_states"] > 2
    page = mms.view(r)
    assert "id=\"rtime\"" in page.html and "\"tree\"" in page.html
    assert page._repr_html_().startswith("<iframe srcdoc=")
    page.save(tmp_path / "v.html")
    assert (tmp_path / "v.html").read_text() == page.html


def test_no_record_unless_asked_and_bad_arguments_are_named(bar_slot):
    r = mms.plan(bar_slot, "mms", seed=1, time_limit=30)
    assert r.record is None
    assert "id=\"rtime\"" not in mms.view(r).html
    with pytest.raises(mms.InputError, match="record"):
        mms.plan(bar_slot, "mms", record=1)
    with pytest.raises(mms.InputError, match="mms.view: result"):
        mms.view("not a result")
