"""Compare two builds of seaway on the benchmark chart, query by query, for a refactor that must
not slow the search down.

    python benchmarks/compare_builds.py OLD_SITE NEW_SITE [--rounds 5] [--callgrind]

OLD_SITE and NEW_SITE are directories holding an installed seaway (e.g. made by
`pip install --no-deps --target DIR .` at each commit). Each round runs every query once in a
fresh process per build, old and new alternating, and times the query alone (process CPU time,
after a warm-up query in the same process), so a busy machine slows both builds alike; the
table gives the median per build and the ratio new / old. With --callgrind each query runs once
per build under valgrind's callgrind instead, and the instructions of the query alone (the run
minus a run that only builds the chart) are compared: a count that does not depend on the load.
Every query's cost must agree between the builds to 1e-9. The child drops an editable install's
import hook (before 2026-12-08 it did not, and in a virtualenv with an editable install every
comparison ran that one build against itself).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

QUERIES = {
    # name: (season, method, neighbourhood, landmarks)
    "dijkstra k=5 winter": ("winter", "dijkstra", 5, 0),
    "auto winter": ("winter", "auto", 5, 0),
    "auto summer": ("summer", "auto", 5, 0),
    "astar summer": ("summer", "astar", 5, 0),
    "landmarks winter": ("winter", "landmarks", 5, 8),
}

CHILD = r"""
import json, sys, time
# An editable install's import hook would load its own build whatever PYTHONPATH says.
sys.meta_path[:] = [f for f in sys.meta_path if not type(f).__module__.startswith("_editable_")]
import numpy as np
from seaway.samples import synthetic_sea, synthetic_endpoints
import seaway
season, method, k, landmarks, runs = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
cost = synthetic_sea((1900, 2300))
if season == "summer":
    cost = np.where(np.isfinite(cost), 1.0 + (cost - 1.0) / 29.0, cost)
a, b = synthetic_endpoints(cost.shape)
chart = seaway.prepare(cost, neighbourhood=k, edge_cost="mean", landmarks=landmarks)
times, r = [], None
for i in range(runs):
    t = time.process_time()
    r = chart.route(a, b, method=method)
    times.append(time.process_time() - t)
print(json.dumps({"cost": None if r is None else r.cost, "times": times, "site": seaway.__file__}))
"""


def run(site, query, runs, callgrind=False):
    env = dict(os.environ, PYTHONPATH=site)
    args = [sys.executable, "-c", CHILD, *map(str, QUERIES[query]), str(runs)]
    if not callgrind:
        out = subprocess.run(args, env=env, check=True, capture_output=True, text=True).stdout
        result = json.loads(out)
        if not result["site"].startswith(os.path.abspath(site)):
            sys.exit(f"the child imported seaway from {result['site']}, not from {site}")
        return result
    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "cg.out")
        subprocess.run(
            ["valgrind", "--tool=callgrind", f"--callgrind-out-file={log}", *args],
            env=env,
            check=True,
            capture_output=True,
            text=True,
        )
        with open(log) as f:
            total = next(int(line.split()[1]) for line in f if line.startswith("summary:"))
    return {"instructions": total}


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("old")
    p.add_argument("new")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--callgrind", action="store_true")
    p.add_argument("--only", nargs="*", default=list(QUERIES))
    a = p.parse_args()
    print(f"{'query':24} {'old':>12} {'new':>12} {'new/old':>8}")
    for q in a.only:
        if a.callgrind:
            base = {s: run(s, q, 0, True)["instructions"] for s in (a.old, a.new)}
            full = {s: run(s, q, 1, True)["instructions"] for s in (a.old, a.new)}
            old, new = (full[s] - base[s] for s in (a.old, a.new))
            print(f"{q:24} {old:12,d} {new:12,d} {new / old:8.3f}", flush=True)
            continue
        med = {a.old: [], a.new: []}
        costs = {}
        for _ in range(a.rounds):
            for s in (a.old, a.new):
                out = run(s, q, 2)
                med[s].append(out["times"][-1])  # the second query: the first warms up
                costs[s] = out["cost"]
        assert abs(costs[a.old] - costs[a.new]) <= 1e-9 * abs(costs[a.old]), costs
        old, new = statistics.median(med[a.old]), statistics.median(med[a.new])
        print(f"{q:24} {old:11.3f}s {new:11.3f}s {new / old:8.3f}", flush=True)


if __name__ == "__main__":
    main()
