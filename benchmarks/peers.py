"""The peers, each on one voyage as a user of it would ask (building its graph counts):

* skimage: scikit-image's MCP_Geometric, 8-connected (costs of the two ends averaged x length);
* tcod Dijkstra / tcod A*: python-tcod's compiled Pathfinder on a CustomGraph with the same 5 x 5
  stencil as seaway's default (24 steps), integer edge weights round(10 x length) times the
  entered pixel's integer cost round(10 x cost) (tcod's graphs take integers: 0 blocks); A* with
  the heuristic (9, 13) x the cheapest pixel for a straight and a diagonal move, admissible for
  every step of the stencil;
* pyastar2d: its A* (8-connected, a step costs the entered pixel's weight whatever its length).

None prices a step exactly as seaway's default model does (max of the two ends x length, and no
step jumping land), so only scikit-image is asserted against seaway's drop-in; the others are
timed, their path checked to join the ends. Peers ignore a lat/lon chart's geometry (pixels are
unit squares to them), which makes their searches no harder."""

from __future__ import annotations

import os

import numpy as np

PEERS = ("skimage", "tcod dijkstra", "tcod astar", "pyastar2d")
#: SEAWAY_BENCH_PEERS (comma-separated) runs fewer peers; scikit-image always runs (the ratios).
CHOSEN = {"skimage"} | set(os.environ.get("SEAWAY_BENCH_PEERS", ",".join(PEERS)).split(","))


def skimage_route(raster, s, e):
    from skimage.graph import MCP_Geometric

    costs, _ = MCP_Geometric(raster, fully_connected=True).find_costs([s], [e])
    return float(costs[e])


_EDGES = np.array(
    [[0 if (i, j) == (2, 2) else round(10 * np.hypot(i - 2, j - 2)) for j in range(5)] for i in range(5)],
    np.int32,
)


def tcod_route(raster, s, e, astar):
    import tcod.path

    cost = np.where(np.isfinite(raster), np.rint(10 * raster), 0).astype(np.int32)
    graph = tcod.path.CustomGraph(raster.shape)
    graph.add_edges(edge_map=_EDGES, cost=cost)
    if astar:
        least = int(cost[cost > 0].min())
        graph.set_heuristic(cardinal=9 * least, diagonal=13 * least)
    pf = tcod.path.Pathfinder(graph)
    pf.add_root(s)
    path = pf.path_to(e)
    assert tuple(path[0]) == tuple(s) and tuple(path[-1]) == tuple(e)
    return float(pf.distance[e]) / 100


def pyastar2d_route(raster32, s, e):
    import pyastar2d

    path = pyastar2d.astar_path(raster32, s, e, allow_diagonal=True)
    assert path is not None and tuple(path[0]) == tuple(s) and tuple(path[-1]) == tuple(e)
    return float(len(path))


def peer_cases(raster, s, e):
    """{peer name: a call running it on the voyage s -> e (pixels)}; pyastar2d needs weights >= 1
    (the raster scaled by its least cost, once, outside the timing)."""
    least = float(raster[np.isfinite(raster)].min())
    scaled = (raster / min(least, 1.0)).astype(np.float32)
    runs = {
        "skimage": lambda: skimage_route(raster, s, e),
        "tcod dijkstra": lambda: tcod_route(raster, s, e, False),
        "tcod astar": lambda: tcod_route(raster, s, e, True),
        "pyastar2d": lambda: pyastar2d_route(scaled, s, e),
    }
    return {name: run for name, run in runs.items() if name in CHOSEN}
