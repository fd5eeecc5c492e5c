"""Plan the Pacman scene with mms, show it, and compare with OMPL's RRT-Connect over ten seeds
(docs/python.md). Run from a build tree or an installed prefix:

    PYTHONPATH=build/python python3 examples/python/compare.py [TIGHTNESS] [OUT.svg]
"""

import statistics
import sys

import mms

tightness = float(sys.argv[1]) if len(sys.argv) > 1 else 0.5
picture = sys.argv[2] if len(sys.argv) > 2 else "pacman.svg"

scene = mms.scenario("pacman", tightness=tightness)
print(scene)

result = mms.plan(scene, seed=1, time_limit=30)
print(result)
with open(picture, "w") as f:
    f.write(result.svg())  # in a notebook, `result` alone shows the picture

times = {"mms": [], "rrtconnect": []}
for planner in times:
    for seed in range(1, 11):
        r = mms.plan(scene, planner, seed=seed, time_limit=10)
        # An unsolved run counts as the whole time limit.
        times[planner].append(r.seconds if r.found else r.time_limit)
        assert not r.found or mms.check(scene, r)
    solved = sum(t < 10 for t in times[planner])
    print(f"{planner:>10}: median {statistics.median(times[planner]):.3f} s, "
          f"{solved}/10 solved")

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5, 3))
    ax.boxplot(list(times.values()), labels=list(times))
    ax.set_yscale("log")
    ax.set_ylabel("seconds to a certified path")
    ax.set_title(f"Pacman, tightness {tightness}, seeds 1-10")
    fig.tight_layout()
    fig.savefig("pacman-times.png")
    print("pacman-times.png written")
except ImportError:
    print("matplotlib is not installed: no plot")
