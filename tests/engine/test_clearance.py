"""The land clearance the preparation builds (cpp/seaway/passability.hpp), against a numpy
reference: Chebyshev pixels to the nearest impassable pixel (NaN, inf, land), capped at the
stencil's half-width + 1, across the seam on a 360-degree chart; 0 on impassable pixels."""

import numpy as np
import pytest

import seaway


def _reference(blocked, cap, wrap):
    rows, cols = blocked.shape
    out = np.full(blocked.shape, cap, np.uint8)
    for di in range(-cap + 1, cap):
        for dj in range(-cap + 1, cap):
            d = max(abs(di), abs(dj))
            shifted = np.zeros_like(blocked)  # blocked[r + di, c + dj], outside the chart: open
            r0, r1 = max(0, -di), min(rows, rows - di)
            if wrap:
                shifted[r0:r1] = np.roll(blocked, -dj, axis=1)[r0 + di : r1 + di]
            else:
                c0, c1 = max(0, -dj), min(cols, cols - dj)
                shifted[r0:r1, c0:c1] = blocked[r0 + di : r1 + di, c0 + dj : c1 + dj]
            out[shifted] = np.minimum(out[shifted], d)
    return out


@pytest.mark.parametrize("k", [3, 5, 9, 15])
@pytest.mark.parametrize("seed", range(4))
def test_clearance_equals_the_reference(k, seed):
    rng = np.random.default_rng(seed)
    rows, cols = int(rng.integers(1, 40)), int(rng.integers(16, 70))  # a wrapping chart: 16 or more
    u = rng.random((rows, cols)) + 0.5
    u[rng.random(u.shape) < [0.0, 0.02, 0.1, 0.4][seed]] = np.inf
    u[rng.random(u.shape) < 0.01] = np.nan
    land = rng.random(u.shape) < 0.02
    u[0, 0] = 1.0
    land[0, 0] = False
    for geo in (False, True):
        if geo:  # 360 degrees of longitude: the columns wrap
            lon = -180.0 + (360.0 / cols) * (np.arange(cols) + 0.5)
            lat = np.linspace(-60.0, 60.0, rows) if rows > 1 else np.array([0.0])
            opts = dict(lat=lat, lon=lon)
        else:
            opts = {}
        chart = seaway.prepare(
            u.astype(np.float32 if seed % 2 else np.float64), land=land, neighbourhood=k, **opts
        )
        blocked = ~np.isfinite(u) | land
        wrap = chart.chart.grid.wrap
        assert wrap == geo
        assert chart.router.clearance.tolist() == _reference(blocked, (k - 1) // 2 + 1, wrap).tolist()
