"""Brute-force distance to the nearest True pixel of a mask (moved from
constraints/test_constraints.py)."""

import numpy as np

from support.reference import haversine


def brute_distance(mask, lat=None, lon=None, dx=1.0, dy=1.0):
    """Distance from every pixel centre to the nearest mask pixel centre, all pairs."""
    rows, cols = mask.shape
    R, C = np.meshgrid(np.arange(rows), np.arange(cols), indexing="ij")
    out = np.full(mask.shape, np.inf)
    for r, c in np.argwhere(mask):
        if lat is not None:
            d = haversine(lat[R], lon[C], lat[r], lon[c])
        else:
            d = np.hypot((R - r) * dy, (C - c) * dx)
        out = np.minimum(out, d)
    return out
