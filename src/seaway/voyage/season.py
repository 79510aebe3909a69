"""A season of ice charts opened for routing (seaway.open_season): dated SIGRID-3 files
rasterised onto one grid, or one NetCDF with a time axis; OpenSeason.route gives the quickest
route through it (waiting allowed) as ``seaway season`` finds it."""

from __future__ import annotations

import dataclasses
import os
import warnings
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from ..base.memory import SEASON_CHART
from ..base.validate import one_line
from ..engine.api import prepare
from ..engine.snap import DEFAULT_SNAP_KM
from ..errors import ChartError, NoRouteError, SeawayTypeError
from ..ice.grids import latlon_grid
from ..ice.routegrid import route_grid
from ..ice.seasongrid import SeasonGrid, read_season
from ..icenav.seasonwhy import closed_reason, explain_season_no_route, usable
from ..models import IceSeasonTime
from ..result.schedule import schedule
from ..smoothtime import on_clock
from ..vessel import Vessel
from .departures import DepartureChoice, best_departure
from .ends import check_ends
from .route import searching
from .ship import as_vessel, vessel_notes
from .timing import CHART_AGE_DAYS
from .vectorchart import in_degrees

if TYPE_CHECKING:
    from ..result.route import Route

Charts = str | os.PathLike[str] | Mapping[Any, str] | Sequence[tuple[Any, str]]


