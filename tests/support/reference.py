"""An independent brute-force reference for seaway's routing contract.

Nothing here calls seaway: the stencil, the segment geometry (exact rational arithmetic), the
edge lengths (own haversine), the edge costs and the shortest-path search (heapq Dijkstra, which
handles zero-cost edges) are all written from the contract alone.

Geometry is in pixel-index space: pixel (a, b) is the closed square [a-1/2, a+1/2] x
[b-1/2, b+1/2]; a step (di, dj) from pixel (i, j) is the closed segment from (i, j) to
(i+di, j+dj). Translating a step does not change which pixels it touches relative to its start,
so the geometry is worked out once per offset and cached."""

from __future__ import annotations

import heapq
import math
from fractions import Fraction
from functools import lru_cache

import numpy as np

EARTH_RADIUS_KM = 6371.0088
HALF = Fraction(1, 2)


def stencil_offsets(k: int, directions: str) -> list[tuple[int, int]]:
    """The contract's stencil: the k x k square less (0, 0); "unique" keeps gcd(|di|,|dj|)=1."""
    assert k % 2 == 1 and 3 <= k <= 15 and directions in ("full", "unique")
    h = (k - 1) // 2
    out = []
    for di in range(-h, h + 1):
        for dj in range(-h, h + 1):
            if (di, dj) == (0, 0):
                continue
            if directions == "unique" and math.gcd(abs(di), abs(dj)) != 1:
                continue
            out.append((di, dj))
    return out


def _t_interval(d: int, a: int):
    """Closed range of t in [0, 1] with |t*d - a| <= 1/2, or None when empty."""
    if d == 0:
        return (Fraction(0), Fraction(1)) if abs(a) * 2 <= 1 else None
    lo, hi = sorted(((a - HALF) / d, (a + HALF) / d))
    lo, hi = max(lo, Fraction(0)), min(hi, Fraction(1))
    return (lo, hi) if lo <= hi else None


@lru_cache(maxsize=None)
def touched(di: int, dj: int) -> tuple[tuple[int, int], ...]:
    """Pixels (relative to the start) whose closed square meets the closed segment to (di, dj),
    corner contacts included."""
    out = []
    for a in range(min(0, di) - 1, max(0, di) + 2):
        for b in range(min(0, dj) - 1, max(0, dj) + 2):
            ra, rb = _t_interval(di, a), _t_interval(dj, b)
            if ra is None or rb is None:
                continue
            if max(ra[0], rb[0]) <= min(ra[1], rb[1]):
                out.append((a, b))
    return tuple(out)


@lru_cache(maxsize=None)
def pieces(di: int, dj: int) -> tuple[tuple[tuple[int, int], float], ...]:
    """(pixel, fraction of the segment's length inside it) for the line integral; the fractions
    add up to 1 and zero-length contacts (corners) are left out."""
    ts = {Fraction(0), Fraction(1)}
    for d in (di, dj):
        if d == 0:
            continue
        for m in range(min(0, d) - 1, max(0, d) + 1):
            t = (m + HALF) / d
            if 0 < t < 1:
                ts.add(t)
    ts = sorted(ts)
    acc: dict[tuple[int, int], Fraction] = {}
    for t0, t1 in zip(ts[:-1], ts[1:]):
        tm = (t0 + t1) / 2
        pix = (math.floor(tm * di + HALF), math.floor(tm * dj + HALF))
        acc[pix] = acc.get(pix, Fraction(0)) + (t1 - t0)
    assert sum(acc.values()) == 1
    return tuple((p, float(f)) for p, f in sorted(acc.items()))


def haversine(lat1, lon1, lat2, lon2):
    p1, p2 = np.radians(lat1), np.radians(lat2)
    dp, dl = p2 - p1, np.radians(np.asarray(lon2) - np.asarray(lon1))
    a = np.sin(dp / 2) ** 2 + np.cos(p1) * np.cos(p2) * np.sin(dl / 2) ** 2
    return 2 * EARTH_RADIUS_KM * np.arcsin(np.sqrt(np.clip(a, 0.0, 1.0)))


