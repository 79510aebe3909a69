"""Paper 004's fallback when every route crosses danger: the route that spends the least time in
the forecast's danger zones (wind above Vessel.danger_wind_ms, waves above
Vessel.danger_wave_m), then the least total time, flagged and with the stretches in danger
listed. Called by seaway.weather.route_time (cpp/seaway/danger_time.hpp searches)."""

from __future__ import annotations

import numpy as np

from . import _core
from ._interrupt import interruptible


def danger_stretches(route, danger_h, start_h) -> list[dict]:
    """Consecutive steps in danger merged: where (from, to as lat/lon), when (hours after
    departure) and for how long (hours)."""
    coords = route.coords
    elapsed = np.concatenate([[0.0], np.cumsum(route.step_costs)]) + start_h
    out, i, n = [], 0, len(danger_h)
    while i < n:
        if danger_h[i] <= 0:
            i += 1
            continue
        j = i
        while j + 1 < n and danger_h[j + 1] > 0:
            j += 1
        out.append({"from": tuple(map(float, coords[i])), "to": tuple(map(float, coords[j + 1])),
                    "start_h": float(elapsed[i]), "hours": float(np.sum(danger_h[i:j + 1])),
                    "steps": (i, j + 1)})
        i = j + 1
    return out


def least_danger_route(fc, s, e, weight, vessel, best_kn, vessel_dict, method):
    """The lexicographic (hours in danger, hours) route between located pixels, or None."""
    cols = fc.chart.shape[1]
    wind = np.inf if vessel.danger_wind_ms is None else float(vessel.danger_wind_ms)
    wave = np.inf if vessel.danger_wave_m is None else float(vessel.danger_wave_m)
    (hours, path, stats, cumulative), danger_h = interruptible(lambda cancel: _core.route_least_danger(
        fc.prepared._router, s[0] * cols + s[1], e[0] * cols + e[1], weight, fc.arrays, fc.frames,
        fc.first_h, fc.step_h, vessel_dict, best_kn, wind, wave, cancel))
    if not np.isfinite(hours):
        return None
    danger_h = np.asarray(danger_h, dtype=float)
    stats = dict(stats, hours=hours, through_danger=True, danger_h=float(danger_h.sum()))
    r = fc.route(path, hours, cumulative, stats, method, "time", speed_kn=vessel.speed_kn)
    r.stats["danger_legs"] = danger_stretches(r, danger_h, 0.0)
    r.stats["danger_step_h"] = danger_h
    r.name = "seaway route (through danger: no route avoids the danger zones)"
    return r