@dataclasses.dataclass(eq=False)
class OpenSeason:
    """A season of ice charts opened for routing: `grid` (seaway.ice.SeasonGrid: the charts,
    their times, the land), `notes` (what opening it decided: the grid, charts that leave the
    grid uncovered) and `route()`."""

    grid: SeasonGrid
    source: str
    notes: list[str] = dataclasses.field(default_factory=list)

    def route(
        self,
        start: tuple[float, float],
        end: tuple[float, float],
        *,
        vessel: Vessel | str = "Arc7",
        speed_kn: float | None = None,
        depart: Any = None,
        speed_table: Mapping[float, Any] | None = None,
        fast_ice: str | float | None = None,
        concentration_limit: bool = True,
        snap_km: float | None = None,
        neighbourhood: int = 5,
        method: str = "astar",
        smooth: bool = True,
        name: str = "seaway season route",
        progress: Callable[[str], None] | None = None,
    ) -> Route:
        """The earliest-arriving route from `start` to `end` (lat, lon) through the season for
        `vessel` (a seaway.vessel.Vessel, e.g. from a vessel file: its class, service speed and
        ice curve; or an ice class at 12 kn) at `speed_kn` in open water (default the vessel's),
        leaving at `depart` (default the first chart's date): the ship's ice curve, else Andreeva
        2021's speeds, or `speed_table` {WMO stage: knots}; waiting is allowed. fast_ice: the stage of fast ice of unknown stage (None: the season's rule, else
        "nearby"; seaway.ice.seasonfast). snap_km: an end no chart opens moves at most that far (None: refused, naming
        why). smooth: straight legs sailed through the charts, never later, never through closed
        ice, the waits kept (seaway.smoothtime); False: the engine's steps. Route.notes record the
        assumptions; NoRouteError names what closes the way."""
        say = progress or (lambda message: None)
        ship, model, speed, limit = self._model(
            vessel, speed_kn, depart, speed_table, fast_ice, concentration_limit
        )
        said_ship = vessel_notes(ship)
        assumed = [f"assumed: {said}" for said in model.assumptions]
        snap = snap_km is not None
        # Only an end no chart opens moves (an end closed at departure may open later: the ship waits).
        (a, b), moved = check_ends(
            self.grid.template.copy(data=np.where(usable(model), 1.0, np.inf)),
            self.grid.dry,
            None,
            (start, end),
            snap=snap,
            snap_km=snap_km if snap else DEFAULT_SNAP_KM,
            say=lambda note: None,
            neighbourhood=neighbourhood,
            why=closed_reason(model),
        )
        say(
            f"routing {model.ice_class} at {ship.speed_kn:g} kn from {model.departure} "
            f"({neighbourhood}x{neighbourhood} stencil, waiting allowed)"
        )
        chart = prepare(self.grid, neighbourhood=neighbourhood)
        try:
            with searching(progress, int(np.prod(self.grid.shape))):
                r = on_clock(chart.route(a, b, model=model, method=method), smooth)
        except NoRouteError:
            say("no route: reading the season's ice for why")
            err = explain_season_no_route(
                self.grid, model, a, b, neighbourhood=neighbourhood, speed=speed, asked=(start, end), **limit
            )
            err.notes = tuple(assumed) + tuple(moved)
            raise err from None
        ages = chart_ages(self.grid.times, r)
        return dataclasses.replace(
            r,
            name=name,
            notes=r.notes + tuple(self.notes) + tuple(said_ship) + tuple(moved) + tuple(ages),
            requested=(tuple(start), tuple(end)),
        )

    def best_departure(
        self, start, end, window, *, step_h=24.0, arrive_by=None, **options
    ) -> DepartureChoice:
        """The departure in `window` (first, last) that arrives first (or by `arrive_by` with the
        least fuel), tried every step_h hours: seaway.voyage.departures; options as route()."""
        ship = as_vessel(options.get("vessel", "Arc7"), options.get("speed_kn"))
        rate = None
        if ship is not None and ship.fuel_speeds_kn:
            rate = float(np.interp(ship.speed_kn, ship.fuel_speeds_kn, ship.fuel_rates_t_per_h))
        return best_departure(
            lambda depart, **kw: self.route(start, end, depart=depart, **kw),
            window,
            step_h=step_h,
            arrive_by=arrive_by,
            fuel_rate_t_per_h=rate,
            **options,
        )

    def arrival_field(self, start: tuple[float, float], *, neighbourhood: int = 5, **options: Any) -> Any:
        """Hours after departure at which the vessel can first reach each pixel from `start`
        (lat, lon), waiting allowed, as route() prices the voyage (inf where never): the
        voyage's isochrones, a DataArray on the season's grid in hours. options: route()'s
        vessel, speed_kn, depart, speed_table, fast_ice, concentration_limit. A route to a
        pixel with smooth=False arrives at its value; one search serves every destination."""
        keys = ("vessel", "speed_kn", "depart", "speed_table", "fast_ice", "concentration_limit")
        ship, model, _, _ = self._model(*(options.pop(k, d) for k, d in zip(keys, _MODEL_DEFAULTS)))
        if options:
            raise SeawayTypeError(
                f"arrival_field takes none of {sorted(options)}; it takes {', '.join(keys)}"
            )
        out = prepare(self.grid, neighbourhood=neighbourhood).cost_field(start, model=model)
        out.name = "arrival_hours"
        out.attrs.update(
            long_name="hours to reach after departure (waiting allowed)",
            units="h",
            departure=str(model.departure),
            ice_class=model.ice_class,
            speed_kn=ship.speed_kn,
        )
        return out

    def _model(self, vessel, speed_kn, depart, speed_table, fast_ice, concentration_limit):
        """The vessel and the season's time model for it: (ship, model, speed, limit)."""
        ship = as_vessel(vessel, speed_kn)
        assert ship is not None
        curve = ship.ice_curve if speed_table is None else None
        speed = speed_table if speed_table is not None else (curve if curve is not None else "andreeva")
        limit = {"concentration_limit": concentration_limit and curve is None}
        model = IceSeasonTime(
            self.grid,
            ship.ice_class or "Arc7",
            ship.speed_kn,
            departure=depart,
            speed=speed,
            fast_ice=fast_ice,
            **limit,
        )
        return ship, model, speed, limit


#: route()'s defaults for the vessel and its model (arrival_field takes the same).
_MODEL_DEFAULTS = ("Arc7", None, None, None, None, True)


def chart_ages(times, r) -> list[str]:
    """The charts used against the legs that use them: a warning when a leg runs more than
    CHART_AGE_DAYS after the date of the chart it crosses (the charts are too sparse)."""
    timed = schedule(r)
    if timed is None or timed.departure is None or times.size == 0:
        return []
    at = np.array([timed.eta(i) for i in range(len(r.coords))], dtype="datetime64[s]")
    k = np.clip(np.searchsorted(times.astype("datetime64[s]"), at, side="right") - 1, 0, times.size - 1)
    age = (at - times.astype("datetime64[s]")[k]) / np.timedelta64(1, "D")
    worst = int(np.argmax(age))
    if age[worst] <= CHART_AGE_DAYS:
        return []
    date = str(times[k[worst]])[:16]
    return [
        f"warning: the ice chart of {date} is {age[worst]:.1f} days older than the part of the voyage that "
        f"crosses it (at {str(at[worst])[:16]}; more than {CHART_AGE_DAYS:g}): add newer charts"
    ]


