"""A brute-force reference for the turn penalty: Dijkstra on the explicit expanded graph whose
vertices are (pixel, incoming step) pairs, built from tests/reference.py's edge list. Nothing
here calls seaway.

Turn angle at pixel v between steps (di1, dj1) and (di2, dj2): the angle between the vectors
(di*dy, dj*dx) on planar charts, (di*dlat, dj*dlon*cos(lat_v)) on lat/lon charts."""

from __future__ import annotations

import heapq
import math

import numpy as np

from support.reference import RefGraph


def turn_angle(g: RefGraph, v: int, a, b, dx=1.0, dy=1.0) -> float:
    if tuple(a) == tuple(b):
        return 0.0
    if g.geographic:
        dlat, dlon = g.lat[1] - g.lat[0], g.lon[1] - g.lon[0]
        c = math.cos(math.radians(g.lat[v // g.cols]))
        va, vb = (a[0] * dlat, a[1] * dlon * c), (b[0] * dlat, b[1] * dlon * c)
    else:
        va, vb = (a[0] * dy, a[1] * dx), (b[0] * dy, b[1] * dx)
    cos = (va[0] * vb[0] + va[1] * vb[1]) / (math.hypot(*va) * math.hypot(*vb))
    return math.degrees(math.acos(min(1.0, max(-1.0, cos))))


def turn_route_cost(g: RefGraph, start_rc, end_rc, angles, costs, dx=1.0, dy=1.0, incoming=None) -> float:
    """Least cost from start to end where each course change at a pixel costs
    np.interp(angle, angles, costs); the first step is free of penalty unless `incoming` (the
    (di, dj) that reached the start) is given."""
    s, t = g.node(start_rc), g.node(end_rc)
    if s == t:
        return 0.0
    out = {}  # v -> [(w, cost, (di, dj))]
    for (a, b), w in g.edges.items():
        out.setdefault(a, []).append((b, w, g.offset(divmod(a, g.cols), divmod(b, g.cols))))
    heap = []
    for w, c, o in out.get(s, []):
        pen = (
            0.0
            if incoming is None
            else float(np.interp(turn_angle(g, s, incoming, o, dx, dy), angles, costs))
        )
        heapq.heappush(heap, (c + pen, w, o))
    done = set()
    while heap:
        d, v, o = heapq.heappop(heap)
        if (v, o) in done:
            continue
        done.add((v, o))
        if v == t:
            return d
        for w, c, o2 in out.get(v, []):
            if (w, o2) in done:
                continue
            pen = float(np.interp(turn_angle(g, v, o, o2, dx, dy), angles, costs))
            heapq.heappush(heap, (d + c + pen, w, o2))
    return math.inf
