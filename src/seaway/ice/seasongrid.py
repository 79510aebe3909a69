"""A season of ice charts on one grid: the charts and their times, read from SIGRID-3 files
(`read_season`) or a NetCDF with a time dimension (`as_season`, which also takes CF
`sea_ice_area_fraction` and `sea_ice_thickness`, e.g. an ocean model's aice and hice), and a
class's hours per km in each chart from a departure on (`SeasonGrid.hours_per_km`).

A season is an ice chart Dataset (see seaway.ice) with a `time` dimension: CT (tenths) with SA
(WMO stage) and/or `thickness` (m), and `land`. Chart k is valid from its time until the next
chart's time (the last one for ever after). Routing through it (waiting allowed, the speed
models, why no route) is seaway.icenav.season's; seaway.models.IceSeasonTime is its cost model.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt
import xarray as xr

from ..base.files import open_netcdf
from ..base.memory import SEASON_CHART, check_pixels
from ..chart.cf import planar_in_km
from ..chart.raster import Chart, as_chart
from ..errors import ChartError, SeawayError
from . import andreeva
from .forms import check_fast_ice
from .seasoncache import FrameCache, Frames, speed_key
from .seasonfast import record_rule, season_assumptions, season_layers
from .seasonspeed import frame_speed_kn, is_curve
from .seasonvars import sigrid_layers
from .sigrid import read_sigrid3

if TYPE_CHECKING:
    import datetime
    import os

    from . import classes  # classes.IceClass: one name in the API pages (seaway.ice re-exports it)

    #: A season: its Dataset or a NetCDF file of it.
    SeasonLike = xr.Dataset | str | os.PathLike[str]
    #: A departure: a date numpy.datetime64 takes (None: the season's first chart).
    Departure = str | datetime.date | np.datetime64 | None
    #: Speeds by WMO stage: {stage: knots} or {stage: {max CT tenths: knots}}.
    SpeedTable = Mapping[float, float | Mapping[float, float]]

__all__ = ["read_season", "as_season", "SeasonGrid"]


def read_season(charts, grid, *, fast_ice=None, **read_kwargs) -> xr.Dataset:
    """SIGRID-3 files with their dates -> a season Dataset on `grid` (seaway.ice.grids), with
    each chart's form of ice (FA-FC) and free_water (seaway.ice.seasonfast.SEASON_LAYERS).
    charts: {date: path} or [(date, path), ...] in date order; each chart is valid from its
    date (any form numpy.datetime64 takes) until the next one's. fast_ice: the rule for fast ice
    of unknown stage its routes take unless they give one (attribute ``fast_ice``; None: "nearby"
    then, seaway.ice.forms). read_kwargs go to read_sigrid3."""
    items = list(charts.items()) if isinstance(charts, dict) else list(charts)
    if not items:
        raise SeawayError("give at least one (date, path) chart")
    try:
        dates = [np.datetime64(d, "s") for d, _ in items]
    except (TypeError, ValueError) as exc:
        raise SeawayError(f"chart dates must be dates such as '2026-07-01' or datetime64: {exc}") from None
    _check_increasing(np.array(dates), "sorted(charts)")
    rule = None if fast_ice is None else check_fast_ice(fast_ice)  # refused before any file is read
    check_pixels(
        *grid.shape,
        SEASON_CHART * len(items),
        f"a season of {len(items)} charts on a grid",
        "give a coarser grid, a smaller box or fewer charts",
        ChartError,
    )
    frames = [read_sigrid3(p, grid, **read_kwargs) for _, p in items]
    ds = xr.concat([f[season_layers(f)] for f in frames], dim="time", coords="minimal", compat="override")
    return record_rule(ds.assign_coords(time=dates), rule)


def _check_increasing(t, fix):
    if t.size > 1 and not np.all(t[1:] > t[:-1]):
        k = int(np.flatnonzero(~(t[1:] > t[:-1]))[0])
        raise ChartError(
            f"chart times must be unique and increasing, but {t[k]} is followed by "
            f"{t[k + 1]}: {fix}, and drop duplicate dates"
        )


def as_season(season) -> xr.Dataset:
    """A season Dataset from a Dataset or NetCDF path: CF sea_ice_area_fraction (in its units)
    becomes CT in tenths, sea_ice_thickness `thickness` (m), stage_of_development SA
    (seaway.ice.seasonvars); times must increase."""
    if not isinstance(season, xr.Dataset):
        season = open_netcdf(season, "a season of ice charts is a NetCDF file with a time axis", ChartError)
    ds = sigrid_layers(season)  # CT in tenths, thickness and SA from their other names
    if "time" not in ds.dims:
        raise ChartError(
            "a season needs a `time` dimension (one chart per time); for one chart, "
            "add it with ds.expand_dims(time=[date])"
        )
    if "CT" not in ds or not ({"SA", "thickness"} & set(ds)):
        raise ChartError(
            f"a season needs CT (tenths, or CF sea_ice_area_fraction) and SA (WMO "
            f"stage) or thickness (m, or CF sea_ice_thickness); it has {sorted(ds.data_vars)}"
        )
    if "land" not in ds:
        found = land_of(ds)
        ds = ds.assign(land=xr.zeros_like(ds["CT"], dtype=bool) if found is None else found)
    _check_increasing(ds["time"].values, "ds.sortby('time')")
    for name, lo, hi, what in PLAUSIBLE:
        if name in ds:
            _check_range(ds[name], lo, hi, what)
    return ds


def land_of(ds: xr.Dataset) -> xr.DataArray | None:
    """The land a season file's own mask marks, or None: CF land_binary_mask (1: land) or
    sea_binary_mask (1: sea), or an ocean model's 0/1 land-sea mask (ROMS `mask`, `mask_rho`;
    met.no's area_type with option_0 "land"), where 0 is land. Its attrs say which was read."""
    for name, v in ds.data_vars.items():
        std, opt0 = v.attrs.get("standard_name"), str(v.attrs.get("option_0", "")).strip().lower()
        if std == "land_binary_mask":
            land, rule = v == 1, f"the file's {name} (CF land_binary_mask: 1 is land)"
        elif (
            std == "sea_binary_mask"
            or name in ("mask", "mask_rho")
            or (std == "area_type" and opt0 == "land")
        ):
            land, rule = v == 0, f"the file's {name} (0 is land, 1 water)"
        else:
            continue
        if set(np.unique(np.asarray(v.values))) - {0, 1}:
            continue  # not a 0/1 mask
        return land.assign_attrs(read_from=rule)
    return None


