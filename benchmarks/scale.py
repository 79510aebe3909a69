"""One route on a very large memory-mapped float32 chart: 10^8 or 10^9 pixels (not part of the
test suite: minutes of run time and, at 10^9, most of a 24 GiB machine's memory).

    python benchmarks/scale.py --pixels 1e8 [--method dijkstra] [--dir /tmp] [--keep]
    python benchmarks/scale.py --pixels 1e9

The chart is `seaway.samples.synthetic_sea()` at 1/10 of the side with every pixel repeated into
a 10 x 10 block (the land and ice have the same shapes 10 x larger), written once as raw float32
to DIR/seaway-scale-N.f32 and opened with np.memmap(mode="r") in a fresh process, routed corner
to corner. Printed: the preparation and search seconds (wall), pixels settled, nanoseconds per
settled pixel, and the process's peak resident memory (VmHWM) in GiB and bytes per pixel, over
what it held before the chart was opened (the chart's own file pages count: they are read in
place, not copied).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys

import numpy as np

CHILD = r"""
import json, sys, time
import numpy as np
import seaway

def status(key):
    for line in open("/proc/self/status"):
        if line.startswith(key):
            return int(line.split()[1]) * 1024

path, n, method = sys.argv[1], int(sys.argv[2]), sys.argv[3]
s, e = (int(sys.argv[4]), int(sys.argv[5])), (int(sys.argv[6]), int(sys.argv[7]))
seaway.route(np.ones((50, 50)), (0, 0), (49, 49))  # imports and first-use costs before the baseline
before = status("VmRSS:")
cost = np.memmap(path, dtype=np.float32, mode="r", shape=(n, n))
t0 = time.perf_counter()
chart = seaway.prepare(cost)
t1 = time.perf_counter()
r = chart.route(s, e, method=method)
t2 = time.perf_counter()
print(json.dumps(dict(prepare_s=t1 - t0, search_s=t2 - t1, settled=r.stats.search.settled,
                      method=r.method, cost=r.cost, hwm=status("VmHWM:"), before=before,
                      engine_bytes=r.stats.search.state_bytes)))
"""


def build(path: str, n: int, block: int = 10):
    """The block-repeated synthetic chart, written row band by row band; returns its ends."""
    from seaway.samples import synthetic_endpoints, synthetic_sea

    coarse = synthetic_sea((n // block, n // block)).astype(np.float32)
    if not os.path.exists(path) or os.path.getsize(path) != n * n * 4:
        mm = np.memmap(path, dtype=np.float32, mode="w+", shape=(n, n))
        for i in range(n // block):
            mm[i * block : (i + 1) * block] = np.repeat(coarse[i], block)[None, :]
        mm.flush()
        del mm
    return [tuple(v * block + block // 2 for v in p) for p in synthetic_endpoints(coarse.shape)]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--pixels", type=float, default=1e8, help="about this many pixels (a square)")
    p.add_argument("--method", default="auto")
    p.add_argument("--dir", default="/tmp")
    p.add_argument("--keep", action="store_true", help="keep the chart file for the next run")
    a = p.parse_args()
    n = int(round(a.pixels**0.5 / 10)) * 10
    path = os.path.join(a.dir, f"seaway-scale-{n}.f32")
    s, e = build(path, n)
    try:
        out = subprocess.run(
            [sys.executable, "-c", CHILD, path, str(n), a.method, *map(str, (*s, *e))],
            capture_output=True,
            text=True,
            check=True,
        ).stdout
    finally:
        if not a.keep:
            os.remove(path)
    r = json.loads(out)
    gib = 2**30
    print(
        f"{n} x {n} = {n * n:,} pixels, {r['method']}: prepare {r['prepare_s']:.1f} s, search "
        f"{r['search_s']:.1f} s, {r['settled']:,} settled ({1e9 * r['search_s'] / r['settled']:.0f} ns "
        f"each), peak RSS {r['hwm'] / gib:.2f} GiB ({(r['hwm'] - r['before']) / (n * n):.1f} B/pixel "
        f"over the {r['before'] / gib:.2f} GiB before; engine's count "
        f"{r['engine_bytes'] / (n * n):.1f} B/pixel), cost {r['cost']:.3f}"
    )


if __name__ == "__main__":
    main()
