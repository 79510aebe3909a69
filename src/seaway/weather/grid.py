"""ForecastGrid: a forecast on a regular lat/lon grid as the weather models read it: its fields
by role, its time axis from the departure, and its grid as a chart to route on."""

from __future__ import annotations

import numpy as np

from .. import native as _core
from ..base.units import KNOTS_PER_MS
from ..chart.raster import as_chart
from ..chart.roles import ICE_ROLES
from ..constraints import hard_only
from ..engine.methods import check_options
from ..engine.prepared import PreparedChart
from ..errors import ForecastError, SeawayError
from ..models.base import EdgeCost
from ..vessel import Vessel
from .files import decode_time, unknown_fields_hint
from .forecast import STANDARD_NAMES, find_fields


def _departure(departure, t, persist) -> tuple[np.datetime64, list[str]]:
    """(the departure, what it assumes): one outside the forecast's times is refused, or with
    `persist` routed holding the nearest frame (persistence), said."""
    try:
        dep = t[0] if departure is None else np.datetime64(departure, "ns")
    except (TypeError, ValueError):
        raise SeawayError(
            f"departure must be a time such as '2026-09-15T06:00' (ISO 8601) or a "
            f"datetime64, got {departure!r}"
        ) from None
    if t[0] <= dep <= t[-1]:
        return dep, []
    side = "before the forecast's first time" if dep < t[0] else "after the forecast's last time"
    gap = abs(dep - (t[0] if dep < t[0] else t[-1])) / np.timedelta64(1, "h")
    span = f"{_iso(t[0])} to {_iso(t[-1])}"
    if not persist:
        raise ForecastError(
            f"departure {_iso(dep)} is {gap:g} h {side} (the forecast covers {span}): "
            "the weather then is unknown; depart within the forecast, give a forecast "
            "that covers the departure, or pass --persist (persist=True) to hold its "
            "nearest frame"
        )
    held = (
        "its first frame is held until the forecast begins"
        if dep < t[0]
        else "its last frame is held for the whole voyage"
    )
    return dep, [f"persistence: the departure {_iso(dep)} is {gap:g} h {side} ({span}); {held}"]


def _iso(t) -> str:
    """A time as YYYY-MM-DDTHH:MM (UTC)."""
    return str(np.datetime_as_string(np.datetime64(t, "m"), unit="m"))


def _time_axis(ds, departure):
    """(frames, first_h, step_h): frame k is valid first_h + k * step_h hours after departure."""
    if "time" not in ds.dims:
        return 1, 0.0, 1.0
    t = ds["time"].values
    if t.size == 1:
        return 1, 0.0, 1.0
    hours = (t - t[0]) / np.timedelta64(1, "h")
    step = float(hours[1] - hours[0])
    if step <= 0 or np.max(np.abs(np.diff(hours) - step)) > 1e-6:
        raise ForecastError(
            "forecast times must be regularly spaced and increasing; "
            "resample it, e.g. ds.resample(time='6h').interpolate()"
        )
    return t.size, float((t[0] - departure) / np.timedelta64(1, "h")), step


#: No forecast field (currents, winds, waves, periods, directions, ice) reaches this magnitude.
PLAUSIBLE_MAX = 1e6


def _frames(field, chart_dims, frames) -> np.ndarray:
    dims = (("time",) if "time" in field.dims else ()) + chart_dims
    if set(field.dims) != set(dims):
        raise ForecastError(f"forecast field {field.name!r} has dims {field.dims}; expected {dims}")
    raw = np.asarray(field.transpose(*dims).values)
    if not np.issubdtype(raw.dtype, np.number) or np.iscomplexobj(raw):
        raise ForecastError(f"forecast field {field.name!r} must hold real numbers, got dtype {raw.dtype}")
    with np.errstate(invalid="ignore"):
        bad = np.abs(raw) > PLAUSIBLE_MAX
    if bad.any():  # (a float32 cast would overflow, or warn: no forecast field holds such values)
        raise ForecastError(
            f"forecast field {field.name!r} holds {int(bad.sum())} values no forecast has (e.g. "
            f"{raw.flat[int(np.argmax(bad))]!r}; any field's magnitude stays below {PLAUSIBLE_MAX:g}): "
            "the file is damaged, or the field is in other units; fetch it again"
        )
    a = raw.astype(np.float32)
    if a.ndim == 2:
        a = np.broadcast_to(a, (frames,) + a.shape)
    return np.ascontiguousarray(a)


