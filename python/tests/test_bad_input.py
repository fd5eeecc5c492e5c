"""The bad-input corpus through Python: every reader either returns or raises mms.InputError
with one line, never crashes the interpreter. The inputs are the fuzz corpora and deterministic
mutations of them; a crash would end this process, and pytest would report it."""

import glob
import os
import random

import pytest

import mms
from conftest import cli, source


def corpus(kind):
    return sorted(glob.glob(source("fuzz", "corpus", kind, "*")))


def load(file):
    try:
        return mms.load_scene(file)
    except mms.InputError as e:
        assert "\n" not in str(e)
        return e


@pytest.mark.filterwarnings("ignore::UserWarning")
def test_fuzz_corpora_load_or_raise_as_the_cli_says():
    files = corpus("scene") + corpus("discopygal") + corpus("cfg")
    assert len(files) >= 10
    for file in files:
        outcome = load(file)
        run = cli("validate", "--quiet", file) if False else cli("validate", file)
        if isinstance(outcome, mms.InputError):
            assert run.returncode == 2, file
            assert run.stderr.strip().endswith(str(outcome)), (file, run.stderr, str(outcome))
        else:
            assert run.returncode == 0, (file, run.stderr)


def mutations(text, rng, count):
    data = text.encode()
    for _ in range(count):
        b = bytearray(data)
        for _ in range(rng.randint(1, 4)):
            op = rng.random()
            i = rng.randrange(len(b)) if b else 0
            if op < 0.3 and b:
                b[i] = rng.choice(b'{}[],:"0123456789-.eE \\ntrfnul')
            elif op < 0.5:
                b = b[:i]
            elif op < 0.7 and b:
                del b[i:i + rng.randint(1, 16)]
            else:
                j = rng.randrange(len(b)) if b else 0
                b[i:i] = b[j:j + rng.randint(1, 32)]
        yield bytes(b)


@pytest.mark.filterwarnings("ignore::UserWarning")
def test_mutated_scenes_and_paths(tmp_path):
    rng = random.Random(20261124)
    scene_file = source("scenes", "one-robot", "bar-slot.json")
    path_file = source("scenes", "one-robot", "bar-slot.path.json")
    scene = mms.load_scene(scene_file)
    texts = [open(f).read() for f in corpus("scene") + corpus("discopygal")
             if f.endswith(".json")][:12]
    loaded = refused = 0
    for text in texts:
        for i, mutant in enumerate(mutations(text, rng, 40)):
            file = tmp_path / f"m{i}.json"
            file.write_bytes(mutant)
            outcome = load(str(file))
            loaded += not isinstance(outcome, mms.InputError)
            refused += isinstance(outcome, mms.InputError)
            try:
                mms.Scene(mutant.decode("utf-8", "replace"), source="mutant")
            except mms.InputError as e:
                assert "\n" not in str(e)
    assert refused > 100 and loaded + refused == 40 * len(texts)
    for i, mutant in enumerate(mutations(open(path_file).read(), rng, 200)):
        file = tmp_path / f"p{i}.json"
        file.write_bytes(mutant)
        try:
            waypoints = mms.load_path(scene, file)
            mms.check(scene, waypoints)
        except mms.InputError as e:
            assert "\n" not in str(e)