class RefGraph:
    """The explicit edge list of a chart under the contract, and Dijkstra over it."""

    def __init__(
        self, cost, *, lat=None, lon=None, dx=1.0, dy=1.0, land=None, k=5, directions="full", edge_cost="max"
    ):
        u = np.array(cost, dtype=np.float64)
        self.rows, self.cols = R, C = u.shape
        ok = np.isfinite(u)
        if land is not None:
            ok &= ~np.asarray(land, dtype=bool)
        self.u, self.ok = u, ok
        self.geographic = lat is not None
        self.lat = None if lat is None else np.asarray(lat, dtype=float)
        self.lon = None if lon is None else np.asarray(lon, dtype=float)
        self.wrap = self.geographic and abs(abs(self.lon[1] - self.lon[0]) * C - 360) < 1e-6
        self.offsets = stencil_offsets(k, directions)
        self.h = (k - 1) // 2
        self.edge_cost = edge_cost
        src, dst, wt = [], [], []
        for di, dj in self.offsets:
            i = np.arange(max(0, -di), min(R, R - di))
            j = np.arange(C) if self.wrap else np.arange(max(0, -dj), min(C, C - dj))
            if i.size == 0 or j.size == 0:
                continue
            I, J = np.meshgrid(i, j, indexing="ij")
            I2, J2 = I + di, (J + dj) % C
            good = np.ones(I.shape, dtype=bool)
            for a, b in touched(di, dj):
                good &= ok[I + a, (J + b) % C]
            if self.geographic:
                r = haversine(self.lat[I], self.lon[J], self.lat[I2], self.lon[J2])
            else:
                r = np.full(I.shape, math.hypot(di * dy, dj * dx))
            with np.errstate(invalid="ignore"):
                if edge_cost == "max":
                    w = np.maximum(u[I, J], u[I2, J2]) * r
                elif edge_cost == "mean":
                    w = (u[I, J] + u[I2, J2]) / 2 * r
                elif edge_cost == "length":
                    w = r
                else:
                    s = np.zeros(I.shape)
                    for (a, b), f in pieces(di, dj):
                        s = s + f * np.where(good, u[I + a, (J + b) % C], 0.0)
                    w = r * s
            src.append((I * C + J)[good])
            dst.append((I2 * C + J2)[good])
            wt.append(w[good])
        src, dst, wt = (np.concatenate(x).tolist() if x else [] for x in (src, dst, wt))
        self.adj: list[list[tuple[int, float]]] = [[] for _ in range(R * C)]
        self.edges: dict[tuple[int, int], float] = {}
        for s, d, w in zip(src, dst, wt):
            self.adj[s].append((d, w))
            self.edges[(s, d)] = w

    # -- queries -------------------------------------------------------------------------
    def node(self, rc) -> int:
        return int(rc[0]) * self.cols + int(rc[1])

    def offset(self, p, q):
        """The step (di, dj) from pixel p to q (columns modulo cols on wrapping charts)."""
        di, dj = int(q[0]) - int(p[0]), int(q[1]) - int(p[1])
        if self.wrap:
            dj = (dj + self.cols // 2) % self.cols - self.cols // 2
        return di, dj

    def edge(self, p, q):
        """The contract's cost of the step p -> q, or None when it is not an allowed edge."""
        return self.edges.get((self.node(p), self.node(q)))

    def path_cost(self, pixels) -> float:
        """Sum of edge costs along a path; raises AssertionError on a forbidden step."""
        total = 0.0
        for p, q in zip(pixels[:-1], pixels[1:]):
            w = self.edge(p, q)
            assert w is not None, f"step {tuple(p)} -> {tuple(q)} is not an allowed edge"
            total += w
        return total

    def costs(self, start_rc) -> np.ndarray:
        """Least accumulated cost from start to every pixel (inf where unreachable)."""
        dist = [math.inf] * (self.rows * self.cols)
        s = self.node(start_rc)
        dist[s] = 0.0
        heap = [(0.0, s)]
        done = [False] * len(dist)
        while heap:
            d, v = heapq.heappop(heap)
            if done[v]:
                continue
            done[v] = True
            for w_, c in self.adj[v]:
                nd = d + c
                if nd < dist[w_]:
                    dist[w_] = nd
                    heapq.heappush(heap, (nd, w_))
        return np.array(dist).reshape(self.rows, self.cols)


def reference_costs(
    cost, start_rc, *, lat=None, lon=None, dx=1.0, dy=1.0, land=None, k=5, directions="full", edge_cost="max"
) -> np.ndarray:
    """(rows, cols) least cost from start_rc (row, col) under the contract; inf if unreachable."""
    g = RefGraph(
        cost, lat=lat, lon=lon, dx=dx, dy=dy, land=land, k=k, directions=directions, edge_cost=edge_cost
    )
    return g.costs(start_rc)


def refraction_optimum(u1, u2, a, b, y0):
    """(cost, x): the exact least cost from a to b ((y, x)) across the straight interface y = y0
    between media of cost u1 (a's side) and u2, and where it crosses (bisection on Snell's law)."""

    def slope(x):
        return u1 * (x - a[1]) / np.hypot(x - a[1], y0 - a[0]) - u2 * (b[1] - x) / np.hypot(
            b[1] - x, b[0] - y0
        )

    lo, hi = a[1], b[1]
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if slope(mid) < 0 else (lo, mid)
    x = (lo + hi) / 2
    return u1 * np.hypot(x - a[1], y0 - a[0]) + u2 * np.hypot(b[1] - x, b[0] - y0), x


# -- A season of charts: time-dependent steps with waiting ------------------------------------
def season_step_arrival(hours_per_km, valid_from_h, p, q, t, length):
    """Earliest arrival at q for a ship at p at time t (h), waiting allowed: the ship leaves at
    t or at any later chart time; each departure d crosses the chart valid at d (the last one
    whose time is <= d), taking length * sum(fraction x hours per km) over the step's pieces,
    closed when any pixel touched by the closed segment is inf in that chart."""
    di, dj = q[0] - p[0], q[1] - p[1]
    best = math.inf
    for d in [t] + [float(x) for x in valid_from_h if x > t]:
        k = max(i for i, x in enumerate(valid_from_h) if x <= d) if d >= valid_from_h[0] else 0
        h = hours_per_km[k]
        if any(not np.isfinite(h[p[0] + a, p[1] + b]) for a, b in touched(di, dj)):
            continue
        dur = length * sum(f * float(h[p[0] + a, p[1] + b]) for (a, b), f in pieces(di, dj))
        best = min(best, d + dur)
    return best


def season_path_arrival(hours_per_km, valid_from_h, path, length_of):
    """Arrival time along a pixel path from time 0; length_of(p, q) gives a step's length."""
    t = 0.0
    for p, q in zip(path[:-1], path[1:]):
        t = season_step_arrival(hours_per_km, valid_from_h, p, q, t, length_of(p, q))
        if not math.isfinite(t):
            return math.inf
    return t


def best_arrival_over_paths(shape, start, end, k, step_arrival):
    """The earliest arrival over every simple path of k x k stencil steps from time 0
    (depth-first), step_arrival(p, q, t) the arrival at q leaving p at t: with waiting allowed no
    path needs to revisit a pixel, since waiting there dominates the loop."""
    rows, cols = shape
    offsets = stencil_offsets(k, "full")
    best = math.inf

    def walk(p, t, seen):
        nonlocal best
        if p == end:
            best = min(best, t)
            return
        for di, dj in offsets:
            q = (p[0] + di, p[1] + dj)
            if not (0 <= q[0] < rows and 0 <= q[1] < cols) or q in seen:
                continue
            a = step_arrival(p, q, t)
            if a < best:  # arrival times only grow along a path
                walk(q, a, seen | {q})

    walk(start, 0.0, {start})
    return best


def season_best_arrival(hours_per_km, valid_from_h, start, end, k, length_of):
    """The earliest arrival through a season over every simple path (best_arrival_over_paths)."""
    return best_arrival_over_paths(
        hours_per_km.shape[1:],
        start,
        end,
        k,
        lambda p, q, t: season_step_arrival(hours_per_km, valid_from_h, p, q, t, length_of(p, q)),
    )
