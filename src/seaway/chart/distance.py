"""Distance from every pixel centre to the nearest pixel of a mask, for keep-away buffers
(seaway.constraints): exact great-circle km on lat/lon charts, scipy.ndimage's exact EDT on
planar ones."""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from ..base.units import EARTH_RADIUS_KM
from .raster import Chart


def _row_gaps(mask: npt.NDArray[np.bool_], wrap: bool) -> npt.NDArray[np.float64]:
    """Per pixel, the column distance (in pixels) to the nearest True pixel of its own row
    (inf when the row has none); columns wrap around on global charts."""
    rows, cols = mask.shape
    m = np.concatenate([mask, mask, mask], axis=1) if wrap else mask
    n = m.shape[1]
    col = np.arange(n, dtype=float)
    left = np.where(m, col, -np.inf)
    np.maximum.accumulate(left, axis=1, out=left)
    right = np.where(m, col, np.inf)
    right = np.minimum.accumulate(right[:, ::-1], axis=1)[:, ::-1]
    gap: npt.NDArray[np.float64] = np.minimum(col - left, right - col)
    return gap[:, cols : 2 * cols] if wrap else gap


def distance_to(mask: npt.ArrayLike, chart: Chart, limit: float) -> npt.NDArray[np.float64]:
    """Distance from every pixel centre to the nearest True pixel centre of `mask` (0 on the
    mask), exact up to `limit` and inf beyond it: great-circle km on lat/lon charts (sphere of
    R = 6371.0088 km), Euclidean chart units on planar charts (scipy.ndimage's exact EDT).

    On lat/lon charts a pixel's east-west size changes with latitude, which a Euclidean
    transform with fixed sampling cannot express; instead, for each row within `limit`, the
    nearest feature of that row is the one with the smallest longitude gap (the great-circle
    distance between two latitudes grows with the longitude gap), and the least over rows is
    exact."""
    mask = np.asarray(mask, dtype=bool)
    if not mask.any():
        return np.full(mask.shape, np.inf)
    if not chart.geographic:
        from scipy.ndimage import distance_transform_edt

        g = chart.grid
        d = distance_transform_edt(~mask, sampling=(g.dy, g.dx))
        return np.where(d <= limit, d, np.inf)
    g = chart.grid
    rows, _ = mask.shape
    gap = _row_gaps(mask, bool(g.wrap)) * abs(g.dlon)  # degrees of longitude, inf if none
    lat = np.radians(chart.axes[0].astype(float))
    half = np.radians(np.minimum(gap, 180.0)) / 2
    sin2_half = np.where(np.isfinite(gap), np.sin(half) ** 2, np.inf)
    best = np.full(mask.shape, np.inf)  # haversine's a = sin^2(dphi/2) + cos cos sin^2(dl/2)
    reach = int(math.ceil(limit / (EARTH_RADIUS_KM * math.radians(abs(g.dlat))))) + 1
    for di in range(-min(reach, rows - 1), min(reach, rows - 1) + 1):
        lo, hi = max(0, -di), min(rows, rows - di)  # rows r whose row r + di exists
        r, q = np.arange(lo, hi), np.arange(lo, hi) + di
        a = (np.sin((lat[q] - lat[r]) / 2) ** 2)[:, None] + (np.cos(lat[r]) * np.cos(lat[q]))[
            :, None
        ] * sin2_half[q]
        np.minimum(best[lo:hi], a, out=best[lo:hi])
    d = 2 * EARTH_RADIUS_KM * np.arcsin(np.sqrt(np.clip(best, 0.0, 1.0)))
    d[~np.isfinite(best)] = np.inf
    return np.where(d <= limit, d, np.inf)
