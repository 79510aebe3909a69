"""Constraints of time routes: hard keep-away buffers on a forecast's grid and exclusion zones
open or closed in time windows (the engine's ZonedTravelTimeModel)."""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING, Protocol

import numpy as np

from .. import native as _core
from ..chart.raster import as_chart
from ..errors import ForecastError, SeawayError, SeawayTypeError
from .zones import KeepAway, Zone, constraint_factor, rasterise_zone

if TYPE_CHECKING:
    import xarray as xr


class TimedGrid(Protocol):
    """What zones with time windows read of a forecast (seaway.weather.ForecastGrid): its grid
    and its departure (None: no time axis)."""

    @property
    def template(self) -> xr.DataArray: ...
    @property
    def departure(self) -> np.datetime64 | None: ...


def hard_only(km, keep_away, land) -> np.ndarray:
    """The land mask of a time route's chart (`km`: its DataArray of ones) widened by hard
    keep-away buffers; soft penalties are refused (a time model has no static cost to scale)."""
    keep_away = [keep_away] if isinstance(keep_away, KeepAway) else list(keep_away)
    for k in keep_away:
        if isinstance(k, KeepAway) and k.soft_km:
            raise SeawayError(
                "time routes take hard keep-away buffers only (KeepAway(km=...)): a "
                "soft penalty scales a static cost, and a time route's cost is hours"
            )
        if isinstance(k, KeepAway) and k.ice is not None and not hasattr(k.ice, "shape"):
            raise SeawayError(
                "on a time route KeepAway.ice must be a boolean mask of the forecast's "
                "grid (there is no static cost to threshold)"
            )
    chart = as_chart(km, land=land)
    return np.isinf(constraint_factor(chart, keep_away)) | np.asarray(land, bool)


def _hours(t, forecast) -> float:
    if isinstance(t, (int, float, np.integer, np.floating)) and not isinstance(t, bool):
        return float(t) - getattr(forecast, "shift_h", 0.0)
    if forecast.departure is None:
        raise ForecastError("this forecast has no time axis: give zone windows in hours after departure")
    try:
        return float((np.datetime64(t) - forecast.departure) / np.timedelta64(1, "h"))
    except (TypeError, ValueError):
        raise SeawayError(
            f"a zone window time must be a datetime or hours after departure, got {t!r}"
        ) from None


def timed_zone_engine(
    forecast: TimedGrid, base: _core.TravelTimeModel, zones: Iterable[Zone]
) -> _core.ZonedTravelTimeModel:
    """The engine's TravelTime model with `zones` (at most 8 exclusions, each closed always or in
    its `active` window) rasterised on the forecast's grid (a seaway.weather.ForecastGrid)."""
    zones = list(zones)
    if len(zones) > 8:
        raise SeawayError(
            f"a time route takes at most 8 zones, got {len(zones)}; merge polygons "
            "with the same window into one Zone"
        )
    chart = as_chart(forecast.template)
    mask = np.zeros(chart.shape, np.uint8)
    closes, opens = [], []
    for i, z in enumerate(zones):
        if not isinstance(z, Zone):
            raise SeawayTypeError(f"zones takes Zone objects, got {type(z).__name__}")
        if math.isfinite(z.penalty):
            raise SeawayError(
                f"zone {z.name!r} is a penalty zone; a time route's cost is hours, so it "
                "takes exclusion zones (penalty=inf), optionally with a time window"
            )
        mask[rasterise_zone(z, chart)] |= np.uint8(1 << i)
        a, b = (-math.inf, math.inf) if z.active is None else (_hours(t, forecast) for t in z.active)
        if not a < b:
            raise SeawayError(
                f"zone {z.name!r}: its window must close before it opens again, got {z.active!r}"
            )
        closes.append(a)
        opens.append(b)
    from scipy.ndimage import maximum_filter

    # Pixels within 7 (the widest stencil's reach) of a zone: only their steps are checked.
    near = maximum_filter(mask > 0, size=15, mode=("nearest", "wrap" if chart.grid.wrap else "nearest"))
    return _core.ZonedTravelTimeModel(base, mask, near.astype(np.uint8), closes, opens)
