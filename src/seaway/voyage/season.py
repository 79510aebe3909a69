"""A season of ice charts opened for routing (seaway.open_season): dated SIGRID-3 files
rasterised onto one grid, or one NetCDF with a time axis; OpenSeason.route gives the quickest
route through it (waiting allowed) as ``seaway season`` finds it."""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from ..base.memory import SEASON_CHART
from ..engine.api import prepare
from ..errors import ChartError, NoRouteError, SeawayError, SeawayTypeError
from ..ice.grids import latlon_grid
from ..ice.routegrid import route_grid
from ..ice.seasongrid import SeasonGrid, read_season
from ..models import IceSeasonTime
from ..vessel import Vessel
from .departures import DepartureChoice, best_departure
from .route import searching
from .seasoncover import charts_bounds, check_cover
from .seasonmany import season_routes
from .seasonproj import SeasonPlane
from .seasonroutes import ends_used, explain, finish, plan
from .ship import as_vessel

if TYPE_CHECKING:
    from ..result.route import Route

Charts = str | os.PathLike[str] | Mapping[Any, str] | Sequence[tuple[Any, str]]


@dataclasses.dataclass(eq=False)
class OpenSeason:
    """A season of ice charts opened for routing: `grid` (seaway.ice.SeasonGrid: the charts,
    their times, the land), `notes` (what opening it decided: the grid, charts that leave the
    grid uncovered, a projected grid) and `route()`. `plane`: on a projected grid with a CF grid
    mapping (ROMS, NSIDC's polar stereographic), its projection (seaway.voyage.seasonproj,
    found when None): ends are then given in lat/lon and routes come back in lat/lon."""

    grid: SeasonGrid
    source: str
    notes: list[str] = dataclasses.field(default_factory=list)
    plane: SeasonPlane | None = dataclasses.field(default=None, repr=False)
    _prepared: dict = dataclasses.field(default_factory=dict, repr=False)

    def __post_init__(self) -> None:
        if self.plane is None:
            self.plane = SeasonPlane.of(self.grid)
            if self.plane is not None:
                self.notes.append(self.plane.note)
                if self.plane.latlon:
                    self.notes.append(self.plane.latlon)

    @property
    def projection(self):
        """The projection of a projected season (seaway.voyage.projected.Projection), or None."""
        return None if self.plane is None else self.plane.projection

    def pixel(self, point: tuple[float, float], name: str = "point") -> tuple[int, int]:
        """(row, col) of the pixel that holds `point`: (lat, lon) on a projected season, else the
        point as the engine takes it ((row, col) on a planar grid without a projection)."""
        if self.plane is None:
            return tuple(point)  # type: ignore[return-value]
        return self.plane.pixel(point, name)

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
        p = plan(self, vessel, speed_kn, depart, speed_table, fast_ice, concentration_limit)
        (a, b), moved, asked = ends_used(self, p, start, end, snap_km, neighbourhood)
        say(
            f"routing {p.model.ice_class} at {p.ship.speed_kn:g} kn from {p.model.departure} "
            f"({neighbourhood}x{neighbourhood} stencil, waiting allowed)"
        )
        try:
            with searching(progress, int(np.prod(self.grid.shape))):
                found = self.prepared(neighbourhood).route(a, b, model=p.model, method=method)
        except NoRouteError:
            say("no route: reading the season's ice for why")
            raise explain(self, p, a, b, neighbourhood, asked, moved) from None
        return finish(self, p, found, asked, moved, smooth, name)

    def routes(
        self, start: tuple[float, float], ends: Sequence[tuple[float, float]], **options: Any
    ) -> list[Route | SeawayError]:
        """The routes from `start` to each of `ends` (options as route()'s, except method and
        progress), from one search per start pixel used: each is what
        ``route(start, end, method="dijkstra", **options)`` gives, or the SeawayError it raises
        (an end off the chart, too far from usable water, no route) in its place."""
        return season_routes(self, start, ends, **options)

    def prepared(self, neighbourhood: int = 5):
        """The season's grid prepared for routing (seaway.prepare), kept for the next route."""
        if neighbourhood not in self._prepared:
            self._prepared[neighbourhood] = prepare(self.grid, neighbourhood=neighbourhood)
        return self._prepared[neighbourhood]

    def __getstate__(self) -> dict:
        return dict(self.__dict__, _prepared={})  # the engine's charts are rebuilt where unpickled

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
        (lat, lon; on a planar grid without a projection (row, col)), waiting allowed, as route() prices the voyage (inf where never): the
        voyage's isochrones, a DataArray on the season's grid in hours. options: route()'s
        vessel, speed_kn, depart, speed_table, fast_ice, concentration_limit. A route to a
        pixel with smooth=False arrives at its value; one search serves every destination."""
        keys = ("vessel", "speed_kn", "depart", "speed_table", "fast_ice", "concentration_limit")
        ship, model, _, _ = self._model(*(options.pop(k, d) for k, d in zip(keys, _MODEL_DEFAULTS)))
        if options:
            raise SeawayTypeError(
                f"arrival_field takes none of {sorted(options)}; it takes {', '.join(keys)}"
            )
        out = self.prepared(neighbourhood).cost_field(self.pixel(start, "start"), model=model)
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
        bounds = charts_bounds(items)
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
    notes += check_cover(ds, items, ends, target)
    return OpenSeason(SeasonGrid(ds), ", ".join(str(p) for _, p in items), notes)
