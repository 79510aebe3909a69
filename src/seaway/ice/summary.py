"""Route summaries for ice: distance and time in each stage of development and concentration
band, the POLARIS RIO met, and whether any leg is in elevated risk.

A leg (step between two route pixels) is split half and half between its two end pixels for
the per-stage and per-band sums, so the sums add up to the route's length. A leg's time is its
length times the time cost the route's edge rule gives it (max or mean of the two ends).
Concentration bands follow the WMO nomenclature: ice free (< 1/10), very open (1-3/10), open
(4-6/10), close (7-8/10), very close or compact (9-10/10), and 'unknown' (NaN)."""

from __future__ import annotations

import numpy as np

from ..models.base import EdgeCost
from .codes import stage_name
from .impact import governing_stage

BANDS = (("ice free <1/10", -np.inf, 1.0), ("very open 1-3/10", 1.0, 4.0),
         ("open 4-6/10", 4.0, 7.0), ("close 7-8/10", 7.0, 9.0),
         ("very close 9-10/10", 9.0, np.inf))


def band_name(ct: float) -> str:
    """WMO concentration band of a total concentration in tenths ('unknown' for NaN)."""
    if not np.isfinite(ct):
        return "unknown"
    return next(name for name, lo, hi in BANDS if lo <= ct < hi)


def _layer(x, pixels):
    if x is None:
        return None
    v = np.asarray(getattr(x, "values", x), dtype=float)
    return v[pixels[:, 0], pixels[:, 1]]


def _chart_layers(chart):
    """(stage, concentration) rasters of a chart Dataset: SIGRID names or kara_sea() names."""
    if "CT" in chart and "SA" in chart:

        return governing_stage(chart), chart["CT"]
    return chart["stage_of_development"], chart["sea_ice_concentration"]


def summarize(route, chart, *, time_cost=None, polaris=None) -> dict:
    """Summary of `route` (a seaway Route found on this chart's grid) over `chart` (a SIGRID
    chart Dataset or seaway.samples.kara_sea()).

    time_cost: optional raster of time per unit length (e.g. h/km from andreeva.time_cost or
    polaris_chart(...).cost) to give times; polaris: optional Dataset from
    polaris.polaris_chart for the RIO and the operation levels.
    Returns a dict: length (km on geographic charts, else grid units), time (or None),
    by_stage and by_concentration ({name: {'distance', 'time'}}), and with `polaris`:
    rio_min (the worst RIO met: lowest), rio_max, elevated_risk (any leg touches an
    elevated-risk pixel), elevated_distance, special_consideration (should be False)."""
    px = np.asarray(route.pixels)
    legs = np.asarray(route.leg_lengths, dtype=float)
    stage_raster, conc_raster = _chart_layers(chart)
    stage, conc = _layer(stage_raster, px), _layer(conc_raster, px)
    leg_time = None
    if time_cost is not None:
        tc = _layer(time_cost, px)
        rule = route.model if isinstance(route.model, EdgeCost) else EdgeCost("mean")
        leg_time = rule.pair_costs(tc[:-1], tc[1:], legs)
    by_stage, by_band = {}, {}
    for k, length in enumerate(legs):
        for end in (k, k + 1):
            t = None if leg_time is None else leg_time[k] / 2
            for table, key in ((by_stage, stage_name(stage[end])), (by_band, band_name(conc[end]))):
                entry = table.setdefault(key, {"distance": 0.0, "time": 0.0 if t is not None else None})
                entry["distance"] += float(length) / 2
                if t is not None:
                    entry["time"] += float(t)
    out = {"length": float(legs.sum()),
           "time": None if leg_time is None else float(leg_time.sum()),
           "by_stage": by_stage, "by_concentration": by_band}
    if polaris is not None:
        r = _layer(polaris["rio"], px)
        level = _layer(polaris["level"], px)
        elevated_leg = (level[:-1] == 1) | (level[1:] == 1)
        out.update(rio_min=float(np.nanmin(r)), rio_max=float(np.nanmax(r)),
                   elevated_risk=bool(elevated_leg.any()),
                   elevated_distance=float(legs[elevated_leg].sum()),
                   special_consideration=bool((level == 2).any()))
    return out
