"""What a route meets on its way: chart variables (ice, weather, depth) sampled along its legs,
for the leg tables, summaries and exports.

Numeric variables give a leg's mean, min and max over the points sampled every half pixel
along it (`Numeric`: a (mean, max) pair, (mean, min) for LEAST, with .mean .min .max).
Categorical variables give one category (`Category`: .code, .name, .rule): the stages of
development (SA, SB, SC, stage_of_development) their governing stage, the most severe met
(seaway.ice.codes.SEVERITY: the thickest, unknown last); the form of ice (FA, FB, FC) and other
codes the most frequent. A leg that samples no value gives NaN numbers and the category "none"
(code NaN), never an error."""

from __future__ import annotations

from collections import Counter

import numpy as np

from ..chart.legs import index_coords, leg_path
from ..ice.codes import form_name, stage_name, stage_rank
from ..ice.forms import FREE_WATER
from ..native import haversine_km

__all__ = ["Numeric", "Category", "LEAST", "STAGES", "FORMS", "CATEGORICAL"]

#: Environment variables whose least value along a leg matters (reported instead of the most).
LEAST = frozenset({"depth"})
#: Categorical variables: a leg reports the governing stage (STAGES) or the most frequent code.
STAGES = frozenset({"SA", "SB", "SC", "stage_of_development"})
FORMS = frozenset({"FA", "FB", "FC"})
CATEGORICAL = STAGES | FORMS | frozenset({"polygon", "free_water"})


class Numeric(tuple):
    """(mean, max) ((mean, min) for LEAST) of a numeric variable along a leg, with .mean, .min,
    .max (NaN when the leg samples no value)."""

    mean: float
    min: float
    max: float

    def __new__(cls, mean, low, high, least=False):
        self = super().__new__(cls, (mean, low if least else high))
        self.mean, self.min, self.max = mean, low, high
        return self


class Category(tuple):
    """The category of a leg: (code, code) as a pair, with .code, .name ('none' when no value
    was sampled), .rule ('governing' or 'most frequent') and .share (of the sampled points)."""

    code: float
    name: str
    rule: str
    share: float
    label: str

    def __new__(cls, code, name, rule, share, coded=True):
        self = super().__new__(cls, (code, code))
        self.code, self.name, self.rule, self.share = code, name, rule, share
        self.label = f"{name} ({int(code)})" if coded and np.isfinite(code) else name
        return self

    def __str__(self) -> str:
        return self.label


def extreme_name(name: str) -> str:
    """'min' for variables in LEAST (depth), else 'max': the second number of a leg's pair."""
    return "min" if name in LEAST else "max"


def category_name(name: str, code: float) -> str:
    if not np.isfinite(code):
        return "none"
    if name in STAGES:
        return stage_name(code)
    if name in FORMS:
        return form_name(code)
    if name == "free_water":
        return FREE_WATER.get(int(code), "neither")
    return f"{name} {int(code)}"


def summarise(name: str, vals: np.ndarray, weights=None):
    """The Numeric or Category of values sampled along a leg (NaN ignored); `weights` (the
    length each sample stands for) make the mean a length-weighted one."""
    vals = np.asarray(vals, float)
    keep = np.isfinite(vals)
    w = None if weights is None else np.asarray(weights, float)[keep]
    vals = vals[keep]
    if name in CATEGORICAL:
        if not vals.size:
            return Category(np.nan, "none", "governing" if name in STAGES else "most frequent", 0.0)
        counts = Counter(vals.tolist())
        if name in STAGES:
            code = max(counts, key=lambda c: (stage_rank(c), c))
            rule = "governing"
        else:
            code, rule = counts.most_common(1)[0][0], "most frequent"
        return Category(
            float(code),
            category_name(name, code),
            rule,
            counts[code] / vals.size,
            coded=name in STAGES | FORMS,
        )
    if not vals.size:
        return Numeric(np.nan, np.nan, np.nan, name in LEAST)
    mean = float(np.average(vals, weights=w)) if w is not None and w.sum() > 0 else float(vals.mean())
    low, high = float(vals.min()), float(vals.max())
    return Numeric(min(max(mean, low), high), low, high, name in LEAST)  # a constant's mean is itself


def values_at(arr, pixels) -> np.ndarray:
    """arr at (row, col) pixels (columns taken modulo the width, rows clipped), as float."""
    a = np.asarray(arr, float)
    return a[np.clip(pixels[:, 0], 0, a.shape[0] - 1), pixels[:, 1] % a.shape[1]]


