"""Isochrones on one opened chart (OpenChart.arrival_field): the hours the ship takes to reach
every pixel from a start, on the hours per km its least-time route is searched on
(OpenChart.route(objective="time"), seaway.voyage.route): the same vessel, open-water speed,
speed in the ice (seaway.ice.speed), escort, draft and true-km scale. One search serves every
destination; a route with smooth=False to a pixel arrives at the field's value there."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..engine.api import prepare
from ..engine.snap import DEFAULT_SNAP_KM
from ..errors import ChartError, SeawayError, SnapError
from ..models import EdgeCost
from .ends import check_ends
from .pricing import price_chart
from .projected import end_pixel, pixel_latlon

if TYPE_CHECKING:
    import xarray as xr

    from ..vessel import Vessel
    from .chart import OpenChart


def time_cost(
    chart: OpenChart,
    *,
    vessel: Vessel | str | None = None,
    speed_kn: float | None = None,
    escort: bool = False,
    escort_speed_kn: float | None = None,
    stage_thickness: Any = None,
    draft_m: float | None = None,
    ukc_m: float | None = None,
    concentration_limit: bool = False,
) -> tuple[xr.DataArray, Any, dict[str, Any]]:
    """(hours per true km on the chart's grid, inf where the ship may not go; the Vessel; what
    check_ends needs to say why an end is closed) — the raster OpenChart.route(objective="time")
    searches, priced as route() prices it (seaway.voyage.pricing)."""
    if not chart.is_ice or chart.layers is None:
        raise ChartError(
            f"{chart.source} is a cost raster ({chart.description}): hours need an ice chart (a "
            "speed in its ice); use seaway.cost_field for its accumulated cost"
        )
    p = price_chart(
        chart,
        vessel=vessel,
        speed_kn=speed_kn,
        objective="time",
        escort=escort,
        escort_speed_kn=escort_speed_kn,
        stage_thickness=stage_thickness,
        draft_m=draft_m,
        ukc_m=ukc_m,
        concentration_limit=concentration_limit,
    )
    why = {"chart_cost": p.chart_cost, "reasons": p.reasons, "vessel": p.cls}
    return p.routed, p.ship, why


def arrival_field(
    chart: OpenChart,
    start: tuple[float, float],
    *,
    neighbourhood: int = 5,
    snap_km: float | None = None,
    **options: Any,
) -> xr.DataArray:
    """Hours from `start` to every pixel of `chart` (inf where the ship may not go or cannot
    reach): OpenChart.arrival_field. A start the ship may not use is refused as route() refuses
    it (why, and the nearest usable point), or with snap_km moved there when that is at most
    snap_km away (the field's attribute `start_used` says where)."""
    keys = (
        "vessel",
        "speed_kn",
        "escort",
        "escort_speed_kn",
        "stage_thickness",
        "draft_m",
        "ukc_m",
        "concentration_limit",
        "snap_km",
    )
    unknown = sorted(set(options) - set(keys[:-1]))
    if unknown:
        raise SeawayError(f"arrival_field takes none of {unknown}; it takes {', '.join(keys)}")
    hours, ship, why, prepared = _search(chart, neighbourhood, options)
    point = tuple(start)
    if chart.projection is not None:
        point = end_pixel(hours, chart.projection, point, "start")
    to_user = pixel_latlon(hours, chart.projection)
    try:  # the start as route() checks an end (both ends of check_ends: the start)
        (point, _), moved = check_ends(
            hours,
            chart.land,
            chart.layers,
            (point, point),
            vessel=why["vessel"],
            snap=snap_km is not None,
            snap_km=snap_km if snap_km is not None else DEFAULT_SNAP_KM,
            say=lambda note: None,
            neighbourhood=neighbourhood,
            reasons=why["reasons"],
            fast_ice=chart.options.fast_ice,
            chart_cost=why["chart_cost"],
            to_user=to_user,
            asked=(tuple(start), tuple(start)),
        )
    except SnapError as exc:  # say it once, for the start
        raise SnapError(exc.moves[:1], exc.limit, exc.unit, str(exc).split("; end ", 1)[0]) from None
    out = prepared.cost_field(point, model=EdgeCost("integral", unit="h"))
    out = out.copy(data=np.asarray(out.values, float))
    if chart.projection is not None:  # lat/lon of every pixel centre beside the grid's km
        y, x = np.meshgrid(np.asarray(out.y.values, float), np.asarray(out.x.values, float), indexing="ij")
        ll = chart.projection.to_latlon(y.ravel(), x.ravel())
        out = out.assign_coords(
            lat=(
                ("y", "x"),
                ll[:, 0].reshape(y.shape),
                {"standard_name": "latitude", "units": "degrees_north"},
            ),
            lon=(
                ("y", "x"),
                ll[:, 1].reshape(y.shape),
                {"standard_name": "longitude", "units": "degrees_east"},
            ),
        )
    out.name = "arrival_hours"
    out.attrs = {
        "long_name": "hours to reach from the start",
        "units": "h",
        "start": str(tuple(float(v) for v in start)),
        "ice_class": str(ship.ice_class),
        "speed_kn": float(ship.speed_kn),
        "chart": chart.source,
    }
    if moved:  # the start as routed, and how it moved
        used = to_user(point) if to_user is not None else tuple(point)
        out.attrs.update(start_used=str(tuple(float(v) for v in used)), notes=moved[0])
    return out


def _search(chart: OpenChart, neighbourhood: int, options: dict[str, Any]) -> tuple[Any, ...]:
    """(hours per km, ship, why, the prepared chart) for these options: the last ones kept on
    the chart, so fields from many starts (od_matrix) build the search once. Kept only when
    every option is a plain value (a Vessel or a thickness table builds it afresh)."""
    key = (neighbourhood, tuple(sorted(options.items())))
    plain = all(v is None or isinstance(v, (str, int, float, bool)) for _, v in key[1])
    memo = chart._searched
    if plain and memo and memo[0] == key:
        return memo[1]
    hours, ship, why = time_cost(chart, **options)
    built = (hours, ship, why, prepare(hours, land=chart.land, neighbourhood=neighbourhood))
    if plain:
        memo[:] = [key, built]
    return built
