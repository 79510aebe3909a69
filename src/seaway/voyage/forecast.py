"""A forecast opened for routing (seaway.open_forecast): one or more forecast files (CF NetCDF,
CDO output from GRIB, GRIB) merged into one Dataset of roles; OpenForecast.route gives the route
``seaway route --forecast`` finds: on the forecast's own grid (land where every field is NaN and
the package's coastline), or through an ice chart or season (ice and weather in one voyage).

Objectives: the least time (Olovyannikov 2025; with danger zones the least time in danger when no
safe route exists, Sotnikova 2009), the least fuel (Sotnikova 2009; with arrive_by the least fuel
that arrives in time), or the least wave danger (Grinyak et al. 2018). A projected forecast
(polar stereographic ROMS, NEMO, WAM) is resampled onto a lat/lon grid: the ice chart's, else
the box around the ends at the forecast's resolution, or `grid` (seaway.voyage.forecastgrid)."""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from ..errors import ForecastError
from ..vessel import Vessel
from ..weather import ForecastGrid, read_forecasts
from .chart import OpenChart
from .departures import DepartureChoice, best_departure
from .forecastgrid import onto_route_grid
from .forecastice import forecast_ice, ice_season, route_ice_weather_voyage
from .forecastroutes import OBJECTIVES, route_on_forecast
from .route import searching
from .season import OpenSeason
from .ship import as_vessel, vessel_notes

if TYPE_CHECKING:
    import xarray as xr

    from ..ice.seasongrid import SeasonGrid
    from ..result.route import Route

Say = Callable[[str], None]


@dataclasses.dataclass(eq=False)
class OpenForecast:
    """A forecast opened for routing: `data` (the fields by role, seaway.weather.roles), `source`
    (its files), `crs` (the projection given for a projected forecast without a grid mapping),
    `notes` (which variable plays each role, how the files were merged) and `route()`."""

    data: xr.Dataset
    source: str
    crs: str | None = None
    notes: list[str] = dataclasses.field(default_factory=list)

    def route(
        self,
        start: tuple[float, float],
        end: tuple[float, float],
        *,
        vessel: Vessel | str | None = None,
        ice: OpenChart | OpenSeason | SeasonGrid | None = None,
        ice_class: str | None = None,
        depart: str | np.datetime64 | None = None,
        objective: str = "time",
        arrive_by: str | np.datetime64 | None = None,
        persist: bool = False,
        grid: tuple[float, float, float, float, float] | None = None,
        neighbourhood: int = 5,
        method: str = "astar",
        name: str = "seaway route",
        progress: Say | None = None,
        smooth: bool = True,
    ) -> Route:
        """The route from `start` to `end` (lat, lon) through the forecast, leaving at `depart`
        (default its first time; outside its times only with persist=True, said).

        vessel: a seaway.vessel.Vessel (a vessel file's: seaway.vessel.load), an ice class, or
            None (12 kn, 15000 t, said). ice: an ice chart (OpenChart, taken as valid from the
            departure for the whole voyage, said) or a season (OpenSeason, SeasonGrid): the ice
            and the weather act in one voyage at the speed of `ice_class` (default the vessel
            file's, else Arc7). objective: "time", "fuel" (needs a fuel curve; with arrive_by
            the least fuel that arrives in time) or "safety" (needs the ship's length).
        grid: the lat/lon grid a projected forecast is resampled onto without `ice`.
        smooth: a least-time route's steps replaced by straight legs sailed on the clock, never
        later (seaway.smoothtime). Route.notes record what was assumed and resampled."""
        say = progress or (lambda message: None)
        if objective not in OBJECTIVES:
            raise ForecastError(f"objective must be one of {', '.join(OBJECTIVES)}, got {objective!r}")
        if method in ("auto", "bidirectional"):
            if method == "bidirectional":
                raise ForecastError(
                    "a route through a forecast is on a clock: it cannot be searched from both "
                    "ends; use method astar or dijkstra"
                )
            method = "astar"
        if ice is not None and objective != "time":
            raise ForecastError(
                "through ice and weather at once only the least time is modelled; "
                "use objective time, or route without the ice chart"
            )
        ship, notes = _vessel(vessel)
        cls = ice_class or ship.ice_class or "Arc7"
        season = None if ice is None else ice_season(ice, cls, notes)
        ds, resampled = onto_route_grid(
            self.data, self.source, season_grid(season), grid=grid, ends=(start, end), crs=self.crs
        )
        notes += resampled
        fc = ForecastGrid(ds, departure=depart, persist=persist, source=self.source)
        notes += list(fc.assumptions)
        if season is None and fc.ice:  # a coupled ice-ocean forecast: its own ice with its currents
            if objective != "time":
                raise ForecastError(
                    "through a forecast's own ice only the least time is modelled: use objective time"
                )
            season = forecast_ice(ds, fc.dry, notes)
        say(f"departure {fc.departure} (forecast {fc.describe()})")
        rows, cols = fc.shape
        common = dict(neighbourhood=neighbourhood, method=method)
        if objective == "time":  # the fuel and wave-danger routes price only the engine's steps
            common["smooth"] = smooth
        with searching(progress, rows * cols):
            if season is not None:
                r = route_ice_weather_voyage(
                    season, ds, start, end, cls, ship, fc, persist, self.source, notes, say, **common
                )
            else:
                r = route_on_forecast(
                    ds, fc, start, end, ship, objective, arrive_by, persist, self.source, notes, say, **common
                )
        return dataclasses.replace(r, name=name, notes=tuple(self.notes) + tuple(notes) + tuple(r.notes))

    def best_departure(self, start, end, window, *, step_h=6.0, arrive_by=None, **options) -> DepartureChoice:
        """The departure in `window` (first, last) that arrives first, or with `arrive_by` the
        one that arrives in time with the least fuel (each departure's least-fuel route to the
        deadline, Sotnikova 2009; needs the vessel's fuel curve), tried every step_h hours
        (seaway.voyage.departures); options as route()."""
        if arrive_by is not None:
            deadline = np.datetime64(arrive_by, "s")
            options = {**options, "objective": "fuel"}

            def go(depart, **kw):
                return self.route(start, end, depart=depart, arrive_by=deadline, **kw)
        else:

            def go(depart, **kw):
                return self.route(start, end, depart=depart, **kw)

        return best_departure(go, window, step_h=step_h, arrive_by=arrive_by, **options)


