"""A planar cost raster for benchmarks (seaway.samples re-exports it): land in a few large blobs
and islands, smooth ice-like costs over the water, and a channel that keeps two corners joined."""

from __future__ import annotations

import numpy as np

from ..base.fields import resample, smooth_noise
from ..base.memory import SEARCH, SYNTHETIC, check_shape
from ..base.validate import number
from ..errors import SeawayError


def synthetic_endpoints(shape=(1900, 2300)):
    """(row, col) start near the south-west corner and end near the north-east corner of
    synthetic_sea(shape); both are water and joined by water (rows run north to south)."""
    rows, cols = (int(n) for n in shape)
    return (rows - 1 - rows // 20, cols // 20), (rows // 20, cols - 1 - cols // 20)


SYNTHETIC_START, SYNTHETIC_END = synthetic_endpoints()


def synthetic_sea(shape=(1900, 2300), land_fraction=0.3, seed=0):
    """A deterministic planar cost raster for benchmarks: land (np.inf) in a few large blobs and
    islands covering `land_fraction` of the pixels, smooth ice-like costs 1-30 over the water
    (open water 1-2). A winding channel keeps synthetic_endpoints(shape) connected by water."""
    rows, cols = (int(n) for n in shape)
    if rows < 20 or cols < 20:
        raise SeawayError(f"shape must be at least (20, 20), got {shape!r}")
    check_shape(rows, cols, SYNTHETIC + SEARCH, "the synthetic sea", "give a smaller shape", SeawayError)
    number(land_fraction, "land_fraction", minimum=0, maximum=0.9, what="a number in [0, 0.9)")
    if land_fraction == 0.9:
        raise SeawayError("land_fraction must be a number in [0, 0.9), got 0.9")
    rng = np.random.default_rng(seed)
    coarse = (max(rows // 8, 20), max(cols // 8, 20))
    cy, cx = np.mgrid[0 : coarse[0], 0 : coarse[1]] / np.array(coarse).reshape(2, 1, 1)
    blobs = np.zeros(coarse)
    for y, x, r in zip(rng.uniform(0.1, 0.9, 6), rng.uniform(0.1, 0.9, 6), rng.uniform(0.06, 0.12, 6)):
        blobs += np.exp(-((cy - y) ** 2 + (cx - x) ** 2) / (2 * r**2))
    relief = resample(blobs + 0.7 * smooth_noise(rng, coarse, 2.0), rows, cols)
    ice = resample(smooth_noise(rng, coarse, 4.0), rows, cols).astype(np.float64)

    (r0, c0), (r1, c1) = synthetic_endpoints(shape)
    knots = np.array([[r0, c0], [0.65 * rows, 0.45 * cols], [0.35 * rows, 0.55 * cols], [r1, c1]])
    channel = _near_polyline(rows, cols, knots, max(3.0, 0.005 * min(rows, cols)))
    free = relief[~channel]
    k = int(round(land_fraction * rows * cols))
    land = np.zeros((rows, cols), bool)
    if k > 0:
        threshold = np.partition(free, free.size - k)[free.size - k]
        land = (relief >= threshold) & ~channel
    cost = 1.0 + 29.0 * ice**2
    cost[land] = np.inf
    return cost


def _near_polyline(rows, cols, knots, width):
    """Pixels within `width` of the polyline through `knots` ((row, col) points)."""
    r, c = np.mgrid[0:rows, 0:cols]
    best = np.full((rows, cols), np.inf)
    for a, b in zip(knots[:-1], knots[1:]):
        ab = b - a
        t = np.clip(((r - a[0]) * ab[0] + (c - a[1]) * ab[1]) / (ab @ ab), 0, 1)
        np.minimum(best, np.hypot(r - a[0] - t * ab[0], c - a[1] - t * ab[1]), out=best)
    return best <= width
