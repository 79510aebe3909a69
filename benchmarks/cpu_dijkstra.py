"""CPU time of 5x5-style Dijkstra on the benchmark chart, k = 3, 5, 7, for comparing two builds:
run it alternately with the python of each build's environment: python benchmarks/cpu_dijkstra.py LABEL."""

import sys
import time

import numpy as np

import seaway
from seaway.samples import synthetic_endpoints, synthetic_sea

cost = synthetic_sea((1900, 2300))
a, b = synthetic_endpoints(cost.shape)
out = []
for k in (3, 5, 7):
    seaway.route(cost, a, b, neighbourhood=k, method="dijkstra", edge_cost="mean")
    ts = []
    for _ in range(5):
        t = time.process_time()
        r = seaway.route(cost, a, b, neighbourhood=k, method="dijkstra", edge_cost="mean")
        ts.append(time.process_time() - t)
    out.append(f"k={k} {np.median(ts):.3f} cost={r.cost:.6f}")
print(sys.argv[1], *out)