def season_grid(season):
    """(lat, lon, dims) of a season's grid, or None."""
    if season is None:
        return None
    t = season.template
    return (*(t[d].values for d in t.dims), t.dims)


def _vessel(vessel) -> tuple[Vessel, list[str]]:
    """(the voyage's Vessel, what was said of it)."""
    if vessel is None:
        return (
            Vessel(speed_kn=12.0),
            [
                "vessel: 12 kn in calm water, 15000 t (the defaults; give --speed, --displacement or --vessel-file)"
            ],
        )
    ship = as_vessel(vessel)
    assert ship is not None
    return ship, vessel_notes(ship) if ship.path or ship.name else []


def open_forecast(
    paths: str | os.PathLike[str] | Sequence[str | os.PathLike[str]],
    *,
    variables: Mapping[str, str] | None = None,
    crs: str | None = None,
) -> OpenForecast:
    """Open forecast files for routing: CF NetCDF (fields by standard name, or GRIB short
    names), CDO output from GRIB, or GRIB (the [grib] extra); several files are merged on time.
    variables: {role: variable} for fields the files do not name by their standard names
    (seaway.weather.roles); crs: the projection of a projected forecast whose file names no grid
    mapping (EPSG code, PROJ string or WKT)."""
    many = [paths] if isinstance(paths, (str, os.PathLike)) else list(paths)
    ds, notes = read_forecasts(many, dict(variables or {}))
    source = ", ".join(os.path.basename(os.fspath(p)) for p in many)
    return OpenForecast(ds, source, crs, list(notes))


__all__ = ["OpenForecast", "open_forecast", "OBJECTIVES"]