#: What a season's layers may hold (NaN: unknown): anything else is a damaged file or a wrong unit.
#: Models' round-off (ROMS: thickness -0.00015 m, concentration -6e-6) is let through.
PLAUSIBLE = (
    ("CT", -0.01, 10.01, "total concentration in tenths (0-10)"),
    ("SA", 0.0, 99.0, "WMO stage codes (0-99)"),
    ("thickness", -0.01, 50.0, "ice thickness in m (0-50: the thickest ice measured is about 30 m)"),
)


def _check_range(da: xr.DataArray, lo: float, hi: float, what: str) -> None:
    values = np.asarray(da.values)
    if not np.issubdtype(values.dtype, np.number) or np.iscomplexobj(values):
        raise ChartError(f"the season's {da.name} must hold numbers ({what}), got dtype {values.dtype}")
    with np.errstate(invalid="ignore"):
        bad = ~np.isnan(values) & ((values < lo) | (values > hi))
    if bad.any():
        where = tuple(int(i) for i in np.argwhere(bad)[0])
        raise ChartError(
            f"the season's {da.name} holds {int(bad.sum())} value(s) outside its range, e.g. "
            f"{values[where]:g} at {dict(zip(da.dims, where))}: it holds {what}; the file is damaged "
            "or in other units: fetch it again, or convert it"
        )


