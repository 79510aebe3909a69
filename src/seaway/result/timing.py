"""Times of a route through ice: a speed field on the chart's grid (seaway.ice.speed) integrated
along the legs. Each leg is sampled as the ice summaries sample it (every half pixel along its
own path, seaway.result.environment.weighted_samples); a sample's time is its length over the
speed at its pixel. Where the model gives no speed (0: e.g. Andreeva's F = 0 in ice at least as
thick as the class passes), the time is infinite and the length is reported as stopped."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..base.units import KM_PER_NM
from ..errors import ChartError
from .environment import route_samples


@dataclass(frozen=True)
class SpeedField:
    """knots: (rows, cols) speed on the route's chart, 0 where the model gives none; model: its
    name and terms, as the outputs print it; v0_kn: the open-water speed it was made for;
    escorted: (rows, cols) True where the speed is an icebreaker escort's (None: nowhere)."""

    knots: np.ndarray
    model: str
    v0_kn: float
    escorted: np.ndarray | None = None

    @classmethod
    def on(cls, chart, knots, model=None, escorted=None) -> SpeedField:
        """The speed `knots` on `chart`'s grid: a DataArray from seaway.ice.speed.ice_speed
        (its attributes give the model and the open-water speed) or an array with `model`;
        `escorted`: where that speed is under escort."""
        arr, template = knots, chart.template
        if template is not None and hasattr(arr, "dims") and set(arr.dims) == set(template.dims):
            arr = arr.transpose(*template.dims)
        values = np.asarray(getattr(arr, "values", arr), float)
        if values.shape != chart.shape:
            raise ChartError(f"the speed has shape {values.shape}, the chart {chart.shape}")
        attrs = getattr(knots, "attrs", {})
        v0 = float(attrs.get("v0_kn", np.nanmax(values)))
        if escorted is not None:
            escorted = np.asarray(getattr(escorted, "values", escorted), bool)
            if escorted.shape != chart.shape:
                raise ChartError(f"the escort mask has shape {escorted.shape}, the chart {chart.shape}")
        return cls(values, model or str(attrs.get("model", "speed field")), v0, escorted)


def step_times(route):
    """(hours, stopped km, escorted km) of each step between the route's vertices under
    route.ice_speed: the speed at each sample's pixel; stopped where it is 0 (hours inf)."""
    cached = route.__dict__.get("_step_times")
    if cached is not None:
        return cached
    px, km, step = route_samples(route)
    knots = route.ice_speed.knots
    rc = (np.clip(px[:, 0], 0, knots.shape[0] - 1), px[:, 1] % knots.shape[1])
    v = knots[rc]
    escort = route.ice_speed.escorted
    under = escort[rc] if escort is not None else np.zeros(v.shape, bool)
    with np.errstate(divide="ignore"):
        hours = np.where(v > 0, km / (np.where(v > 0, v, 1.0) * KM_PER_NM), np.inf)
    n = max(len(route.vertices) - 1, 0)
    out = (
        np.bincount(step, weights=hours, minlength=n)[:n],
        np.bincount(step, weights=np.where(v > 0, 0.0, km), minlength=n)[:n],
        np.bincount(step, weights=np.where(under, km, 0.0), minlength=n)[:n],
    )
    route.__dict__["_step_times"] = out
    return out