class ForecastGrid:
    """A forecast as the engine reads it: float32 (frames, rows, cols) fields by role (NaN set
    to 0), the time axis relative to `departure` (default the first time), and where the sea is
    (not NaN in every field). The models of seaway.models read it; prepare() gives the chart
    to route on (its static cost: 1 per km).

    A time axis that is not datetime64 is decoded first (seaway.weather.files.decode_time: CF
    units, CDO's "day as %Y%m%d.%f", cfgrib's steps). A departure outside the forecast's times
    is refused unless `persist` (then the nearest frame is held, and `assumptions` says so).
    `source` names the forecast in the routes' outputs."""

    def __init__(self, forecast, variables=None, departure=None, *, persist=False, source=None):
        forecast = decode_time(forecast)
        fields = find_fields(forecast, variables)
        #: The forecast's own ice (its sea-ice concentration and thickness), by role: not weather,
        #: priced by the ice models (seaway.voyage.forecastice), left out of the arrays here.
        self.ice = {r: fields.pop(r) for r in ICE_ROLES if r in fields}
        if not fields and self.ice:
            raise ForecastError(
                "the forecast has only ice (sea-ice concentration or thickness) and no weather: "
                "route through its ice as a season of charts (seaway.open_season), or add its currents, "
                "winds or waves"
            )
        if not fields:
            raise ForecastError(
                "the forecast has no field seaway knows; mark them with CF standard "
                f"names ({', '.join(n[0] for n in STANDARD_NAMES.values())}) or pass "
                "variables={role: name}" + unknown_fields_hint(forecast)
            )
        some = next(iter(fields.values()))
        dims = tuple(d for d in some.dims if d != "time")
        #: What routing through this forecast assumes (persistence), for the routes' outputs.
        self.assumptions: list[str] = []
        self.departure = None
        times = forecast["time"].values if "time" in forecast.dims else None
        if times is not None:
            self.departure, self.assumptions = _departure(departure, times, persist)
        elif departure is not None:
            self.departure = np.datetime64(departure, "ns")
            self.assumptions = ["the forecast has no time axis: its fields are held for the whole voyage"]
        self.frames, self.first_h, self.step_h = _time_axis(forecast, self.departure)
        #: The times the forecast covers (None without a time axis).
        self.times = times
        self.source = source or forecast.attrs.get("title") or "forecast in memory"
        arrays = {role: _frames(f, dims, self.frames) for role, f in fields.items()}
        self.dry = np.all([np.isnan(a).all(axis=0) for a in arrays.values()], axis=0)
        if "wind_speed" not in arrays and "wind_east" in arrays:
            arrays["wind_speed"] = np.hypot(arrays.pop("wind_east"), arrays.pop("wind_north"))
        arrays.pop("wind_east", None), arrays.pop("wind_north", None)
        self.arrays = {k: np.ascontiguousarray(np.nan_to_num(a, nan=0.0)) for k, a in arrays.items()}
        self.template = some.isel(time=0, drop=True) if "time" in some.dims else some
        self.shape = self.dry.shape

    def prepare(self, land=None, neighbourhood=5, keep_away=()) -> PreparedChart:
        """The forecast's lat/lon grid as a chart: land where every field is NaN or `land` is
        True, or within a hard keep-away buffer (seaway.constraints.KeepAway); its static cost
        is 1 per km (distance), the weather models bring their own."""
        check_options(neighbourhood, "full")
        km = self.template.copy(data=np.ones(self.shape, np.float32))
        if keep_away:
            land = hard_only(km, keep_away, self.dry if land is None else (np.asarray(land, bool) | self.dry))
        chart = as_chart(km, land=self.dry if land is None else (np.asarray(land, bool) | self.dry))
        if not chart.geographic:
            raise ForecastError("weather routing needs a forecast on a lat/lon grid (coordinates lat/lon)")
        return PreparedChart.from_chart(chart, neighbourhood, "full", EdgeCost("max"))

    def describe(self) -> str:
        """The forecast in words, for the routes' outputs: its source and the times it covers."""
        if self.times is None:
            return f"{self.source} (no time axis)"
        step = f", every {self.step_h:g} h" if self.frames > 1 else ""
        return f"{self.source} ({_iso(self.times[0])} to {_iso(self.times[-1])}{step})"

    def assumed(self, arrival) -> list[str]:
        """What a voyage arriving at `arrival` assumes of this forecast: its persistence notes,
        and its last frame held past its last time."""
        out = list(self.assumptions)
        if (
            self.times is not None
            and arrival is not None
            and arrival > self.times[-1]
            and not any("last frame" in a for a in out)
        ):
            hours = (arrival - self.times[-1]) / np.timedelta64(1, "h")
            out.append(
                f"persistence: the voyage arrives {hours:.1f} h after the forecast's last "
                f"time ({_iso(self.times[-1])}); its last frame is held until then"
            )
        return out

    def engine(self) -> _core.Forecast:
        """The forecast's fields as the C++ core's Forecast object."""
        return _core.Forecast(self.first_h, self.step_h, **self.arrays)

    def frame_at(self, hours, roles) -> ForecastGrid:
        """A one-frame copy with the fields of `roles` it has: the frame valid nearest `hours`
        after departure."""
        k = int(np.clip(round((hours - self.first_h) / self.step_h), 0, self.frames - 1))
        out = object.__new__(ForecastGrid)
        out.__dict__.update(self.__dict__, frames=1, first_h=0.0, step_h=1.0)
        out.arrays = {r: np.ascontiguousarray(self.arrays[r][k : k + 1]) for r in roles if r in self.arrays}
        return out

    def later(self, hours: float) -> ForecastGrid:
        """The same forecast for a ship leaving `hours` after this departure (frame times and
        departure shifted; `shift_h` adds up, for zone windows given in hours)."""
        out = object.__new__(ForecastGrid)
        out.__dict__.update(
            self.__dict__, first_h=self.first_h - hours, shift_h=getattr(self, "shift_h", 0.0) + hours
        )
        if self.departure is not None:
            out.departure = self.departure + np.timedelta64(int(round(hours * 3.6e12)), "ns")
        return out

    def best_extra_kn(self, vessel: Vessel, slowest_kn: float | None = None) -> float:
        """The most the weather can add to a calm-water speed: following seas under Khokhlov's
        formula, plus the strongest current (for A*'s admissible bound). slowest_kn: the least
        speed the formula is applied to (default the vessel's; in ice, 0)."""
        extra, a = 0.0, self.arrays
        v0 = vessel.speed_kn if slowest_kn is None else slowest_kn
        if vessel.speed_loss == "khokhlov" and "wave_height" in a:
            gain = (0.275 * np.pi - 0.745) * 1.32 * float(a["wave_height"].max())
            extra += max(gain, 0.0) * (1 - 1.35e-6 * vessel.displacement_t * v0)
        if "current_east" in a:
            extra += float(np.hypot(a["current_east"], a["current_north"]).max()) * KNOTS_PER_MS
        return extra
