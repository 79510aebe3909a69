"""More planar cost rasters for benchmarks, each by a recipe of its own, so that the engine's
speed is measured on charts it was not tuned on:

* floe_sea: a Kara-sized sea by another recipe than synthetic_sea: land from ridged noise (an
  archipelago with fjords), ice in zones of constant cost with sharp edges (as a chart's
  polygons) cut by straight leads of open water.
* game_map: a coastline of the kind game maps have (fractal noise at three scales) with smooth
  ice-like costs 1-20.
* maze: a perfect maze of narrow channels between walls of land, costs 1-5.

Every recipe is deterministic (seeded) and returns costs >= 1 with np.inf on land; ends of a
voyage are best taken from the water reached from one pixel (several water bodies may exist)."""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ..base.fields import resample, smooth_noise
from ..errors import SeawayError

Floats = npt.NDArray[np.float64]


def _check(shape: tuple[int, int], least: int) -> tuple[int, int]:
    rows, cols = (int(n) for n in shape)
    if rows < least or cols < least:
        raise SeawayError(f"shape must be at least ({least}, {least}), got {shape!r}")
    return rows, cols


def _octaves(
    rng: np.random.Generator, rows: int, cols: int, scales: tuple[float, ...], amps: tuple[float, ...] = ()
) -> Floats:
    """Sum of smooth noise at `scales` (correlation lengths in pixels) with amplitudes `amps`
    (default: proportional to the scale)."""
    out = np.zeros((rows, cols))
    for i, s in enumerate(scales):
        step = max(1, int(s // 4))
        coarse = (max(rows // step, 8), max(cols // step, 8))
        a = amps[i] if amps else s / scales[0]
        out += a * resample(smooth_noise(rng, coarse, 4.0), rows, cols)
    return out


def _threshold(field: Floats, share: float) -> npt.NDArray[np.bool_]:
    """The `share` of the pixels with the highest values."""
    k = int(round(share * field.size))
    if k <= 0:
        return np.zeros(field.shape, bool)
    return field >= np.partition(field.ravel(), field.size - k)[field.size - k]


def floe_sea(shape: tuple[int, int] = (2300, 1900), land_fraction: float = 0.3, seed: int = 1) -> Floats:
    """A Kara-sized sea by a second recipe: land (np.inf) on `land_fraction` of the pixels from
    ridged noise; ice in zones of constant cost (1, 2, 4, 8, 15, 30) bounded by the level lines
    of a smooth field, cut by 12 straight leads 2-4 pixels wide of cost 1.2."""
    rows, cols = _check(shape, 40)
    rng = np.random.default_rng(seed)
    span = min(rows, cols)
    ridged = np.zeros((rows, cols))
    for s, a in ((span / 6, 1.0), (span / 20, 0.45), (span / 60, 0.2)):
        n = _octaves(rng, rows, cols, (s,))
        ridged += a * (1 - np.abs(2 * n - 1))
    # a margin of water along the edges keeps the corners joined
    r, c = np.mgrid[0:rows, 0:cols]
    edge = np.minimum(np.minimum(r, rows - 1 - r), np.minimum(c, cols - 1 - c)) / (0.04 * span)
    ridged -= np.clip(1 - edge, 0, 1) * 3
    land = _threshold(ridged, land_fraction)
    zones = _octaves(rng, rows, cols, (span / 8, span / 30))
    levels = np.quantile(zones, [0.25, 0.45, 0.6, 0.75, 0.9])
    cost = np.array([1.0, 2.0, 4.0, 8.0, 15.0, 30.0])[np.searchsorted(levels, zones)]
    for _ in range(12):  # leads: straight cracks of open water
        y0, x0 = rng.uniform(0, rows), rng.uniform(0, cols)
        ang, half = rng.uniform(0, np.pi), rng.uniform(1.0, 2.0)
        d = np.abs((r - y0) * np.cos(ang) - (c - x0) * np.sin(ang))
        along = np.abs((r - y0) * np.sin(ang) + (c - x0) * np.cos(ang))
        cost[(d <= half) & (along <= rng.uniform(0.2, 0.6) * span)] = 1.2
    cost[land] = np.inf
    return cost


def game_map(shape: tuple[int, int] = (1024, 1024), land_fraction: float = 0.35, seed: int = 2) -> Floats:
    """A game-map coastline: land from noise at three scales (bays, peninsulas, ragged edges) on
    `land_fraction` of the pixels, smooth ice-like costs 1-20 over the water."""
    rows, cols = _check(shape, 40)
    rng = np.random.default_rng(seed)
    span = min(rows, cols)
    relief = _octaves(rng, rows, cols, (span / 6, span / 20, span / 60), (1.0, 0.8, 0.5))
    land = _threshold(relief, land_fraction)
    ice = _octaves(rng, rows, cols, (span / 10,))
    cost = 1.0 + 19.0 * ((ice - ice.min()) / (np.ptp(ice) or 1.0)) ** 1.5
    cost[land] = np.inf
    return cost


def maze(shape: tuple[int, int] = (1200, 1200), cell: int = 12, wall: int = 4, seed: int = 3) -> Floats:
    """A perfect maze (one way between any two cells; depth-first, seeded) of channels
    `cell - wall` pixels wide between land walls `wall` pixels thick, costs 1-5 over the water;
    the channels join the cells nearest the corners."""
    rows, cols = _check(shape, 3 * cell)
    if not 0 < wall < cell - 2:
        raise SeawayError(f"wall must be from 1 to cell - 3 pixels, got {wall} (cell {cell})")
    rng = np.random.default_rng(seed)
    nr, nc = rows // cell, cols // cell
    water = np.zeros((rows, cols), bool)
    seen = np.zeros((nr, nc), bool)
    stack = [(0, 0)]
    seen[0, 0] = True

    def carve(i: int, j: int, di: int = 0, dj: int = 0) -> None:
        # the cell's square, stretched towards the neighbour it joins
        r0, c0 = i * cell + wall, j * cell + wall
        r1, c1 = (i + 1) * cell, (j + 1) * cell
        r0, r1 = (r0 - cell, r1) if di < 0 else (r0, r1 + (cell if di > 0 else 0))
        c0, c1 = (c0 - cell, c1) if dj < 0 else (c0, c1 + (cell if dj > 0 else 0))
        water[max(r0, 0) : r1, max(c0, 0) : c1] = True

    carve(0, 0)
    while stack:
        i, j = stack[-1]
        nbrs = [
            (i + a, j + b)
            for a, b in ((1, 0), (-1, 0), (0, 1), (0, -1))
            if 0 <= i + a < nr and 0 <= j + b < nc and not seen[i + a, j + b]
        ]
        if not nbrs:
            stack.pop()
            continue
        ni, nj = nbrs[int(rng.integers(len(nbrs)))]
        seen[ni, nj] = True
        carve(i, j, ni - i, nj - j)
        stack.append((ni, nj))
    cost = 1.0 + 4.0 * _octaves(rng, rows, cols, (min(rows, cols) / 8,))
    cost[~water] = np.inf
    return cost