def along(route, i: int, j: int) -> dict:
    """name -> Numeric or Category of each environment variable between vertices i and j of
    `route`: at the very samples its times are read at (weighted_samples: every half pixel of
    each step's own path), numbers as length-weighted means, so a leg's ice, speed and time come
    from the same pixels."""
    if not route.environment:
        return {}
    px, km, step = route_samples(route)
    inside = (step >= i) & (step < j)
    p, w = px[inside], km[inside]
    return {name: summarise(name, values_at(arr, p), w) for name, arr in route.environment.items()}


def route_samples(route):
    """weighted_samples(route), computed once per route (its times and legs read the same)."""
    cached = route.__dict__.get("_samples")
    if cached is None:
        cached = route.__dict__["_samples"] = weighted_samples(route)
    return cached


def weighted_samples(route):
    """(pixels (n, 2), length (n,) each sample stands for, step (n,)) along the route's steps:
    the midpoints of pieces at most half a pixel long of each step's own path (a great circle on
    lat/lon charts), each piece's length scaled so a step's pieces add up to its length (km on
    geographic charts, grid units on planar ones). Sums over them are line integrals along the
    route, smoothed or not."""
    v, steps = route.vertices, route.step_lengths
    half = (route.neighbourhood - 1) // 2
    if route.points is None and len(v) > 1:  # engine steps between pixel centres: vectorised
        return _step_samples(v, steps)
    pix, km, idx = [], [], []
    for k, (p, q) in enumerate(zip(v[:-1], v[1:])):
        straight = bool(np.all(p == np.round(p)) and np.all(q == np.round(q)) and np.abs(q - p).max() <= half)
        path = leg_path(route.chart, p, q, straight)
        pts, w = [], []
        for a, b in zip(path[:-1], path[1:]):
            m = max(int(np.ceil(2 * np.abs(b - a).max())), 1)
            t = (np.arange(m) + 0.5) / m
            pts.append(a + t[:, None] * (b - a))
            w.append(np.full(m, _piece_length(route, a, b) / m))
        w = np.concatenate(w)
        w = w * (steps[k] / w.sum()) if w.sum() > 0 else np.full(w.size, steps[k] / w.size)
        pix.append(np.rint(np.concatenate(pts)).astype(np.int64))
        km.append(w)
        idx.append(np.full(w.size, k))
    if not pix:
        return np.zeros((0, 2), np.int64), np.zeros(0), np.zeros(0, np.int64)
    return np.concatenate(pix), np.concatenate(km), np.concatenate(idx)


def _step_samples(v, steps):
    """weighted_samples of a route of engine steps (straight in index space, a few pixels long):
    m = ceil(2 * the step's longest side) equal pieces per step, each standing for 1/m of it."""
    d = np.diff(v, axis=0)
    m = np.maximum(np.ceil(2 * np.abs(d).max(axis=1)).astype(np.int64), 1)
    k = np.repeat(np.arange(len(d)), m)
    first = np.repeat(np.cumsum(m) - m, m)
    t = (np.arange(k.size) - first + 0.5) / m[k]
    pix = np.rint(v[k] + t[:, None] * d[k]).astype(np.int64)
    return pix, steps[k] / m[k], k


def _piece_length(route, a, b) -> float:
    if route.chart.geographic:
        (la1, lo1), (la2, lo2) = index_coords(route.chart, np.array([a, b]))
        return float(haversine_km(la1, lo1, la2, lo2))
    g = route.chart.grid
    return float(np.hypot((b[0] - a[0]) * g.dy, (b[1] - a[1]) * g.dx))


def least_depth(route, depth):
    """(depth in m, (lat, lon) or (y, x)) of the shallowest pixel the route crosses (sampled
    every half pixel along its legs, as the leg tables are)."""
    z = np.asarray(getattr(depth, "values", depth), dtype=float)
    p = route.sample_pixels()
    vals = z[p[:, 0], p[:, 1] % z.shape[1]]
    if not np.isfinite(vals).any():
        return np.nan, None
    i = int(np.nanargmin(vals))
    where = route.chart.pixel_coords(p[i : i + 1] % [z.shape[0], z.shape[1]])[0]
    return float(vals[i]), (float(where[0]), float(where[1]))