def open_season(
    charts: Charts,
    *,
    ends: tuple[tuple[float, float], tuple[float, float]] | None = None,
    grid: tuple[float, float, float, float, float] | None = None,
    fast_ice: str | float | None = None,
) -> OpenSeason:
    """Open a season of ice charts: one NetCDF file with a time axis (CT or
    sea_ice_area_fraction, and SA or thickness), or SIGRID-3 files with the date each is valid
    from ({date: path} or [(date, path), ...], in date order). SIGRID-3 files are rasterised onto
    `grid` (south, north, west, east, resolution in degrees), by default the box around the
    voyage's `ends` (as ``seaway route`` chooses it), else the charts' extent at 0.05 deg."""
    if isinstance(charts, (str, os.PathLike)):
        path = os.fspath(charts)
        if not os.path.exists(path):
            raise ChartError(f"{path}: no such file")
        return OpenSeason(SeasonGrid(path), path)
    items = list(charts.items()) if isinstance(charts, Mapping) else [tuple(c) for c in charts]
    for _, path in items:
        if not os.path.exists(path):
            raise ChartError(f"{path}: no such file")
    notes: list[str] = []
    per_pixel = SEASON_CHART * len(items)  # bytes: the charts read and routed (seaway.base.memory)
    what = f"a season of {len(items)} charts on a grid"
    if grid is not None:
        target = latlon_grid(*grid, bytes_per_pixel=per_pixel, what=what)
    else:  # as `seaway route` does: the box around the voyage
        bounds = _bounds(items)
        if ends is None:
            if bounds is None:
                raise ChartError(
                    "the charts are not in degrees: give the grid (south, north, west, east, res)"
                )
            west, south, east, north = bounds
            target = latlon_grid(south, north, west, east, 0.05, bytes_per_pixel=per_pixel, what=what)
            notes.append(
                f"grid: the charts' extent at 0.05 deg ({south:g} to {north:g} N, {west:g} to {east:g} E)"
            )
        else:
            target, note = route_grid(*ends, chart_bounds=bounds, bytes_per_pixel=per_pixel, what=what)
            notes.append(note)
    ds = read_season(items, target, fast_ice=fast_ice)
    notes += _check_cover(ds, items, ends, target)
    return OpenSeason(SeasonGrid(ds), ", ".join(str(p) for _, p in items), notes)


def _bounds(charts):
    """The union of the charts' extents in degrees, or None when one is not in degrees."""
    import pyogrio

    boxes = []
    for _, path in charts:
        try:
            with warnings.catch_warnings():  # GDAL's notes on a damaged file: the read names it
                warnings.simplefilter("ignore")
                info = pyogrio.read_info(path)
        except Exception as exc:  # pyogrio's DataSourceError, ...
            raise ChartError(f"{path}: cannot read it as a SIGRID-3 vector file ({one_line(exc)})") from None
        if not in_degrees(info):
            return None
        boxes.append(info["total_bounds"])
    b = np.array(boxes, float)
    return b[:, 0].min(), b[:, 1].min(), b[:, 2].max(), b[:, 3].max()


def _check_cover(ds, charts, ends, target) -> list[str]:
    """Say which chart does not cover an end (ChartError), or most of the grid (a note): off a
    chart's polygons the ice is unknown, so impassable; that is the chart's extent, not the ice."""
    off = np.asarray(ds["off_chart"].values)
    lat, lon = np.asarray(target.y, float), np.asarray(target.x, float)
    notes = []
    for k, (date, path) in enumerate(charts):
        for name, p in zip(("start", "end"), ends or ()):
            r = int(np.argmin(np.abs(lat - p[0])))
            c = int(np.argmin(np.abs((lon - p[1] + 180) % 360 - 180)))
            if off[k, r, c]:
                raise ChartError(
                    f"the chart of {date} ({path}) does not cover the {name} {p[0]:g},{p[1]:g}: no polygon "
                    "of it lies there, so its ice is unknown; give a chart that covers the voyage, or set "
                    "the grid with --grid"
                )
        share = float(off[k].mean())
        if share > 0.05:
            notes.append(
                f"the chart of {date} ({path}) leaves {100 * share:.0f} % of the grid uncovered: "
                "off its polygons the ice is unknown and impassable"
            )
    return notes
