"""What a route meets on its way: chart variables (ice, weather, depth) sampled along its legs,
for the leg tables, summaries and exports."""

from __future__ import annotations

import numpy as np

#: Environment variables whose least value along a leg matters (reported instead of the most).
LEAST = frozenset({"depth"})


def extreme_name(name: str) -> str:
    """'min' for variables in LEAST (depth), else 'max': the second number of a leg's pair."""
    return "min" if name in LEAST else "max"


def along(route, i: int, j: int) -> dict:
    """name -> (mean, max) ((mean, min) for LEAST) of each environment variable between
    vertices i and j of `route`, sampled every half pixel."""
    if not route.environment:
        return {}
    p = route.sample_pixels(i, j)
    out = {}
    for name, arr in route.environment.items():
        cols = p[:, 1] % arr.shape[1]
        vals = np.asarray(arr, float)[np.clip(p[:, 0], 0, arr.shape[0] - 1), cols]
        vals = vals[np.isfinite(vals)]
        top = vals.min() if name in LEAST else vals.max()
        out[name] = (float(vals.mean()), float(top)) if vals.size else (np.nan, np.nan)
    return out


def least_depth(route, depth):
    """(depth in m, (lat, lon) or (y, x)) of the shallowest pixel the route crosses (sampled
    every half pixel along its legs, as the leg tables are)."""
    z = np.asarray(getattr(depth, "values", depth), dtype=float)
    p = route.sample_pixels()
    vals = z[p[:, 0], p[:, 1] % z.shape[1]]
    if not np.isfinite(vals).any():
        return np.nan, None
    i = int(np.nanargmin(vals))
    where = route.chart.pixel_coords(p[i:i + 1] % [z.shape[0], z.shape[1]])[0]
    return float(vals[i]), (float(where[0]), float(where[1]))