class SeasonGrid:
    """A season of ice charts on one grid: the chart to route on (prepare()) and, for a class,
    speed and departure, the engine's frames (hours_per_km()). One prepared chart serves every
    class and departure; land is where every chart (or `land`) has land or no chart."""

    def __init__(self, season: SeasonLike, land: npt.ArrayLike | xr.DataArray | None = None) -> None:
        self.ds = as_season(season)
        self.times = self.ds["time"].values
        ct = self.ds["CT"]
        template = ct.isel(time=0, drop=True)
        template = template.drop_vars([c for c in template.coords if c not in template.dims])
        #: What the grid's step lengths assume (planar coordinates without units: km), in words.
        self.template, self.assumptions = planar_in_km(template, "the season")
        self.shape = self.template.shape
        dry = np.zeros(self.shape, bool)
        for name in ("land", "off_chart"):
            if name in self.ds:
                a = self.ds[name].astype(bool)
                a = a.all("time") if "time" in a.dims else a
                dry |= a.transpose(*self.template.dims).values
        if land is not None:
            land = np.asarray(getattr(land, "values", land), bool)
            if land.shape != self.shape:
                raise ChartError(
                    f"land has {land.shape} pixels but the season's charts {self.shape}: "
                    "give a land mask on the charts' grid"
                )
            dry |= land
        self.dry = dry
        if "read_from" in self.ds["land"].attrs:
            self.assumptions += (f"land: {self.ds['land'].attrs['read_from']}",)
        #: 1/k, the projection's point scale factor, on a projected grid whose true km are known
        #: (seaway.voyage.seasonproj): the hours per km are then per true km. None: grid km.
        self.per_true_km: npt.NDArray[np.float64] | None = None
        spacing = np.diff(self.times) / np.timedelta64(1, "h")
        #: How long the last chart is taken as valid: the series' median spacing (a day for one chart).
        self.last_valid_h = float(np.median(spacing)) if spacing.size else 24.0
        #: Each class's hours per km, kept between routes (seaway.ice.seasoncache).
        self._frames = FrameCache()
        self._said: dict[tuple[int, Any], tuple[str, ...]] = {}

    def assumed_from(self, first: int, fast_ice: str | float) -> tuple[str, ...]:
        """What the charts from index `first` on assume under the fast-ice rule, in words
        (seaway.ice.seasonfast.season_assumptions), read once per departure chart and rule."""
        key = (first, fast_ice)
        if key not in self._said:
            self._said[key] = season_assumptions(self.ds, first, fast_ice)
        return self._said[key]

    def as_chart(self) -> Chart:
        """The season's grid as a chart (lat/lon or planar y/x) whose static cost is 1 per unit
        length, land where no chart lets a ship go (`dry`): what seaway.prepare(season) routes
        on; the season's model brings its own cost."""
        one = self.template.copy(data=np.ones(self.shape, np.float32))
        return as_chart(one, land=self.dry)

    def departure_frames(self, departure):
        """(departure, index of the chart valid then); refuses departures outside the season."""
        t = self.times
        try:
            dep = t[0] if departure is None else np.datetime64(departure)
        except (TypeError, ValueError):
            raise SeawayError(
                f"departure must be a date such as '2026-07-01T12' (or a datetime64), got {departure!r}"
            ) from None
        end = t[-1] + np.timedelta64(int(round(self.last_valid_h * 3600)), "s")
        if not (t[0] <= dep <= end):
            raise SeawayError(
                f"departure {dep} is outside the season ({t[0]} to {end}, the last "
                "chart's validity): the ice then is unknown; depart within the season "
                "or add charts that cover the departure"
            )
        return dep, int(np.searchsorted(t, dep, side="right")) - 1

    def hours_per_km(
        self,
        ice_class: str | classes.IceClass,
        v0_kn: float,
        departure: Departure = None,
        speed: str | SpeedTable = "andreeva",
        **speed_options: Any,
    ) -> tuple[npt.NDArray[np.float32], npt.NDArray[np.float64], np.datetime64]:
        """(hours per km float32 (frames, rows, cols) from the chart valid at departure on, inf
        where closed, read-only; validity of each in hours after departure; departure)."""
        frames, k0, valid_from_h, dep = self.class_frames(ice_class, v0_kn, departure, speed, **speed_options)
        return frames.hours[k0:], valid_from_h, dep

    def class_frames(
        self,
        ice_class: str | classes.IceClass,
        v0_kn: float,
        departure: Departure = None,
        speed: str | SpeedTable = "andreeva",
        **speed_options: Any,
    ) -> tuple[Frames, int, npt.NDArray[np.float64], np.datetime64]:
        """(the class's Frames over every chart (seaway.ice.seasoncache: computed once per class,
        speed and options, kept for the next departure), the index of the chart valid at
        departure, the validity of each chart from it on in hours after departure, departure)."""
        if not (np.isfinite(v0_kn) and v0_kn > 0):
            raise SeawayError(f"v0_kn must be a positive speed in knots, got {v0_kn!r}")
        dep, k0 = self.departure_frames(departure)
        if not (
            callable(getattr(speed, "get", None))
            or is_curve(speed)
            or (isinstance(speed, str) and speed in ("andreeva", "class"))
        ):
            raise SeawayError(
                f"speed must be 'andreeva', 'class', a ship's ice curve (seaway.vessel.IceCurve) or a "
                f"table {{stage: knots}}, got {speed!r}"
            )
        key = speed_key(ice_class, v0_kn, speed, dict(speed_options, true_km=self.per_true_km is not None))
        frames = self._frames.get(key, speed, lambda: self._hours(ice_class, v0_kn, speed, speed_options))
        valid_from_h = (self.times[k0:] - dep) / np.timedelta64(1, "h")
        return frames, k0, valid_from_h.astype(float), dep

    def _hours(self, ice_class, v0_kn, speed, speed_options) -> npt.NDArray[np.float32]:
        """Hours per km in every chart of the season (frames, rows, cols), inf where closed."""
        hours = np.empty((self.times.size,) + self.shape, np.float32)
        for k in range(self.times.size):  # frame by frame: no 7-frame float64 copies
            v = frame_speed_kn(self.ds.isel(time=k), ice_class, v0_kn, speed, **speed_options)
            hours[k] = andreeva.time_cost(v / v0_kn, v0_kn)
            if self.per_true_km is not None:  # per projection km: the true km's hours
                hours[k] *= self.per_true_km
        return hours
