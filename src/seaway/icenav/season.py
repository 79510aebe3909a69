"""A season of ice charts: routes through ice that changes during the voyage.

A season is an ice chart Dataset (see seaway.ice) with a `time` dimension: CT (tenths) with SA
(WMO stage) and/or `thickness` (m), and `land`. Build one from SIGRID-3 files with their dates
(`read_season`) or open a NetCDF with a time dimension (`as_season` also takes CF
`sea_ice_area_fraction` and `sea_ice_thickness`, e.g. an ocean model's aice and hice): both
live in seaway.ice.seasongrid (seaway.ice). `seaway.prepare(SeasonGrid(season))` is the
chart to route on and `seaway.models.IceSeasonTime` the cost model;
`route_season` and `arrival_field` wrap the two.

How a step reads the charts: chart k is valid from its time until the next chart's time (the
last one for ever after, with a warning past its usual validity) — piecewise constant, as ice
services mean "valid at". A step started at time t crosses the ice of the chart valid at t, at
the class's speed there; its duration is the exact time of the straight step through that
chart (the line integral of 1 / speed over the pixels it crosses), and it is closed if its
segment touches a pixel closed in that chart.

Waiting is allowed, anywhere the ship has reached (including its start: a later departure),
and it is not optional: without it the graph is not FIFO — leaving just before a chart that
clears the ice would arrive later than leaving with it — and no label-setting search is exact
(cpp/seaway/ice_time.hpp). Routes report every wait (route.stats.voyage.waits); a ship waits where
it is, also in ice its class may not enter meanwhile: the charts are not drift forecasts.

Speed of a class in a chart's ice (knots), `speed=`:
* "andreeva" (default): Andreeva 2021 through seaway.ice.andreeva, V = F * V0, F = f2 * other_factor
  with f2 = 1 - h / h_pass (h_pass the class's Table-1 thickness unless given); h is the
  `thickness` layer if the season has one, else the governing stage's typical thickness (the
  middle of its WMO range by default; `stage_thickness="upper"` the conservative end, "lower",
  or a table {stage: m});
  `other_factor` is f1 * f3 (1 by default; e.g. andreeva.f1(draft, depth) for depth).
* a table {WMO stage: knots} or {stage: {max CT tenths: knots, ...}} read on the governing stage
  (55 ice free, 99 unknown) and total concentration; a stage the table lacks raises.
* "class": the class's own model (seaway.ice.speed): Andreeva 2021 as above for Register classes,
  the IMO POLARIS speed limits for Polar and Finnish-Swedish classes (V0 in normal operation,
  the circular's limit under elevated risk, closed under special consideration: POLARIS's
  levels are then the class's limits, the concentration limit is not applied).
Either way, unknown ice (NaN CT, stage 99, old ice without a thickness), land and pixels off the
chart are closed (fast ice of unknown stage takes the `fast_ice` rule's stage chart by chart, open
and bergy water are ice free: seaway.ice.seasonfast, as seaway.ice.forms for one chart), and with
`concentration_limit=True` (default) so is ice above the class's independent-navigation
concentration (Grinyak et al. 2022 Table 1: Arc4-Arc6 6/10, Arc7-Arc8 8/10; fast ice is 10/10).
"""

from __future__ import annotations

from ..engine.api import prepare
from ..errors import NoRouteError
from ..ice.seasongrid import SeasonGrid
from ..ice.seasonspeed import andreeva_speed_kn, class_speed_kn, table_speed_kn
from ..models import IceSeasonTime
from ..smoothtime import on_clock
from . import seasonwhy

__all__ = ["route_season", "arrival_field"]
__all__ += ["andreeva_speed_kn", "table_speed_kn", "class_speed_kn"]  # of seaway.ice.seasonspeed


def route_season(
    season,
    start,
    end,
    *,
    ice_class="Arc7",
    v0_kn=12.0,
    departure=None,
    speed="andreeva",
    land=None,
    neighbourhood=5,
    method="astar",
    snap_km=None,
    smooth=True,
    **speed_options,
):
    """The earliest-arriving route from `start` to `end` through a season of ice charts.

    season: a season Dataset or NetCDF path (see the module docstring and as_season), or a
        SeasonGrid. ice_class: any class of seaway.ice.classes; v0_kn: its open-water speed (kn).
    departure: a date within the season (default its first chart's time).
    speed: "andreeva" (Andreeva 2021) or a speed table; speed_options go to andreeva_speed_kn
        (h_pass_m, stage_thickness, other_factor, concentration_limit) or table_speed_kn, and
        fast_ice (the stage of fast ice of unknown stage, chart by chart: seaway.ice.seasonfast).
    snap_km: None (default): an end no chart opens raises ValueError; a distance: such an end
        moves at most that far (seaway.icenav.seasonwhy.snap_season_ends; the route records it).
    Waiting is allowed (the module docstring says why). Returns a Route whose cost is the
    passage time in hours, waiting included; see seaway.models.IceSeasonTime for its stats.
    smooth: the route's steps replaced by straight legs sailed through the charts, never later
    and never through closed ice, its waits kept (seaway.smoothtime; stats.smoothing); False:
    the engine's steps.
    No route raises the NoRouteError of seaway.icenav.seasonwhy.explain_season_no_route."""
    grid = season if isinstance(season, SeasonGrid) else SeasonGrid(season, land)
    model = IceSeasonTime(grid, ice_class, v0_kn, departure=departure, speed=speed, **speed_options)
    ends = (
        None
        if snap_km is None
        else seasonwhy.snap_season_ends(model, start, end, neighbourhood=neighbourhood, max_km=snap_km)
    )
    a, b = (start, end) if ends is None else ends.ends
    try:
        r = prepare(grid, neighbourhood=neighbourhood).route(a, b, model=model, method=method)
    except NoRouteError:
        raise seasonwhy.explain_season_no_route(
            grid, model, a, b, neighbourhood=neighbourhood, speed=speed, asked=(start, end), **speed_options
        ) from None
    r = on_clock(r, smooth)
    return r if ends is None else ends.record(r)


def arrival_field(
    season,
    start,
    *,
    ice_class="Arc7",
    v0_kn=12.0,
    departure=None,
    speed="andreeva",
    land=None,
    neighbourhood=5,
    **speed_options,
):
    """Earliest arrival at every pixel from `start` (hours after departure; inf where never),
    a DataArray on the season's grid: isochrones of the voyage."""
    grid = season if isinstance(season, SeasonGrid) else SeasonGrid(season, land)
    model = IceSeasonTime(grid, ice_class, v0_kn, departure=departure, speed=speed, **speed_options)
    out = prepare(grid, neighbourhood=neighbourhood).cost_field(start, model=model)
    out.name = "arrival_hours"
    out.attrs.update(
        long_name="earliest arrival after departure (waiting allowed)",
        departure=str(model.departure),
        ice_class=model.ice_class,
    )
    return out
