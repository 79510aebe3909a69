"""Any-angle smoothing of a raster route (paper 000: "the route can be smoothed afterwards").

1. Line-of-sight shortcuts (string pulling): from each anchor vertex, the route is replaced by
   one straight leg (a great circle on geographic charts) to the farthest vertex ahead such that
   the leg touches no impassable pixel and costs no more than the part of the route it replaces.
2. Refinement (optional): each turning point in turn is moved off the pixel centres by a
   compass search (steps of 1 pixel halved down to 1/32) to lower the cost of its two legs,
   then shortcuts are taken again; sweeps repeat until the cost stops falling.

Legs are priced by seaway._segments (the engine's model extended to arbitrary legs: exact line
integral for "integral"; the max/mean rule applied to the chain of pixels a leg crosses). Every
accepted change lowers the cost or keeps it (to a relative 1e-12 for rounding), so the smoothed
route never costs more than the route it came from, under the model that route was found with."""

from __future__ import annotations

import dataclasses

import numpy as np

RTOL = 1e-12
_DIRS = np.array([(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)], float)


def _pull(seg, v, step_cost, candidates):
    """String pulling over the chain v; returns (kept vertex indices, cost of each new leg)."""
    n = len(v)
    cum = np.concatenate([[0.0], np.cumsum(step_cost)])
    keep, costs, i = [0], [], 0
    while i < n - 1:
        best, best_cost, fail = i + 1, float(step_cost[i]), None
        for j in candidates[candidates > i + 1]:
            c = seg.leg(v[i], v[j])[0]
            if c <= (cum[j] - cum[i]) * (1 + RTOL):
                best, best_cost = int(j), c
            else:
                fail = int(j)
                break
        if fail is not None:  # the farthest vertex before the blocked turning point
            lo, hi = best, fail
            while hi - lo > 1:
                mid = (lo + hi) // 2
                c = seg.leg(v[i], v[mid])[0]
                if c <= (cum[mid] - cum[i]) * (1 + RTOL):
                    lo, best_cost = mid, c
                else:
                    hi = mid
            best = lo
        keep.append(best)
        costs.append(best_cost)
        i = best
    return np.array(keep), np.array(costs)


def _refine(seg, w, costs, active, min_step=1 / 32):
    """One sweep of compass search on each active interior waypoint; returns the improvement and
    which waypoints moved."""
    gained, moved_any = 0.0, np.zeros(len(w), bool)
    for k in range(1, len(w) - 1):
        if not active[k]:
            continue
        here = costs[k - 1] + costs[k]
        step = 1.0
        while step >= min_step:
            moved = False
            for d in _DIRS:
                p = w[k] + step * d
                a = seg.leg(w[k - 1], p)[0]
                if not np.isfinite(a) or a >= here:
                    continue
                b = seg.leg(p, w[k + 1])[0]
                if a + b < here * (1 - RTOL):
                    gained += here - (a + b)
                    w[k], costs[k - 1], costs[k], here, moved = p, a, b, a + b, True
                    moved_any[k] = True
                    break
            if not moved:
                step /= 2
    return gained, moved_any


def smooth(route, *, refine: bool = True, max_sweeps: int = 10):
    """The route with its zig-zag removed: fewer, any-angle waypoints; never a higher cost.

    Returns a Route whose vertices (`points`, fractional row/col; `coords`) are the waypoints;
    `pixels` holds the pixel of each waypoint. `stats` gains cost_before (the route's cost),
    course_changes_before / course_changes_after, sweeps and shortcut_legs."""
    v = route.vertices
    if len(v) < 3:
        return dataclasses.replace(route, points=v.copy(), step_costs=route.costs())
    seg = route.segments()
    step_cost = route.costs()
    idx, costs = _pull(seg, v, step_cost, route.waypoint_index)
    w = v[idx].copy()
    sweeps, active = 0, np.ones(len(w), bool)
    while refine and len(w) > 2 and sweeps < max_sweeps:
        sweeps += 1
        gained, moved = _refine(seg, w, costs, active)
        idx, costs = _pull(seg, w, costs, np.arange(len(w)))
        # next sweep: the waypoints that moved, their neighbours, and those next to a removal
        near = moved | np.roll(moved, 1) | np.roll(moved, -1)
        near[np.setdiff1d(np.arange(len(w)), idx) - 1] = True
        near[np.minimum(np.setdiff1d(np.arange(len(w)), idx) + 1, len(w) - 1)] = True
        w, active = w[idx], near[idx]
        if gained <= RTOL * max(costs.sum(), 1e-300) or not active[1:-1].any():
            break
    total = float(costs.sum())
    stats = dict(route.stats, cost_before=route.cost, course_changes_before=route.course_changes,
                 sweeps=sweeps, shortcut_legs=len(w) - 1)
    out = dataclasses.replace(route, cost=total, pixels=np.rint(w).astype(np.int64), points=w,
                              step_costs=np.asarray(costs, float), stats=stats,
                              method=f"{route.method}+smoothed")
    out.stats["course_changes_after"] = out.course_changes
    return out
