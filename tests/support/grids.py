"""Random charts of every grid kind and the path check against the reference (moved from
engine/test_reference.py; used by the engine, turn and smoothing tests)."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from scipy import ndimage

from support.reference import RefGraph, haversine

EDGE_COSTS = ("max", "mean", "integral", "length")


KS = (3, 5, 7)


DIRECTIONS = ("full", "unique")


GRIDS = ("planar", "geo_asc", "geo_desc", "geo_wrap")


RTOL = 1e-9


CASES = list(itertools.product(EDGE_COSTS, KS, DIRECTIONS, GRIDS))


def make_chart(seed: int, grid: str, zeros: bool):
    """A random chart with land, inf and NaN pixels (and some zero-cost pixels if `zeros`),
    plus the geometry kwargs for seaway and the reference."""
    rng = np.random.default_rng(seed)
    if grid == "geo_wrap":
        rows, cols = int(rng.integers(6, 10)), int(rng.choice([16, 18, 20]))
    else:
        rows, cols = (int(v) for v in rng.integers(6, 15, size=2))
    u = rng.uniform(0.2, 3.0, size=(rows, cols))
    pick = rng.random((rows, cols))
    if zeros:
        u[pick < 0.08] = 0.0
    wet = 0.90 - 0.12 * (seed % 2)  # every other chart is cluttered enough to cut off water
    u[(pick > wet) & (pick < 0.94)] = np.inf
    u[pick >= 0.96] = np.nan
    land = (pick >= 0.94) & (pick < 0.96) | (rng.random((rows, cols)) < 0.04)
    geo = {}
    if grid == "planar":
        geo = dict(dx=float(rng.uniform(0.3, 3.0)), dy=float(rng.uniform(0.3, 3.0)))
    else:
        if grid == "geo_wrap":
            dlat, dlon = 4.0 * (1 if seed % 2 else -1), (360.0 / cols) * (1 if seed % 4 < 2 else -1)
            lat0 = (
                float(rng.uniform(-60, 60 - 4 * rows)) if dlat > 0 else float(rng.uniform(-60 + 4 * rows, 60))
            )
            lon0 = float(rng.uniform(-180, 180))
        else:
            sign = 1 if grid == "geo_asc" else -1
            dlat, dlon = sign * float(rng.uniform(0.3, 2.5)), sign * float(rng.uniform(0.3, 2.5))
            lat0 = float(rng.uniform(-70, 70 - abs(dlat) * rows))
            if sign < 0:
                lat0 += abs(dlat) * (rows - 1)
            lon0 = float(rng.uniform(-180, 180))
        geo = dict(lat=lat0 + dlat * np.arange(rows), lon=lon0 + dlon * np.arange(cols))
    return u, land, geo


def point(geo, rc):
    """What route() takes for pixel rc: (lat, lon) on geographic charts, (row, col) otherwise."""
    if "lat" in geo:
        return (float(geo["lat"][rc[0]]), float(geo["lon"][rc[1]]))
    return (int(rc[0]), int(rc[1]))


def check_path(ref: RefGraph, r, start_rc, end_rc, geo):
    """r.pixels runs from start to end by allowed stencil steps and its edge costs add up."""
    px = np.asarray(r.pixels)
    assert px.ndim == 2 and px.shape[1] == 2
    assert tuple(px[0]) == tuple(start_rc) and tuple(px[-1]) == tuple(end_rc)
    offsets = set(ref.offsets)
    for p, q in zip(px[:-1], px[1:]):
        assert ref.offset(p, q) in offsets, f"{tuple(p)} -> {tuple(q)} is not a stencil step"
    assert ref.path_cost(px) == pytest.approx(r.cost, rel=RTOL, abs=1e-12)
    if "lat" in geo:
        lat, lon = geo["lat"], geo["lon"]
        legs = [haversine(lat[p[0]], lon[p[1]], lat[q[0]], lon[q[1]]) for p, q in zip(px[:-1], px[1:])]
    else:
        legs = [
            math.hypot((q[0] - p[0]) * geo["dy"], (q[1] - p[1]) * geo["dx"]) for p, q in zip(px[:-1], px[1:])
        ]
    assert r.length == pytest.approx(float(np.sum(legs)), rel=RTOL, abs=1e-12)


def blob_sea(seed, shape=(120, 150), lo=1.0, hi=30.0):
    """Smooth random ice costs lo..hi with blobs of land (inf)."""
    rng = np.random.default_rng(seed)
    field = ndimage.gaussian_filter(rng.random(shape), 6)
    field = (field - field.min()) / np.ptp(field)
    u = lo + (hi - lo) * field
    u[ndimage.gaussian_filter(rng.random(shape), 4) > 0.56] = np.inf
    return u


def largest_water(u):
    """The (row, col) of the pixels of u's largest body of 8-connected finite pixels."""
    labels, _ = ndimage.label(np.isfinite(u), np.ones((3, 3)))
    return np.argwhere(labels == np.bincount(labels.ravel())[1:].argmax() + 1)


def blob_geo(seed, shape):
    """Pixels for a blob_sea chart: planar 1.5 x 0.8 (seed 0), else lat/lon from 70 N, 0.05 x
    0.15 degrees, rows ascending (seed 1) or descending (seed 2)."""
    if not seed:
        return dict(dx=1.5, dy=0.8)
    lat = np.linspace(70.0, 70.0 + 0.05 * (shape[0] - 1), shape[0])
    lon = np.linspace(30.0, 30.0 + 0.15 * (shape[1] - 1), shape[1])
    return dict(lat=lat[::-1] if seed == 2 else lat, lon=lon)


def reference_voyages(ref: RefGraph, water, rng, starts):
    """(start, end, least cost) for `starts` random starts in `water`, each to a random pixel of
    it and to the pixel farthest from it, by the brute-force reference."""
    for a in rng.choice(len(water), size=starts, replace=False):
        s = tuple(map(int, water[a]))
        costs = ref.costs(s)
        far = np.unravel_index(np.argmax(np.where(np.isfinite(costs), costs, -1)), costs.shape)
        for e in (tuple(map(int, water[rng.integers(len(water))])), tuple(map(int, far))):
            yield s, e, costs[e]
