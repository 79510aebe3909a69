"""Andreeva's time-safety trade-off as routes (Andreeva 2021): sweep the safety threshold on F, find
the quickest route for each, keep the Pareto-optimal ones."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..engine.api import route
from ..errors import NoRouteError
from ..ice.andreeva import pareto_front, time_cost


@dataclass
class ParetoRoute:
    """One route of the sweep: the F threshold it was found with, its time (route cost: hours
    on geographic charts), its safety (lowest F along its pixels) and the Route itself."""

    threshold: float
    time: float
    safety: float
    route: object


def pareto_routes(F, start, end, *, v0_kn, thresholds=None, **route_kwargs) -> list:
    """Sweep the F threshold: for each t, forbid pixels with F < t, find the minimum-time route
    (cost = time_cost), measure its safety; return the non-dominated ParetoRoutes, fastest
    first. thresholds default to the distinct F values of the chart (at most 20 quantiles).
    route_kwargs go to seaway.route (lat/lon, land, neighbourhood, ...)."""
    values = np.asarray(getattr(F, "values", F), dtype=float)
    if thresholds is None:
        positive = np.unique(values[np.isfinite(values) & (values > 0)])
        if positive.size > 20:
            positive = np.unique(np.quantile(positive, np.linspace(0, 1, 20), method="lower"))
        thresholds = positive
    found = []
    for t in sorted(float(x) for x in thresholds):
        allowed = np.where(values >= t, values, 0.0)
        cost = time_cost(F.copy(data=allowed) if hasattr(F, "dims") else allowed, v0_kn)
        try:
            r = route(cost, start, end, **route_kwargs)
        except (NoRouteError, ValueError):
            if not found:
                raise
            break  # the threshold closed the way or an end pixel; higher ones forbid more
        safety = float(values[r.pixels[:, 0], r.pixels[:, 1]].min())
        found.append(ParetoRoute(t, float(r.cost), safety, r))
    keep = pareto_front([p.time for p in found], [p.safety for p in found])
    unique, seen = [], set()
    for i in keep:
        key = (round(found[i].time, 9), found[i].safety)
        if key not in seen:
            seen.add(key)
            unique.append(found[i])
    return unique
