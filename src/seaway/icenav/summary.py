"""Route summaries for ice: distance and time in each ice type (stage of development, fast ice,
open and bergy water) and concentration band, the POLARIS RIO met, and whether any leg is in
elevated risk.

The route is sampled along its legs (seaway.result.environment.weighted_samples: the midpoints
of pieces at most half a pixel long of each leg's own path, a great circle on lat/lon charts),
smoothed or not, so the distance in each ice type is the length of route inside it, as dense
sampling gives, and the sums add up to the route's length. The time of a step is its length
times the time cost the route's edge rule gives it (max or mean of its two ends), shared among
its samples in proportion to their length. Concentration bands follow the WMO nomenclature: ice
free (< 1/10), very open (1-3/10), open (4-6/10), close (7-8/10), very close or compact
(9-10/10), and 'unknown' (NaN). Ice types: the stage's name (seaway.ice.codes), "fast ice, ..."
for fast ice (FA 08; "..., assumed" where its stage is the fast_ice assumption, seaway.ice.forms),
"open water" and "bergy water" for CT codes 01 and 02."""

from __future__ import annotations

import numpy as np

from ..ice.codes import stage_name
from ..ice.forms import DEFAULT_FAST_ICE, FREE_WATER, fast_ice_mask, fast_ice_stage
from ..ice.impact import governing_stage
from ..models.base import EdgeCost
from ..result.environment import values_at, weighted_samples

BANDS = (
    ("ice free <1/10", -np.inf, 1.0),
    ("very open 1-3/10", 1.0, 4.0),
    ("open 4-6/10", 4.0, 7.0),
    ("close 7-8/10", 7.0, 9.0),
    ("very close 9-10/10", 9.0, np.inf),
)


def band_name(ct: float) -> str:
    """WMO concentration band of a total concentration in tenths ('unknown' for NaN)."""
    if not np.isfinite(ct):
        return "unknown"
    return next(name for name, lo, hi in BANDS if lo <= ct < hi)


def _layer(x, pixels):
    if x is None:
        return None
    return values_at(getattr(x, "values", x), pixels)


def _ice_types(chart, fast_ice):
    """(stage raster, concentration raster, name of each pixel's ice type as a function of the
    pixel index arrays, assumptions) of a chart Dataset: SIGRID names or kara_sea() names."""
    if "CT" in chart and "SA" in chart:
        stage = governing_stage(chart, fast_ice=fast_ice)
        fast = fast_ice_mask(chart)
        assumed = fast_ice_stage(chart, fast_ice)[2]
        free = np.asarray(chart["free_water"].values) if "free_water" in chart else np.zeros(fast.shape, int)

        def name(px, codes):
            r, c = px[:, 0], px[:, 1] % fast.shape[1]
            out = []
            for k, code in enumerate(codes):
                if free[r[k], c[k]] in FREE_WATER:
                    out.append(FREE_WATER[int(free[r[k], c[k]])])
                elif fast[r[k], c[k]]:
                    out.append(f"fast ice, {stage_name(code)}" + (", assumed" if assumed[r[k], c[k]] else ""))
                else:
                    out.append(stage_name(code))
            return out

        return stage, chart["CT"], name, stage.attrs["assumptions"]
    return (
        chart["stage_of_development"],
        chart["sea_ice_concentration"],
        lambda px, codes: [stage_name(c) for c in codes],
        (),
    )


def summarize(route, chart, *, time_cost=None, polaris=None, fast_ice=DEFAULT_FAST_ICE) -> dict:
    """Summary of `route` (a seaway Route found on this chart's grid) over `chart` (a SIGRID
    chart Dataset or seaway.samples.kara_sea()).

    time_cost: optional raster of time per unit length (e.g. h/km from andreeva.time_cost or
    polaris_chart(...).cost) to give times; polaris: optional Dataset from
    polaris.polaris_chart for the RIO and the operation levels; fast_ice: the stage of fast ice
    of unknown stage (seaway.ice.forms; use the one the route was found with).
    Returns a dict: length (km on geographic charts, else grid units), time (or None),
    by_stage (by ice type, see the module) and by_concentration ({name: {'distance', 'time'}}),
    assumptions (sentences: what the ice types assume), and with `polaris`: rio_min (the worst
    RIO met: lowest), rio_max, elevated_risk (any sample in an elevated-risk pixel),
    elevated_distance, special_consideration (should be False)."""
    legs = np.asarray(route.step_lengths, dtype=float)
    spx, skm, step = weighted_samples(route)
    stage_raster, conc_raster, names, assumptions = _ice_types(chart, fast_ice)
    stage, conc = _layer(stage_raster, spx), _layer(conc_raster, spx)
    sample_time = leg_time = None
    if time_cost is not None:
        vertex = np.rint(route.vertices).astype(np.int64)
        tc = _layer(time_cost, vertex)
        rule = route.model if isinstance(route.model, EdgeCost) else EdgeCost("mean")
        leg_time = rule.pair_costs(tc[:-1], tc[1:], legs)
        with np.errstate(invalid="ignore", divide="ignore"):
            sample_time = np.where(legs[step] > 0, leg_time[step] * skm / legs[step], 0.0)
    by_stage: dict = {}
    by_band: dict = {}
    for k, (kind, band) in enumerate(zip(names(spx, stage), map(band_name, conc))):
        t = None if sample_time is None else float(sample_time[k])
        for table, key in ((by_stage, kind), (by_band, band)):
            entry = table.setdefault(key, {"distance": 0.0, "time": 0.0 if t is not None else None})
            entry["distance"] += float(skm[k])
            if t is not None:
                entry["time"] += t
    out = {
        "length": float(legs.sum()),
        "time": None if leg_time is None else float(leg_time.sum()),
        "by_stage": by_stage,
        "by_concentration": by_band,
        "assumptions": tuple(assumptions),
    }
    if polaris is not None:
        r = _layer(polaris["rio"], spx)
        level = _layer(polaris["level"], spx)
        elevated = level == 1
        out.update(
            rio_min=float(np.nanmin(r)) if np.isfinite(r).any() else None,
            rio_max=float(np.nanmax(r)) if np.isfinite(r).any() else None,
            elevated_risk=bool(elevated.any()),
            elevated_distance=float(skm[elevated].sum()),
            special_consideration=bool((level == 2).any()),
        )
    return out
