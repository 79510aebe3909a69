"""What each exact method would cost a query on a chart with landmarks: the cost model behind
method="auto" (seaway.engine.methods).

A search's time is the pixels it settles times its time per settled pixel, plus its start-up
(threads, rounds). The pixels are estimated before any search from a fixed sample of the
chart's pixels (SAMPLE of them, drawn when the landmarks are built) and the landmark tables:
for a sampled pixel v, a = max_l |D_l(v) - D_l(s)| and b = max_l |D_l(v) - D_l(t)| are lower
bounds on its cost from the start and to the end, and C = max_l |D_l(t) - D_l(s)| on the
route's (within a few per cent of it on the benchmark charts). Then
  Dijkstra settles the pixels with a < C,
  A* those with a + h(v) < C (h: the straight-line bound to the end),
  bidirectional search those with a < C/2 from the start and b < C/2 from the end (with the
    A* potential on low-contrast charts, a + (h(v) - g(v))/2 < C/2 and the mirror image,
    g: the bound from the start),
  the landmark searches a power law of those with a + b < (1 + LANDMARK_SLACK) C and of
    Dijkstra's count (LANDMARK_FIT),
each share of the sample times the pixels the landmarks reach. The shares and the times per
pixel were measured on the benchmark charts (benchmarks/README.md): the counts come within a
factor of about 1.5 of the settled pixels for the plain searches and 2 for the landmark ones.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from ..base.units import EARTH_RADIUS_KM

if TYPE_CHECKING:
    from ..models.base import CostModel
    from .prepared import PreparedChart

Floats = npt.NDArray[np.float64]

#: Pixels in the sample the counts are estimated from.
SAMPLE = 4096
#: Wall nanoseconds per settled pixel with two free cores: 5x5 stencil, the benchmark chart's
#: corner voyage on a prepared chart (benchmarks/README.md; the two-thread searches' pixels
#: are settled by both threads, so their time per pixel is half their CPU time's).
PIXEL_NS = {
    "dijkstra": 133.0,
    "astar": 163.0,
    "bidirectional": 75.0,
    "bidirectional A*": 100.0,
    "landmarks": 235.0,
    "landmarks one thread": 272.0,
}
#: Start-up seconds: the second thread and the first rounds of the two-thread searches.
START_S = {"bidirectional": 3e-4, "bidirectional A*": 3e-4, "landmarks": 3e-4}
#: The two-thread searches settle at least two rounds of 4096 pixels per side.
ROUND_PIXELS = 2 * 4096
#: The landmark searches' pixels: exp(k) x E^x x (D + LANDMARK_FLOOR)^y, E the pixels with
#: a + b < (1 + LANDMARK_SLACK) C plus LANDMARK_FLOOR, D Dijkstra's estimate: least squares in
#: log on 62 voyages of the benchmark charts (winter and summer; rms error a factor of 2).
LANDMARK_SLACK, LANDMARK_FLOOR = 0.2, 3000.0
LANDMARK_FIT = {"landmarks": (0.529, 0.352, 0.46), "landmarks one thread": (0.082, 0.739, 0.15)}


@dataclass(frozen=True)
class Sample:
    """SAMPLE pixels reached by the landmarks: flat index, row, col, their landmark rows."""

    flat: npt.NDArray[np.int64]
    rows: npt.NDArray[np.int64]
    cols: npt.NDArray[np.int64]
    table: Floats  # (landmarks, SAMPLE): one landmark's costs contiguous
    reached: int  # pixels the landmarks reach (the population sampled)


def make_sample(table: npt.NDArray[np.float32], cols: int) -> Sample:
    """A fixed sample (seeded: the same chart gives the same choice) of the pixels the landmarks
    reach; table: the (pixels, landmarks) tables."""
    reached = np.flatnonzero(np.isfinite(table[:, 0]))
    rng = np.random.default_rng(0)
    flat = np.sort(rng.choice(reached, min(SAMPLE, reached.size), replace=False))
    return Sample(
        flat,
        flat // cols,
        flat % cols,
        np.ascontiguousarray(np.asarray(table[flat], float).T),
        int(reached.size),
    )


def _bound(table: Floats, at: Floats) -> Floats:
    """max over landmarks l of |table[l] - at[l]|, skipping landmarks that reach neither (NaN)."""
    out: Floats = np.abs(table[0] - at[0])
    for row, x in zip(table[1:], at[1:]):
        np.fmax(out, np.abs(row - x), out=out)
    return out


def _distance(
    prepared: PreparedChart, rows: npt.NDArray[np.int64], cols: npt.NDArray[np.int64], rc: tuple[int, int]
) -> Floats:
    """Straight-line (planar) or great-circle (km) distance from pixels to pixel rc."""
    g = prepared.chart.grid
    if not g.geographic:
        out: Floats = np.hypot((rows - rc[0]) * g.dy, (cols - rc[1]) * g.dx)
        return out
    lat, lon = np.radians(g.lat0 + rows * g.dlat), np.radians(g.lon0 + cols * g.dlon)
    lat2, lon2 = math.radians(g.lat0 + rc[0] * g.dlat), math.radians(g.lon0 + rc[1] * g.dlon)
    h = np.sin((lat - lat2) / 2) ** 2 + np.cos(lat) * math.cos(lat2) * np.sin((lon - lon2) / 2) ** 2
    km: Floats = 2 * EARTH_RADIUS_KM * np.arcsin(np.sqrt(np.minimum(h, 1.0)))
    return km


def settled(
    prepared: PreparedChart,
    model: CostModel,
    sample: Sample,
    table: npt.NDArray[np.float32],
    s: tuple[int, int],
    e: tuple[int, int],
    astar_potential: bool,
) -> dict[str, float]:
    """Predicted pixels each exact search settles for the query s -> e (pixels (row, col))."""
    cols = prepared.chart.shape[1]
    ts, te = (np.asarray(table[p[0] * cols + p[1]], float) for p in (s, e))
    with np.errstate(invalid="ignore"):  # inf - inf: a landmark reaches neither (fmax skips it)
        c = float(np.fmax.reduce(np.abs(te - ts)))
        a, b = _bound(sample.table, ts), _bound(sample.table, te)
    c = c if math.isfinite(c) else 0.0
    rate = 1.0 if model.name == "length" else prepared.router.cost_range[0]
    h = rate * _distance(prepared, sample.rows, sample.cols, e)
    g = rate * _distance(prepared, sample.rows, sample.cols, s)
    n = sample.reached / a.size
    ball = n * np.count_nonzero(a < c)
    ellipse = n * np.count_nonzero(a + b < (1 + LANDMARK_SLACK) * c) + LANDMARK_FLOOR
    pixels: dict[str, float] = {"dijkstra": ball, "astar": n * np.count_nonzero(a + h < c)}
    if astar_potential:
        pixels["bidirectional A*"] = n * (
            np.count_nonzero(a + (h - g) / 2 < c / 2) + np.count_nonzero(b + (g - h) / 2 < c / 2)
        )
    else:
        pixels["bidirectional"] = n * (np.count_nonzero(a < c / 2) + np.count_nonzero(b < c / 2))
    for m, (k, x, y) in LANDMARK_FIT.items():
        pixels[m] = math.exp(k) * ellipse**x * (ball + LANDMARK_FLOOR) ** y
    return {m: float(max(p, ROUND_PIXELS if m in START_S else 1.0)) for m, p in pixels.items()}


def estimate(
    prepared: PreparedChart,
    model: CostModel,
    sample: Sample,
    table: npt.NDArray[np.float32],
    s: tuple[int, int],
    e: tuple[int, int],
    astar_potential: bool,
) -> dict[str, float]:
    """Predicted seconds of each exact method for the query s -> e (pixels (row, col))."""
    pixels = settled(prepared, model, sample, table, s, e, astar_potential)
    return {m: START_S.get(m, 0.0) + p * PIXEL_NS[m] * 1e-9 for m, p in pixels.items()}
